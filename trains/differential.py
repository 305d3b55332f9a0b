"""Layer 5, stages: the bevel (car) differential built on real straight bevel gears.

The car differential (Ozols Fig. 7-11, formula (7.9): ``w_left + w_right = 2 w_case``;
lectures §4.5) as a thin builder over :class:`trains.willis.Train`: two side gears on the axle and
``n`` pinions on the case, every mesh a :class:`gears.BevelPair` at a shaft angle of 90 deg.

Speeds are counted about the axle for the side gears and the case (one direction for both wheels,
positive forward), and about each pinion's own axis, pointing away from the centre, for the
pinions (their spin in the case is ``Motion.relative("pinion", "case")``). With both axes pointing
away from the common apex a bevel mesh is an external one (``z_a w_a + z_b w_b = 0`` relative to
the carrier; docs/bevel.md); the left side gear's outward axis points against the axle, so its
mesh is entered ``opposed`` (:meth:`trains.Train.mesh`). Subtracting the two Willis equations
gives (7.9).

Equally spaced pinions assemble only when ``2 z_side / n_pinions`` is an integer: the assembly
number of the generic planet condition (lectures §4.3) is ``T = 2 z_side`` here. :meth:`check`
reports it; :meth:`scene` refuses to place pinions that cannot be assembled.

Placement (:meth:`scene`): the axle is +y, the right side gear's axis +y, the left one's -y;
pinion k's axis is ``R_y(case + 360 k / n) e_x``; every member turns by its speed times
``angle``, phased so that the teeth interleave (the derivation is in docs/bevel.md).
"""

from __future__ import annotations

import math
import numbers
import os
import pathlib
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

import numpy as np

from gears import BevelPair, GearError, Report
from gears.arguments import MAX_TEETH, check_integer, check_real
from gears.bevel.drawing import bevel_svg
from gears.bevel.solid import rotation
from trains.conditions import refuse_failing
from trains.errors import TrainError
from trains.willis import Motion, Train

if TYPE_CHECKING:
    import trimesh

__all__ = ["Differential"]

# pinion-local -> world: the pinion's axis (local z) along world x, local x towards the right
# side gear (world y)
_M0 = np.eye(4)
_M0[:3, :3] = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])

COLOURS = {"side": (222, 140, 60, 255), "pinion": (70, 130, 180, 255)}


