"""Layer 6, stages: the cycloidal drive, a disc of N - 1 lobes rolling on N pins.

The disc sits on an eccentric (the input, the carrier); its profile is the inward parallel
curve at the pin radius of the path a pin centre traces in the disc's frame
(:mod:`gears.noncircular.cycloid`), so that at every angle every pin lies on the disc. The
kinematics is the K-H-V train (Ozols Fig 7-9b; :func:`trains.catalog.khv`): with the pins
fixed, the disc turns by -1/(N - 1) of the input, and a W mechanism (pins in holes) takes its
rotation out. A compound drive adds a second disc of N2 - 1 lobes, fixed to the first, on a
turning ring of N2 output pins: its ratio 1 / (1 - N1 (N2 - 1) / ((N1 - 1) N2)) comes from the
same solver.

The usual clearance modifications (the disc cut with a larger pin radius, ``equidistant``, and
a smaller pin circle, ``radial``) give the backlash a real disc needs; :meth:`check` reports the
clearance, the undercut limit (the pin radius against the pin path's least convex radius of
curvature), the curtate condition R > e N and the pins' spacing.

The load shared among the lobes follows the classical assumption of equal rigidity (the
contact deflection proportional to the lever arm about the disc's centre: Kudryavtsev's
analysis of cycloidal-pin gearing): each contact's force acts along its normal, which passes
through the pitch point P (on the eccentric's line at e N from the centre), and
F_i = T l_i / sum(l_j^2) over the pins whose lever arm l_i about the disc's centre is positive.
"""

from __future__ import annotations

import math
import os
import pathlib
from collections.abc import Callable
from dataclasses import dataclass
from fractions import Fraction
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike

from gears import GearError, Report

if TYPE_CHECKING:
    import shapely
    import trimesh
from gears.arguments import check_angle, check_integer, check_positive, check_real, check_tolerance
from gears.noncircular.cycloid import disc_profile, path_curvature
from gears.report import Finding
from trains.catalog import khv
from trains.willis import Train

__all__ = ["CycloidalDrive"]

#: The most pins a drive may have.
MAX_PINS = 1000


