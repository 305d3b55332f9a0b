"""Layer 8, noncircular pair: ``NonCircularPair``, a thin view over the centrode formulas.

A pair of gears whose ratio omega1/omega2 varies with the input angle: its motion law, its
centre distance, the pitch curves (centrodes) of both gears and their checks (Ozols section
19-1; Litvin's elliptical and n-lobed gears). Angles are degrees; lengths mm.

Examples
--------
>>> p = NonCircularPair.elliptical(50.0, 0.2)
>>> round(p.center_distance, 9), p.lobes
(100.0, (1, 1))
>>> round(float(p.ratio(0.0)), 6), round(float(p.ratio(180.0)), 6)  # (1 - e)/(1 + e), inverse
(0.666667, 1.5)
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
import shapely
from numpy.typing import ArrayLike
from scipy.interpolate import CubicSpline

from gears.arguments import (
    check_angle,
    check_callback,
    check_choice,
    check_fps,
    check_frames,
    check_integer,
    check_module,
    check_positive,
    check_pressure_angle,
    check_real,
    check_tolerance,
)
from gears.cutting.sampling import chord_angle
from gears.errors import GearError
from gears.noncircular.centrode import (
    KINDS,
    LAW_SAMPLES,
    MAX_LOBES,
    MotionLaw,
    center_distance_for_lobes,
    check_center_distance,
    check_law_radii,
    closing_lobes,
    eccentric_radius,
    elliptical_radius,
    law_from_output,
    law_from_ratio,
    polar_arc_length,
    polar_curvature,
    pole_radii,
)
from gears.noncircular.checks import tooth_margins
from gears.noncircular.conjugate import transmission_error
from gears.noncircular.teeth import (
    RackCutter,
    check_cut_budget,
    cut_outline,
    rack_frames,
    rack_tooth,
    roll_step,
)
from gears.report import Finding, Report

if TYPE_CHECKING:
    import trimesh

__all__ = ["NonCircularPair"]

#: A motion law: a number, a callable of the input angle in degrees, or samples of one period.
RatioLaw = float | Callable | ArrayLike


def _spline_arc_length(s: CubicSpline, pieces: bool = False):
    """The length of the polar curve r = s(theta) over the spline's span (4-point Gauss on each
    knot interval: exact to the spline's own accuracy), or each interval's."""
    t, w = np.polynomial.legendre.leggauss(4)
    x0, h = s.x[:-1, None], np.diff(s.x)[:, None]
    x = x0 + (t + 1.0) * h / 2.0
    each = np.sum(polar_arc_length(s(x), s(x, 1)) * w, axis=1) * h[:, 0] / 2.0
    return each if pieces else float(np.sum(each))


@dataclass(frozen=True, eq=False)
class NonCircularPair:
    """Two non-circular gears rolling their centrodes on each other.

    Build one with a named constructor: :meth:`from_ratio` (omega1/omega2 as a function of the
    input angle), :meth:`from_output` (the output law psi(phi)), :meth:`from_pitch_curve`
    (gear 1's pitch curve and the lobes of both), or the named cases :meth:`elliptical`,
    :meth:`lobed` and :meth:`eccentric`.

    ``module`` (optional) gives the teeth: a whole number of teeth per period of the law, the
    module fitted to the pitch curve's length (:attr:`teeth`, :attr:`module`).
    """

    law: MotionLaw
    center_distance: float
    kind: str = "external"
    lobes: tuple[int, int] = (1, 1)
    nominal_module: float | None = None
    pressure_angle: float = 20.0
    addendum: float = 1.0
    name: str = "non-circular pair"

    # -- constructors ---------------------------------------------------------------------------
    @classmethod
    def _build(cls, law, center_distance, kind, lobes1, module, pressure_angle, name, ratio_name):
        m = None if module is None else check_module(module)
        pa = check_pressure_angle(pressure_angle)
        pair = cls(law, center_distance, kind, (lobes1, 0), m, pa, 1.0, name)
        check_law_radii(1.0 / law.q(pair._grid), *pair._radii_samples, kind)
        lobes2 = closing_lobes(law, ratio_name)
        return cls(law, center_distance, kind, (lobes1, lobes2), m, pa, 1.0, name)

    @classmethod
    def from_ratio(
        cls, ratio: RatioLaw, center_distance: float, *, lobes: int = 1, kind: str = "external",
        module: float | None = None, pressure_angle: float = 20.0,
    ) -> NonCircularPair:  # fmt: skip
        """The pair of the ratio omega1/omega2: a number, a callable of the input angle in
        degrees, or samples over one period (360/``lobes`` degrees, equally spaced, the end
        left out). ``lobes`` is gear 1's (the law's period); gear 2's follow from the law, which
        must turn gear 2 by 360/n2 degrees over a period (closure), or a :class:`GearError`
        says by what factor to scale the ratio.

        >>> p = NonCircularPair.from_ratio(2.0, 100.0)     # circles: Ozols (19.2), O1P = 33.33
        >>> round(float(p.radius1(0.0)), 2), p.lobes
        (33.33, (1, 2))
        >>> NonCircularPair.from_ratio(1.5, 100.0)  # doctest: +ELLIPSIS
        Traceback (most recent call last):
        ...
        gears.errors.GearError: ratio cannot close: one period of the law (360 deg of gear 1) ...
        """
        a = check_center_distance(center_distance)
        kind = check_choice("kind", kind, KINDS)
        n1 = check_integer("lobes", lobes, 1, MAX_LOBES)
        law = law_from_ratio(ratio, n1)
        return cls._build(law, a, kind, n1, module, pressure_angle, "from_ratio", "ratio")

    @classmethod
    def from_output(
        cls, psi: RatioLaw, center_distance: float, *, lobes: int = 1, kind: str = "external",
        module: float | None = None, pressure_angle: float = 20.0,
    ) -> NonCircularPair:  # fmt: skip
        """The pair of the output law psi(phi) (degrees to degrees; a callable, or samples over
        one period of 360/``lobes`` degrees with both ends), psi increasing."""
        a = check_center_distance(center_distance)
        kind = check_choice("kind", kind, KINDS)
        n1 = check_integer("lobes", lobes, 1, MAX_LOBES)
        law = law_from_output(psi, n1)
        return cls._build(law, a, kind, n1, module, pressure_angle, "from_output", "psi")

    @classmethod
    def from_pitch_curve(
        cls, radius: Callable, lobes: tuple[int, int] = (1, 1), *, kind: str = "external",
        module: float | None = None, pressure_angle: float = 20.0, name: str = "from_pitch_curve",
    ) -> NonCircularPair:  # fmt: skip
        """The pair whose gear 1 has the pitch curve ``radius(phi)`` (degrees in, mm out,
        period 360/lobes1): the centre distance is solved so gear 2 closes with lobes2 lobes
        (Litvin's closure condition)."""
        if not callable(radius):
            raise GearError(f"radius = {radius!r}; valid is a callable of the angle in degrees")
        if not (isinstance(lobes, tuple | list) and len(lobes) == 2):
            raise GearError(f"lobes = {lobes!r}; valid is a pair (lobes1, lobes2)")
        n1 = check_integer("lobes1", lobes[0], 1, MAX_LOBES)
        n2 = check_integer("lobes2", lobes[1], 1, MAX_LOBES)
        kind = check_choice("kind", kind, KINDS)

        def rad(phi):
            return np.asarray(radius(np.degrees(phi)), dtype=float) * np.ones_like(phi)

        a = center_distance_for_lobes(rad, n1, n2, kind)

        def ratio(deg):
            r1 = rad(np.radians(deg))
            return (a - r1) / r1 if kind == "external" else (a + r1) / r1

        law = law_from_ratio(ratio, n1)
        return cls._build(law, a, kind, n1, module, pressure_angle, name, "radius")

    @classmethod
    def elliptical(
        cls, semi_major: float, eccentricity: float, *, module: float | None = None,
        pressure_angle: float = 20.0,
    ) -> NonCircularPair:  # fmt: skip
        """Two identical ellipses turning about their foci (Litvin): r = A (1 - e^2) /
        (1 - e cos phi), centre distance 2 A, ratio from (1 - e)/(1 + e) to (1 + e)/(1 - e)."""
        big_a = check_positive("semi_major", semi_major)
        e = check_real("eccentricity", eccentricity, 0.0, 1.0, low_open=False)
        # the mating ellipse's radius is 2A - r1: ratio omega1/omega2 = (2A - r1) / r1
        law = law_from_ratio(
            lambda deg: 2.0 * big_a / elliptical_radius(np.radians(deg), big_a, e) - 1.0, 1
        )
        return cls._build(
            law, 2.0 * big_a, "external", 1, module, pressure_angle,
            f"elliptical(A={big_a:g}, e={e:g})", "eccentricity",
        )  # fmt: skip

    @classmethod
    def lobed(
        cls, semi_major: float, eccentricity: float, lobes: tuple[int, int] = (2, 2), *,
        module: float | None = None, pressure_angle: float = 20.0,
    ) -> NonCircularPair:  # fmt: skip
        """Gear 1 the n1-lobed oval r = A (1 - e^2) / (1 - e cos(n1 phi)), gear 2 the closed
        curve of n2 lobes that rolls on it (Litvin's n-lobed gears); (1, 1) is the elliptical
        pair."""
        big_a = check_positive("semi_major", semi_major)
        e = check_real("eccentricity", eccentricity, 0.0, 1.0, low_open=False)
        n1 = check_integer("lobes1", lobes[0] if len(lobes) == 2 else None, 1, MAX_LOBES)
        return cls.from_pitch_curve(
            lambda deg: elliptical_radius(np.radians(deg), big_a, e, n1), lobes,
            module=module, pressure_angle=pressure_angle,
            name=f"lobed(A={big_a:g}, e={e:g}, lobes={tuple(lobes)})",
        )  # fmt: skip

    @classmethod
    def eccentric(
        cls, radius: float, offset: float, lobes2: int = 1, *, module: float | None = None,
        pressure_angle: float = 20.0,
    ) -> NonCircularPair:  # fmt: skip
        """Gear 1 a circle of ``radius`` turning about a point ``offset`` from its centre, gear 2
        the closed curve of ``lobes2`` lobes that rolls on it."""
        r = check_positive("radius", radius)
        e = check_real("offset", offset, 0.0, r, low_open=False)
        return cls.from_pitch_curve(
            lambda deg: eccentric_radius(np.radians(deg), r, e), (1, lobes2),
            module=module, pressure_angle=pressure_angle,
            name=f"eccentric(R={r:g}, e={e:g})",
        )  # fmt: skip

    # -- the law --------------------------------------------------------------------------------
    def ratio(self, phi: ArrayLike) -> np.ndarray:
        """omega1/omega2 at the input angle ``phi`` (degrees, arrays)."""
        return 1.0 / self.law.q(np.radians(phi))

    def output_angle(self, phi: ArrayLike) -> np.ndarray:
        """psi(phi), degrees: gear 2's rotation when gear 1 has turned ``phi`` degrees (Ozols
        (19.3)); gear 2 turns the other way on an external pair."""
        return np.degrees(self.law.psi(np.radians(phi)))

    def output_speed(self, phi: ArrayLike, nu: int = 0) -> np.ndarray:
        """d psi/d phi = omega2/omega1 at ``phi`` (``nu`` = 1: its derivative per radian of
        input, the output's angular acceleration at a unit input speed)."""
        return self.law.q(np.radians(phi), nu)

    def radius1(self, phi: ArrayLike) -> np.ndarray:
        """O1P: gear 1's pitch-curve radius at the pole when it has turned ``phi`` degrees."""
        return pole_radii(1.0 / self.law.q(np.radians(phi)), self.center_distance, self.kind)[0]

    def radius2(self, phi: ArrayLike) -> np.ndarray:
        """O2P: gear 2's pitch-curve radius at the pole when gear 1 has turned ``phi`` degrees
        (gear 2 has then turned :meth:`output_angle` degrees)."""
        return pole_radii(1.0 / self.law.q(np.radians(phi)), self.center_distance, self.kind)[1]

    @cached_property
    def _grid(self) -> np.ndarray:
        return np.arange(LAW_SAMPLES + 1) * (self.law.period / LAW_SAMPLES)

    @cached_property
    def _radii_samples(self) -> tuple[np.ndarray, np.ndarray]:
        q = self.law.q(self._grid[:-1])
        return pole_radii(1.0 / q, self.center_distance, self.kind)

    @cached_property
    def _splines(self) -> tuple[CubicSpline, CubicSpline]:
        """Each pitch curve's radius as a periodic spline of its own polar angle (gear 1 over
        phi, gear 2 over psi), for curvature and length."""
        r1, r2 = self._radii_samples
        psi = self.law.psi(self._grid)
        s1 = CubicSpline(self._grid, np.append(r1, r1[0]), bc_type="periodic")
        s2 = CubicSpline(psi, np.append(r2, r2[0]), bc_type="periodic")
        return s1, s2

    def curvature(self, phi: ArrayLike, gear: int = 1) -> np.ndarray:
        """Signed curvature (1/mm, positive convex) of gear ``gear``'s pitch curve at the point
        that is at the pole when gear 1 has turned ``phi`` degrees."""
        g = check_integer("gear", gear, 1, 2)
        x = np.radians(phi)
        if g == 2:
            x = self.law.psi(x)
            x = np.mod(x, 2.0 * math.pi / self.lobes[1])
        else:
            x = np.mod(x, self.law.period)
        s = self._splines[g - 1]
        return polar_curvature(s(x), s(x, 1), s(x, 2))

    @cached_property
    def pitch_lengths(self) -> tuple[float, float]:
        """The length of each closed pitch curve, mm (equal per period of the law: they roll
        without slipping)."""
        out = []
        for s, n in zip(self._splines, self.lobes, strict=True):
            out.append(_spline_arc_length(s) * n)
        return out[0], out[1]

    @cached_property
    def teeth(self) -> tuple[int, int] | None:
        """(z1, z2): a whole number of teeth per period of the law, fitted to the pitch curve's
        length at the nominal module (None without a module)."""
        if self.nominal_module is None:
            return None
        per = self.pitch_lengths[0] / self.lobes[0]
        k = max(1, round(per / (math.pi * self.nominal_module)))
        return self.lobes[0] * k, self.lobes[1] * k

    @property
    def module(self) -> float | None:
        """The module fitted to the pitch curve: its length over pi times the teeth."""
        if self.teeth is None:
            return None
        return self.pitch_lengths[0] / (math.pi * self.teeth[0])

    def pitch_curves(self, samples: int = 720, phi: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """Both pitch curves placed in mesh when gear 1 has turned ``phi`` degrees: (n, 2)
        arrays of x, y in mm, O1 at the origin, O2 at (a, 0)."""
        n = check_integer("samples", samples, 8, 1_000_000)
        x = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
        s1, s2 = self._splines
        r1 = s1(np.mod(x, self.law.period))
        r2 = s2(np.mod(x, 2.0 * math.pi / self.lobes[1]))
        phi0 = math.radians(phi)
        psi0 = float(self.law.psi(phi0))
        t1 = -x + phi0
        c1 = np.stack([r1 * np.cos(t1), r1 * np.sin(t1)], axis=-1)
        if self.kind == "external":
            t2 = math.pi + x - psi0
        else:
            sign = math.pi if self._ring2 else 0.0
            t2 = sign - x + psi0
        c2 = np.stack([self.center_distance + r2 * np.cos(t2), r2 * np.sin(t2)], axis=-1)
        return c1, c2

    @property
    def _ring2(self) -> bool:
        """On an internal pair: gear 2 is the ring (omega1/omega2 > 1)."""
        return self.kind == "internal" and float(self.law.q(0.0)) < 1.0

    # -- teeth --------------------------------------------------------------------------------
    @property
    def cutter(self) -> RackCutter:
        """The rack cutter of both gears (ISO 53 A proportions at the fitted module)."""
        if self.module is None:
            raise GearError(
                f"{self.name} has no module: give module= to the constructor to cut teeth"
            )
        return RackCutter(self.module, self.pressure_angle, self.addendum)

    def _arc(self, phi: np.ndarray) -> np.ndarray:
        """The arc length rolled (mm) when gear 1 has turned ``phi`` radians (any number of
        periods)."""
        x = self._grid
        arc = np.concatenate([[0.0], np.cumsum(_spline_arc_length(self._splines[0], True))])
        k, rest = np.divmod(np.asarray(phi, float), self.law.period)
        return k * arc[-1] + np.interp(rest, x, arc)

    def _input_at_arc(self, rolled: np.ndarray) -> np.ndarray:
        """The input angle (radians) at which ``rolled`` mm have rolled (the inverse of _arc)."""
        x = self._grid
        arc = np.concatenate([[0.0], np.cumsum(_spline_arc_length(self._splines[0], True))])
        k, rest = np.divmod(np.asarray(rolled, float), arc[-1])
        phi = k * self.law.period + np.interp(rest, arc, x)
        for _ in range(3):  # Newton on the spline's own arc length: the linear inverse's
            s1 = self._splines[0]  # error is O(h^2), this brings it to round-off
            xx = np.mod(phi, self.law.period)
            speed = polar_arc_length(s1(xx), s1(xx, 1))
            phi = phi - (self._arc(phi) - rolled) / speed
        return phi

    def outline(
        self, gear: int = 1, tolerance: float = 0.01, progress: Callable | None = None
    ) -> shapely.Polygon:
        """Gear ``gear``'s outline in its own frame (O at the origin, as at input angle 0), its
        teeth cut by the rack cutter rolled along the pitch curve (:mod:`gears.noncircular.teeth`),
        to ``tolerance`` mm."""
        g = check_integer("gear", gear, 1, 2)
        check_callback("progress", progress)
        cutter = self.cutter
        tol = check_tolerance(tolerance, module=cutter.module)
        if self.kind != "external":
            raise GearError(
                "teeth are cut on external non-circular pairs only; an internal pair's ring "
                "needs a shaper cutter, which is not modelled here"
            )
        cache = self.__dict__.setdefault("_outlines", {})  # a view: cut once per tolerance
        if (g, tol) not in cache:
            cache[(g, tol)] = self._outline(g, tol, progress)
        return cache[(g, tol)]

    def _outline(self, g: int, tol: float, progress) -> shapely.Polygon:
        cutter = self.cutter
        kmax = float(np.max(np.abs(self.curvature(np.degrees(self._grid), g))))
        length = self.pitch_lengths[g - 1]
        ds = roll_step(cutter, kmax, tol)
        n = max(8, math.ceil(length / ds))
        tooth = rack_tooth(cutter, tol)
        check_cut_budget(n, 2 * math.ceil(cutter.reach / cutter.pitch) + 3, len(tooth), tol,
                         f"gear {g} of {self.name}")  # fmt: skip
        rolled = np.arange(n) * (length / n)
        phi = self._input_at_arc(rolled)
        xx = np.mod(phi, self.law.period)
        s1 = self._splines[0]
        r, dr = s1(xx), s1(xx, 1)
        t, nrm = rack_frames(r, dr)
        pole = np.stack([r, np.zeros_like(r)], axis=-1)
        if g == 1:
            rotation, center = -phi, (0.0, 0.0)
        else:
            rotation, center = self.law.psi(phi), (self.center_distance, 0.0)
        blank = self._blank(g, tol)
        return cut_outline(blank, tooth, cutter.pitch, cutter.reach, pole, t, nrm, rolled,
                           rotation, center, g == 2, tol, progress)  # fmt: skip

    def _blank(self, g: int, tol: float) -> shapely.Polygon:
        """The pitch curve in gear ``g``'s own frame offset outwards by the addendum."""
        s = self._splines[g - 1]
        period = 2.0 * math.pi / self.lobes[g - 1]
        kmax = float(np.max(np.abs(self.curvature(np.degrees(self._grid), g))))
        step = math.sqrt(2.0 * tol / max(kmax, 1e-12))  # chord sag tol / 4
        n = min(max(64, math.ceil(self.pitch_lengths[g - 1] / step)), 2_000_000)
        x = np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)
        r = s(np.mod(x, period))
        theta = -x if g == 1 else math.pi + x
        curve = shapely.Polygon(np.stack([r * np.cos(theta), r * np.sin(theta)], axis=-1))
        quad = max(2, math.ceil(math.pi / 2 / chord_angle(self.module, tol / 4)))
        return curve.buffer(self.addendum * self.module, quad_segs=min(quad, 64))

    def outlines(
        self, angle: float = 0.0, tolerance: float = 0.01, progress: Callable | None = None
    ) -> tuple[shapely.Polygon, shapely.Polygon]:
        """Both gears in mesh when gear 1 has turned ``angle`` degrees: gear 1 about the origin,
        gear 2 about (a, 0) turned back by the output angle (it turns the other way)."""
        phi = check_angle("angle", angle)
        first = self.outline(1, tolerance, progress)
        second = self.outline(2, tolerance)
        return self._placed(first, second, phi)

    def transmission_error(
        self, angles: ArrayLike | None = None, tolerance: float = 0.01
    ) -> np.ndarray:
        """The geometric transmission error of the cut teeth against the law, degrees of gear 2
        at each input angle (``angles``, degrees; by default 4 per tooth over a turn of gear
        1): :func:`gears.noncircular.conjugate.transmission_error` on :meth:`outlines`."""
        tol = check_tolerance(tolerance, module=self.cutter.module)
        if angles is None:
            angles = np.linspace(0.0, 360.0, 4 * self.teeth[0] + 1)
        first, second = self.outlines(0.0, tol)
        return transmission_error(first, second, ((0.0, 0.0), (self.center_distance, 0.0)),
                                  angles, self.output_angle)  # fmt: skip

    def scene(
        self, angle: float = 0.0, face_width: float = 10.0, tolerance: float = 0.01
    ) -> trimesh.Scene:
        """A ``trimesh.Scene`` of both gears in mesh at the input angle ``angle`` (degrees): each
        outline extruded over ``face_width`` mm (:func:`gears.solid.mesh.gear_solid`)."""
        from gears.arguments import check_length
        from gears.solid.mesh import gear_solid, scene, transform

        phi = check_angle("angle", angle)
        b = check_length("face_width", face_width, self.center_distance, "the centre distance")
        tol = check_tolerance(tolerance, module=self.cutter.module)
        first, second = self.outline(1, tol), self.outline(2, tol)
        psi = float(self.output_angle(phi))
        return scene([
            ("gear1", gear_solid(first, b, tolerance=tol), transform(phi), (0.2, 0.4, 0.8)),
            ("gear2", gear_solid(second, b, tolerance=tol),
             transform(-psi, (self.center_distance, 0.0)), (0.9, 0.5, 0.1)),
        ])  # fmt: skip

    def animate(
        self, path: str | os.PathLike[str], frames: int = 72, fps: float = 20.0,
        tolerance: float = 0.05, progress: Callable | None = None,
    ) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of both gears in mesh over one turn of gear 1 at
        constant input speed: gear 2 turns by the law, at its varying speed
        (:func:`gears.solid.animate.write_animation`). Checked and its drawing's size estimated
        before any work (the animation budget)."""
        from shapely import affinity

        from gears.budget import check_budget
        from gears.files import check_output
        from gears.solid.animate import write_animation

        path = check_output(path, (".gif", ".mp4"))
        n = check_frames(frames)
        check_fps(fps)
        tol = check_tolerance(tolerance, module=self.cutter.module)
        check_callback("progress", progress)
        one, two = self.outline(1, tol), self.outline(2, tol)
        size = shapely.get_num_coordinates(one) + shapely.get_num_coordinates(two)
        check_budget("animation", f"{n} frames of {self.name}", lambda t: n * size * tol / t,
                     tol, hint="fewer frames")  # fmt: skip
        a = self.center_distance

        def frame(i: int) -> list:
            phi = 360.0 * i / n
            psi = float(self.output_angle(phi))
            first = affinity.rotate(one, phi, origin=(0.0, 0.0))
            second = affinity.translate(affinity.rotate(two, -psi, origin=(0.0, 0.0)), a, 0.0)
            return [(first, "tab:blue"), (second, "tab:orange")]

        return write_animation(path, frame, fps=fps, n_frames=n, progress=progress)

    def _placed(self, first, second, phi: float):
        from shapely import affinity

        psi = float(self.output_angle(phi))
        one = affinity.rotate(first, phi, origin=(0.0, 0.0))
        two = affinity.rotate(second, -psi, origin=(0.0, 0.0))
        return one, affinity.translate(two, self.center_distance, 0.0)

    # -- checks ---------------------------------------------------------------------------------
    def check(self, min_tip_land: float = 0.2) -> Report:
        """Findings: each pitch curve convex (a rack or hob can cut it), and with a module the
        undercut and tip land of the worst tooth on each gear (the equivalent circular gear of
        the local radius of curvature, :func:`gears.noncircular.checks.tooth_margins`), and
        the closure of both curves."""
        land = check_real("min_tip_land", min_tip_land, 0.0, 1.0, low_open=False)
        findings = []
        gap = abs(2.0 * math.pi / self.lobes[1] - self.law.advance)
        r2_mean = float(np.mean(self._radii_samples[1]))
        closure_tol = 1e-6 * self.center_distance
        findings.append(Finding(
            "closure", closure_tol - gap * r2_mean,
            f"gear 2's pitch curve closes after {self.lobes[1]} lobe(s) to {gap * r2_mean:.2g} mm",
        ))  # fmt: skip
        z = self.teeth
        for g in (1, 2):
            where = self._tooth_angles(g) if z else np.degrees(self._grid[:-1])
            k = self.curvature(where, g)
            m = self.module or 1.0
            undercut, tip, conv = tooth_margins(k, m, self.pressure_angle, self.addendum, land)
            i = int(np.argmin(conv))
            rho = "inf" if conv[i] == 0 else f"{1.0 / conv[i]:.4g} mm"
            findings.append(Finding(
                f"gear{g}.convexity", float(conv[i]),
                f"gear {g}'s pitch curve is convex; its flattest point (radius of curvature "
                f"{rho}) passes the pole at the input angle {float(where[i]):.4g} deg"
                if conv[i] >= 0 else
                f"gear {g}'s pitch curve is concave near the input angle {float(where[i]):.4g} "
                f"deg (radius of curvature {rho}): a rack or hob cannot cut it",
                unit="1/mm",
            ))  # fmt: skip
            if z:
                j = int(np.argmin(undercut))
                findings.append(Finding(
                    f"gear{g}.undercut", float(undercut[j]),
                    f"tooth {j + 1} of {z[g - 1]} on gear {g}, the equivalent gear of "
                    f"{2.0 / max(k[j], 1e-300) / m:.4g} teeth, is free of undercut down to the "
                    f"profile shift {-float(undercut[j]):.3g}"
                    if undercut[j] >= 0 else
                    f"tooth {j + 1} of {z[g - 1]} on gear {g}, the equivalent gear of "
                    f"{2.0 / max(k[j], 1e-300) / m:.4g} teeth, is undercut: it needs the profile "
                    f"shift {-float(undercut[j]):.3g} (a larger pitch curve or a smaller module)",
                    unit="module",
                ))  # fmt: skip
                j = int(np.argmin(tip))
                findings.append(Finding(
                    f"gear{g}.pointed_tip", float(tip[j]),
                    f"tooth {j + 1} of {z[g - 1]} on gear {g}: tip land "
                    f"{float(tip[j]) + land * m:.3g} mm against {land:g} m = {land * m:.3g} mm",
                ))  # fmt: skip
        return Report(findings)

    def _tooth_angles(self, gear: int) -> np.ndarray:
        """The input angles (degrees) at which each tooth centre of ``gear`` passes the pole,
        from the arc length (gear 1 and gear 2 roll the same length per period)."""
        x = self._grid
        arc = np.concatenate([[0.0], np.cumsum(_spline_arc_length(self._splines[0], True))])
        per = arc[-1]
        # tooth j's centre passes the pole after j pitches of rolling, j = 0 ... z - 1 (gear 2's
        # z2 teeth take lobes2 periods of the law)
        rolled = np.arange(self.teeth[gear - 1]) * (per * self.lobes[0] / self.teeth[0])
        k, rest = np.divmod(rolled, per)
        return np.degrees(k * self.law.period + np.interp(rest, arc, x))

    def __repr__(self) -> str:
        teeth = "" if self.teeth is None else f", teeth={self.teeth}, module={self.module:.4g}"
        return (
            f"NonCircularPair({self.name}, center_distance={self.center_distance:.6g}, "
            f"kind={self.kind!r}, lobes={self.lobes}{teeth})"
        )