def _count(name: str, value: Any) -> int:
    """A count of teeth or pinions: an integer 1 ... MAX_TEETH (a larger one is no gear, and
    10**400 would overflow every float formula)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral):
        raise TrainError(f"{name} = {value!r}; valid is an integer 1 ... {MAX_TEETH}")
    try:
        return check_integer(name, value, 1, MAX_TEETH)
    except GearError as exc:
        raise TrainError(str(exc)) from None


class Differential:
    """A bevel differential with real straight bevel gears (see the module docstring).

    Parameters
    ----------
    side : int
        Teeth of each side gear.
    pinion : int
        Teeth of each pinion.
    n_pinions : int
        Equally spaced pinions on the case (2 in most cars, 4 in trucks).
    module : float
        Outer transverse module m_et, mm.
    face_width : float, optional
        b, mm; default ``R_e / 3.5`` rounded down to 0.1 mm (inside the rule ``b <= R_e / 3``).
    pressure_angle : float
        alpha, degrees (differentials often use 22.5 or 25 to avoid undercut of their few-toothed
        pinions).
    gleason : bool
        True: the Gleason proportions of KHK Table 4.11 (:meth:`gears.BevelPair.gleason`);
        False: standard heights with ``profile_shift`` on the pinion.
    **kwargs
        Passed to :class:`gears.BevelPair` (``profile_shift``, ``clearance``, ``profile``, ...).

    Examples
    --------
    >>> d = Differential(side=16, pinion=10, module=3, gleason=True)
    >>> m = d.solve(left=90, right=110)
    >>> m["case"], m.relative("pinion", "case")
    (Fraction(100, 1), Fraction(-16, 1))
    >>> d.check().ok
    True
    """

    def __init__(
        self, side: int = 16, pinion: int = 10, n_pinions: int = 2, module: float = 3.0,
        face_width: float | None = None, pressure_angle: float = 20.0, gleason: bool = False,
        **kwargs: Any,
    ) -> None:  # fmt: skip
        self.side = _count("side", side)
        self.pinion = _count("pinion", pinion)
        self.n_pinions = _count("n_pinions", n_pinions)
        if not isinstance(gleason, bool):
            raise TrainError(f"gleason = {gleason!r}; valid is True or False")
        try:
            if face_width is None:
                r_e = BevelPair(self.pinion, self.side, module, 1e-3).cone_distance
                face_width = math.floor(10.0 * r_e / 3.5) / 10.0 or r_e / 3.5
            build = BevelPair.gleason if gleason else BevelPair
            self.pair = build(self.pinion, self.side, module, face_width, 90.0, pressure_angle,
                              **kwargs)  # fmt: skip
        except GearError as exc:
            raise TrainError(
                f"differential side = {self.side}, pinion = {self.pinion}: {exc}"
            ) from None
        t = Train()
        t.name = f"bevel differential {self.side}/{self.pinion}, {self.n_pinions} pinions"
        t.mesh("pinion", "right", pair=self.pair, carrier="case", name="pinion-right")
        t.mesh("pinion", "left", pair=self.pair, carrier="case", name="pinion-left", opposed=True)
        t.set_planets("pinion", self.n_pinions)
        self.train = t
        self._meshes: dict = {}

    @property
    def module(self) -> float:
        return self.pair.module

    @property
    def face_width(self) -> float:
        return self.pair.face_width

    def solve(self, known: dict | None = None, /, **speeds: Any) -> Motion:
        """Speeds of every member from two of ``left``, ``right``, ``case`` (any unit):
        :meth:`trains.Train.solve`. The pinions' spin in the case is
        ``motion.relative("pinion", "case")``. Speeds beyond 1e150 in size are refused (the
        float arithmetic would overflow; give integers or Fractions for exact answers)."""
        for name, v in {**(known or {}), **speeds}.items():
            if isinstance(v, float) and not abs(v) <= 1e150:
                raise TrainError(f"{name} = {v!r}; valid is a finite speed of at most 1e150")
        return self.train.solve(known, **speeds)

    def rating(self, torque: float, left: float, right: float,
               material: Any = "case-carburized", **options: Any) -> dict:  # fmt: skip
        """Pitting and bending rating of every mesh (``"pinion-right"``, ``"pinion-left"``) by
        ISO 10300 method B1 (:meth:`gears.BevelPair.rating`): a dict of
        :class:`gears.BevelRating`.

        ``torque`` N m on the case, split equally between the side gears and among the
        ``n_pinions`` pinions (a differential without friction); ``left`` and ``right`` the
        wheels' speeds in rpm, which must differ: the pinions roll on the side gears only
        while the wheels turn at different speeds (cornering, a spinning wheel), and a flank
        loaded standing still is not rated by ISO 10300. Each pinion is loaded on opposite
        flanks by the two side gears (an idler, Y_M); each side gear meets ``n_pinions`` pinions
        per relative turn. ``options`` go to :meth:`gears.BevelPair.rating` (``life``,
        ``mounting``, ``pattern``, ``effective_width``, ``quality``, factors).

        >>> d = Differential(side=16, pinion=10, module=3, gleason=True)
        >>> r = d.rating(torque=150, left=90, right=110)
        >>> [round(s, 2) for s in r["pinion-right"].safety_bending]
        [1.49, 2.11]
        """
        try:
            t = check_real("torque", torque, 0.0)
        except GearError as exc:
            raise TrainError(str(exc)) from None
        m = self.solve(left=left, right=right)
        spin = abs(float(m.relative("pinion", "case")))
        if not spin > 0.0:
            raise TrainError(
                f"left = {left!r}, right = {right!r}: the pinions do not turn in the case (the "
                "wheels turn alike), so no flank rolls; ISO 10300 rates rolling flanks: give the "
                "wheel speeds of a turn"
            )
        per_mesh = t / 2.0 / self.n_pinions * self.pinion / self.side  # on each pinion
        options.setdefault("idler", (True, False))
        out = {}
        for name in ("pinion-right", "pinion-left"):
            try:
                out[name] = self.pair.rating(per_mesh, spin, material,
                                             contacts=(1, self.n_pinions), **options)  # fmt: skip
            except GearError as exc:
                raise TrainError(f"mesh {name}: {exc}") from None
        return out

    @property
    def assembles(self) -> bool:
        """True when ``2 z_side / n_pinions`` is an integer (equally spaced pinions fit)."""
        return (2 * self.side) % self.n_pinions == 0

    def check(self, tolerance: float = 0.01, min_contact_ratio: float = 1.1,
              min_tip_land: float = 0.2, clearance: float = 0.5) -> Report:  # fmt: skip
        """Every mesh's findings (``pinion-right.*``, ``pinion-left.*``: the bevel pair's
        :meth:`gears.BevelPair.check`), the pinions' assembly (``pinion.assembly``: the assembly
        number ``T = 2 z_side`` a multiple of ``n_pinions``) and their neighbour gap
        (``pinion.neighbour``: the face cones of neighbouring pinions at least ``clearance``
        modules apart at their outer tips): :meth:`trains.Train.check`."""
        return self.train.check(tolerance, min_contact_ratio, min_tip_land, clearance)

    # --- placement -------------------------------------------------------------------------------
    def _angles(self, angle: float, left: float, right: float):
        """Each member's turn in degrees: ``angle`` times its speed over the faster wheel's."""
        for name, v in (("angle", angle), ("left", left), ("right", right)):
            try:
                check_real(name, v)
            except GearError as exc:
                raise TrainError(str(exc)) from None
        if not abs(angle) <= 1e12:
            raise TrainError(
                f"angle = {float(angle):g}; valid is a finite angle of at most 1e12 deg"
            )
        top = max(abs(float(left)), abs(float(right)))
        if top == 0.0:
            return 0.0, 0.0, 0.0
        m = self.solve(left=float(left) / top, right=float(right) / top)
        return angle * float(m["left"]), angle * float(m["right"]), angle * float(m["case"])

    def placements(self, angle: float = 0.0, left: float = 1.0, right: float = 1.0) -> dict:
        """4x4 placements of the members by name (``left``, ``right``, ``pinion1`` ...) for the
        wheel speeds ``left`` and ``right`` (any unit): the faster wheel has turned by ``angle``
        degrees, every other member in proportion to its speed (the case at the wheels' mean,
        the pinions spinning as the Willis relations say).

        Raises
        ------
        TrainError
            When the pinions cannot be assembled equally spaced (``2 z_side / n_pinions`` not
            an integer), or for a non-finite angle or speed.
        """
        if not self.assembles:
            raise TrainError(
                f"{self.n_pinions} pinions cannot be equally spaced around side gears of "
                f"{self.side} teeth: 2 z_side / n_pinions = {2 * self.side / self.n_pinions:g} is "
                f"not an integer (valid n_pinions divide {2 * self.side})"
            )
        deg_l, deg_r, deg_c = self._angles(angle, left, right)
        zs, zp = self.side, self.pinion
        m_r = _M0 @ rotation((0.0, 1.0, 0.0), 90.0)  # side-local z -> world +y
        m_l = _M0 @ rotation((0.0, 0.0, 1.0), 180.0) @ rotation((0.0, 1.0, 0.0), 90.0)  # -> -y
        z_axis = (0.0, 0.0, 1.0)
        out = {
            "right": m_r @ rotation(z_axis, deg_r),
            "left": m_l @ rotation(z_axis, -deg_l + 180.0 * zp / zs),
        }
        for k in range(self.n_pinions):
            c_k = deg_c + 360.0 * k / self.n_pinions
            a_k = (180.0 + 180.0 / zs + c_k - deg_r) * zs / zp
            out[f"pinion{k + 1}"] = rotation((0.0, 1.0, 0.0), c_k) @ _M0 @ rotation(z_axis, a_k)
        return out

    def _solids(self, tolerance: float, backlash: float, bore: float | None):
        key = (float(tolerance), float(backlash), bore)
        if key not in self._meshes:
            try:
                side = self.pair.g2.mesh(tolerance, bore=bore, backlash=backlash)
                pinion = self.pair.g1.mesh(tolerance, backlash=backlash)
            except GearError as exc:
                raise TrainError(f"differential {self.side}/{self.pinion}: {exc}") from None
            side.metadata["name"] = "side_gear"
            pinion.metadata["name"] = "pinion"
            self._meshes.clear()  # keep one set: meshes are large
            self._meshes[key] = (side, pinion)
        return self._meshes[key]

    def scene(
        self, angle: float = 0.0, left: float = 1.0, right: float = 1.0, tolerance: float = 0.02,
        backlash: float = 0.0, bore: float | None = None, check: bool = True,
    ) -> trimesh.Scene:  # fmt: skip
        """The side gears and pinions as a ``trimesh.Scene`` (:meth:`placements`): the two side
        gears share one mesh, the pinions another (instanced). ``bore`` is the side gears' bore
        (the axle), mm. A design that fails :meth:`check` (pinions that collide, teeth that
        interfere) is refused unless ``check=False``.

        Examples
        --------
        >>> sc = Differential(16, 10, module=3, gleason=True).scene(tolerance=0.1)
        >>> sorted(sc.graph.nodes_geometry), len(sc.geometry)
        (['left', 'pinion1', 'pinion2', 'right'], 2)
        """
        from gears.arguments import check_tolerance
        from gears.budget import check_budget
        from gears.solid.mesh import scene

        place = self.placements(angle, left, right)
        refuse_failing(self, check, "scene")
        try:
            tolerance = check_tolerance(tolerance, module=self.module)
            check_budget(
                "mesh", f"the scene of the differential {self.side}/{self.pinion}",
                lambda t: self.pair.g1._vertices()(t) + self.pair.g2._vertices()(t), tolerance,
            )  # fmt: skip
        except GearError as exc:
            raise TrainError(str(exc)) from None
        side, pinion = self._solids(tolerance, backlash, bore)
        parts = [("left", side, place["left"], COLOURS["side"]),
                 ("right", side, place["right"], COLOURS["side"])]  # fmt: skip
        for k in range(self.n_pinions):
            name = f"pinion{k + 1}"
            parts.append((name, pinion, place[name], COLOURS["pinion"]))
        return scene(parts)

    def animate(
        self, path: str | os.PathLike[str], frames: int = 48, left: float = 0.9,
        right: float = 1.1, turn: float | None = None, tolerance: float = 0.05, fps: float = 16.0,
        elevation: float = 20.0, azimuth: float = -35.0, size: int = 400,
        progress: Callable[[int, int], object] | None = None, check: bool = True,
    ) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4) of the differential turning through a corner: the wheels at the
        speeds ``left`` and ``right`` (the outer wheel faster), the faster one turning by
        ``turn`` degrees over the animation (default two pinion pitches, ``720 / z_pinion``),
        every member in proportion (:meth:`placements`), seen from ``elevation`` and ``azimuth``
        degrees, ``size`` pixels square (:func:`gears.solid.render.write_animation_3d`;
        ``progress(i, n)`` after each frame). A design that fails :meth:`check` is refused
        unless ``check=False`` (:meth:`scene`)."""
        from gears.arguments import check_frames, check_tolerance
        from gears.bevel.pair import ANIMATION_BUDGET_3D, DRAWN_PER_VERTEX
        from gears.budget import check_budget
        from gears.solid.render import Camera, write_animation_3d

        try:
            n = check_frames(frames)
            tolerance = check_tolerance(tolerance, module=self.module)
            # every placed part is drawn: two side gears and the pinions
            g1, g2 = self.pair.g1, self.pair.g2
            check_budget(
                "animation", f"{n} frames of the differential {self.side}/{self.pinion}",
                lambda t: n * DRAWN_PER_VERTEX * (2 * g2._vertices()(t)
                                                  + self.n_pinions * g1._vertices()(t)),
                tolerance, hint="fewer frames", budget=ANIMATION_BUDGET_3D,
            )  # fmt: skip
        except GearError as exc:
            raise TrainError(str(exc)) from None
        turn = 2 * 360.0 / self.pinion if turn is None else turn
        self.placements(0.0, left, right)  # refuse bad speeds and unassemblable pinions now
        refuse_failing(self, check, "animation")
        if isinstance(turn, bool) or not isinstance(turn, numbers.Real) or not math.isfinite(turn):
            raise TrainError(f"turn = {turn!r}; valid is a finite number of degrees")
        side, pinion = self._solids(tolerance, 0.0, None)
        colour = {"left": COLOURS["side"], "right": COLOURS["side"]}

        def frame(i: int) -> list:
            place = self.placements(i * turn / n, left, right)
            out = []
            for name, m in place.items():
                mesh = pinion if name.startswith("pinion") else side
                v = mesh.vertices @ m[:3, :3].T + m[:3, 3]
                out.append((v, mesh.faces, colour.get(name, COLOURS["pinion"])))
            return out

        try:
            return write_animation_3d(path, frame, n, Camera(elevation, azimuth), fps=fps,
                                      size=size, progress=progress)  # fmt: skip
        except GearError as exc:
            raise TrainError(str(exc)) from None

    def describe(self) -> str:
        """A readable summary: teeth, the pair's geometry, the speeds cornering, the report."""
        m = self.solve(left=90, right=110)
        lines = [
            f"{self.train.name}, module {self.module:g} mm, face width {self.face_width:g} mm",
            self.pair.describe(),
            f"cornering (left 90, right 110): case {float(m['case']):g}, pinions spin "
            f"{float(m.relative('pinion', 'case')):+g} in the case (Ozols (7.9): left + right = "
            "2 case)",
            f"assembly: 2 z_side / n_pinions = {2 * self.side}/{self.n_pinions}",
            str(self.check()),
        ]
        return "\n".join(lines)

    def __repr__(self) -> str:
        return (
            f"Differential(side={self.side}, pinion={self.pinion}, n_pinions={self.n_pinions}, "
            f"module={self.module:g}, face_width={self.face_width:g})"
        )

    def _repr_svg_(self) -> str:
        """What a notebook shows: the differential in the axial section through the axle and
        the first pinion (the side gears left and right, the pinions in that plane above and
        below), drawn by :func:`gears.bevel.drawing.bevel_svg`."""

        def parts() -> list:
            side, pinion = self.pair.g2, self.pair.g1
            out = [(side, 0.0, COLOURS["side"]), (side, 180.0, COLOURS["side"]),
                   (pinion, 90.0, COLOURS["pinion"])]  # fmt: skip
            if self.n_pinions % 2 == 0:  # a pinion opposite the first lies in the plane too
                out.append((pinion, 270.0, COLOURS["pinion"]))
            return out

        return bevel_svg(parts, "this differential",
                         f"{self!r}: axial section through the axle and pinion 1")  # fmt: skip