@dataclass(frozen=True)
class CycloidalDrive:
    """A cycloidal drive: ``pins`` pins of ``pin_radius`` on a circle of ``pin_circle_radius``,
    one disc of ``pins - 1`` lobes on an ``eccentricity`` (mm).

    ``equidistant`` and ``radial`` (mm, >= 0) are the clearance modifications: the disc is cut
    for pins larger by ``equidistant`` on a circle smaller by ``radial``. ``output_pins`` and
    ``output_pin_circle_radius`` make a compound drive (a second disc of ``output_pins - 1``
    lobes on a turning ring of output pins, same pin radius and eccentricity).

    Examples
    --------
    >>> d = CycloidalDrive(pins=12, pin_radius=3.0, eccentricity=1.5, pin_circle_radius=40.0)
    >>> d.lobes, d.ratio
    (11, Fraction(-11, 1))
    >>> CycloidalDrive(9, 3.0, 1.0, 40.0, output_pins=8, output_pin_circle_radius=36.0).ratio
    Fraction(64, 1)
    """

    pins: int
    pin_radius: float
    eccentricity: float
    pin_circle_radius: float
    equidistant: float = 0.0
    radial: float = 0.0
    output_pins: int | None = None
    output_pin_circle_radius: float | None = None

    def __post_init__(self) -> None:
        n = check_integer("pins", self.pins, 3, MAX_PINS)
        rp = check_positive("pin_radius", self.pin_radius)
        e = check_positive("eccentricity", self.eccentricity)
        big = check_positive("pin_circle_radius", self.pin_circle_radius)
        big = check_real("pin_circle_radius", big, e * n, 1e9)  # curtate: R > e N
        rp = check_real("pin_radius", rp, 0.0, big)
        dr = check_real("equidistant", self.equidistant, 0.0, rp, low_open=False)
        dR = check_real("radial", self.radial, 0.0, big - e * n, low_open=False)
        values = {"pins": n, "pin_radius": rp, "eccentricity": e, "pin_circle_radius": big,
                  "equidistant": dr, "radial": dR}  # fmt: skip
        if (self.output_pins is None) != (self.output_pin_circle_radius is None):
            raise GearError(
                "output_pins and output_pin_circle_radius go together: give both for a compound "
                "drive, or neither"
            )
        if self.output_pins is not None:
            n2 = check_integer("output_pins", self.output_pins, 3, MAX_PINS)
            r2 = check_real("output_pin_circle_radius", self.output_pin_circle_radius, e * n2, 1e9)
            if n2 == n:
                raise GearError(
                    f"output_pins = {n2} equals pins: a compound drive of equal stages does "
                    "not turn its output; valid is output_pins != pins"
                )
            values.update(output_pins=n2, output_pin_circle_radius=r2)
        for k, v in values.items():
            object.__setattr__(self, k, v)

    # -- kinematics ------------------------------------------------------------------------------
    @property
    def lobes(self) -> int:
        """The disc's lobes, N - 1."""
        return self.pins - 1

    @property
    def compound(self) -> bool:
        """A second disc on a turning ring of output pins."""
        return self.output_pins is not None

    @property
    def train(self) -> Train:
        """The Willis train: members ``"carrier"`` (the eccentric), ``"disc"``, ``"ring"`` (the
        fixed pins), and ``"output"`` (the W coupling; a compound drive's output ring)."""
        if not self.compound:
            t = khv(self.lobes, self.pins)
            return t
        t = Train()
        t.name = f"compound cycloidal {self.lobes}/{self.pins} - {self.output_pins - 1}/" + (
            f"{self.output_pins}"
        )
        t.mesh("disc", "ring", teeth=(self.lobes, self.pins), carrier="carrier", internal=True)
        t.mesh("disc", "output", teeth=(self.output_pins - 1, self.output_pins),
               carrier="carrier", internal=True)  # fmt: skip
        return t

    @property
    def ratio(self) -> Fraction:
        """Input (eccentric) over output speed with the pins fixed, from the Willis solver:
        -(N - 1) for one disc, 1 / (1 - N1 (N2 - 1) / ((N1 - 1) N2)) for a compound drive."""
        return self.train.ratio("carrier", "output", fixed=["ring"])

    def disc_angle(self, angle: ArrayLike) -> np.ndarray:
        """The disc's rotation (degrees) when the eccentric has turned ``angle`` degrees."""
        return np.asarray(angle, dtype=float) * (-1.0 / self.lobes)

    # -- geometry --------------------------------------------------------------------------------
    def _profile(self, theta, stage: int = 1):
        n, big = (self.pins, self.pin_circle_radius) if stage == 1 else (
            self.output_pins, self.output_pin_circle_radius)  # fmt: skip
        return disc_profile(theta, n, self.pin_radius + self.equidistant, self.eccentricity,
                            big - self.radial)  # fmt: skip

    def disc_outline(self, tolerance: float = 0.01, stage: int = 1) -> shapely.Polygon:
        """The disc in its own frame (centre at the origin, as at eccentric angle 0), a
        shapely Polygon sampled so that its chords sag at most ``tolerance`` mm."""
        import shapely

        tol = check_tolerance(tolerance, module=self.pin_radius)
        stage = check_integer("stage", stage, 1, 2 if self.compound else 1)
        n = self.pins if stage == 1 else self.output_pins
        big = self.pin_circle_radius if stage == 1 else self.output_pin_circle_radius
        k = path_curvature(np.linspace(0, 2 * math.pi, 721), n, self.eccentricity, big)
        # the parallel curve at the pin radius bends by k / (1 - k rp) (signed)
        rp = self.pin_radius + self.equidistant
        kmax = float(np.max(np.abs(k / np.maximum(1.0 - k * rp, 1e-6))))
        length = 2.0 * math.pi * big * 1.5
        count = math.ceil(length / math.sqrt(8.0 * tol / max(kmax, 1e-12)))
        if count > 2_000_000:
            raise GearError(
                f"tolerance = {tol:g} mm needs {count} disc vertices; use a coarser one"
            )
        theta = np.linspace(0.0, 2.0 * math.pi * (n - 1), max(count, 64), endpoint=False)
        return shapely.Polygon(self._profile(theta, stage))

    def outlines(
        self, angle: float = 0.0, tolerance: float = 0.01
    ) -> tuple[shapely.Polygon, shapely.MultiPolygon]:
        """(disc, pins) placed when the eccentric has turned ``angle`` degrees: the disc about
        e (cos, sin) of the angle, turned by :meth:`disc_angle`; the pins as circles."""
        import shapely
        from shapely import affinity

        a = check_angle("angle", angle)
        disc = self.disc_outline(tolerance)
        disc = affinity.rotate(disc, float(self.disc_angle(a)), origin=(0.0, 0.0))
        t = math.radians(a)
        disc = affinity.translate(disc, self.eccentricity * math.cos(t),
                                  self.eccentricity * math.sin(t))  # fmt: skip
        alpha = 2.0 * math.pi * np.arange(self.pins) / self.pins
        centres = self.pin_circle_radius * np.stack([np.cos(alpha), np.sin(alpha)], axis=-1)
        sag = check_tolerance(tolerance, module=self.pin_radius)
        quad = max(
            4, math.ceil(math.pi / 2 / (2 * math.acos(max(-1.0, 1 - sag / self.pin_radius))))
        )
        pins = shapely.buffer(shapely.points(centres), self.pin_radius, quad_segs=min(quad, 256))
        return disc, shapely.MultiPolygon(list(pins))

    def scene(
        self, angle: float = 0.0, face_width: float = 8.0, tolerance: float = 0.01
    ) -> trimesh.Scene:
        """A ``trimesh.Scene`` of the disc and the pins at the eccentric angle ``angle``
        (degrees), each extruded over ``face_width`` mm (the pins as one shared cylinder)."""
        from gears.arguments import check_length
        from gears.solid.mesh import gear_solid, scene, transform

        a = check_angle("angle", angle)
        b = check_length("face_width", face_width, self.pin_circle_radius, "the pin circle")
        disc, pins = self.outlines(a, tolerance)
        pin = gear_solid(pins.geoms[0], b, tolerance=tolerance)
        pin.apply_translation([-self.pin_circle_radius, 0.0, 0.0])
        parts = [("disc", gear_solid(disc, b, tolerance=tolerance), None, (0.2, 0.4, 0.8))]
        for j in range(self.pins):
            centre = self.pin_circle_radius * np.array(
                [math.cos(2 * math.pi * j / self.pins), math.sin(2 * math.pi * j / self.pins)]
            )
            parts.append((f"pin{j}", pin, transform(0.0, centre), (0.6, 0.6, 0.6)))  # fmt: skip
        return scene(parts)

    def animate(
        self, path: str | os.PathLike[str], frames: int = 60, fps: float = 20.0,
        tolerance: float = 0.05, progress: Callable | None = None,
    ) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of the disc rolling on the pins over one turn of
        the eccentric (:func:`gears.solid.animate.write_animation`)."""
        from shapely import affinity

        from gears.arguments import check_callback, check_fps, check_frames
        from gears.files import check_output
        from gears.solid.animate import write_animation

        path = check_output(path, (".gif", ".mp4"))
        n = check_frames(frames)
        check_fps(fps)
        check_callback("progress", progress)
        disc0, pins = self.outlines(0.0, tolerance)
        disc0 = affinity.translate(disc0, -self.eccentricity, 0.0)  # back on the origin
        pin_list = list(pins.geoms)

        def frame(i: int) -> list:
            a = 360.0 * i / n
            t = math.radians(a)
            d = affinity.rotate(disc0, float(self.disc_angle(a)), origin=(0.0, 0.0))
            d = affinity.translate(d, self.eccentricity * math.cos(t),
                                   self.eccentricity * math.sin(t))  # fmt: skip
            return [(d, "tab:blue"), *((p, "tab:gray") for p in pin_list)]

        return write_animation(path, frame, fps=fps, n_frames=n, progress=progress)

    # -- loads -----------------------------------------------------------------------------------
    def contact_forces(self, torque: float, angle: float = 0.0) -> np.ndarray:
        """The force (N) on each pin when the disc carries ``torque`` (N mm) at the eccentric
        angle ``angle`` (degrees), by the equal-rigidity assumption (module docstring); zero on
        the unloaded side. Without clearance modifications."""
        torque = check_positive("torque", torque, "N mm")
        t = math.radians(check_angle("angle", angle))
        return _pin_forces(torque, t, self.pins, self.eccentricity, self.pin_circle_radius)

    def check(self) -> Report:
        """Findings: curtate pin path (R > e N), no undercut of the disc (the pin radius below
        the pin path's least convex radius of curvature), the pins clear of each other, and the
        clearance the modifications give (>= 0)."""
        n, rp, e, big = self.pins, self.pin_radius, self.eccentricity, self.pin_circle_radius
        theta = np.linspace(0.0, 2.0 * math.pi, 2001)
        k = path_curvature(theta, n, e, big)
        rho = 1.0 / float(np.max(k)) if np.max(k) > 0 else math.inf
        undercut = min(rho - (rp + self.equidistant), 1e9)
        gap = 2.0 * big * math.sin(math.pi / n) - 2.0 * rp
        clearance = self.equidistant + self.radial
        findings = [
            Finding("curtate", big - e * n,
                    f"pin circle R = {big:.6g} mm against e N = {e * n:.6g} mm"),
            Finding("undercut", undercut,
                    f"pin radius {rp + self.equidistant:.4g} mm against the pin path's least "
                    f"convex radius of curvature {rho:.4g} mm"),
            Finding("pin_spacing", gap, f"gap between neighbouring pins {gap:.4g} mm"),
            Finding("clearance", clearance,
                    f"modifications give {clearance:.4g} mm of clearance at the pins "
                    "(equidistant + radial)"),
        ]  # fmt: skip
        return Report(findings)

    def __repr__(self) -> str:
        more = "" if not self.compound else f", output_pins={self.output_pins}"
        return (
            f"CycloidalDrive(pins={self.pins}, pin_radius={self.pin_radius:g}, "
            f"eccentricity={self.eccentricity:g}, pin_circle_radius={self.pin_circle_radius:g}"
            f"{more})"
        )


def _pin_forces(torque: float, theta: float, n: int, e: float, big: float) -> np.ndarray:
    """Equal-rigidity pin forces: the normal at each pin passes through the pitch point P = e N
    (cos, sin) theta; its lever arm about the disc's centre C = e (cos, sin) theta sets the
    share."""
    alpha = 2.0 * math.pi * np.arange(n) / n
    pins = big * np.stack([np.cos(alpha), np.sin(alpha)], axis=-1)
    u = np.array([math.cos(theta), math.sin(theta)])
    p, c = e * n * u, e * u
    d = pins - p
    d = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    rel = p - c
    arm = rel[0] * d[:, 1] - rel[1] * d[:, 0]  # signed moment arm of the unit normal about C
    arm = np.where(arm > 0, arm, 0.0)
    return torque * arm / float(np.sum(arm * arm))
