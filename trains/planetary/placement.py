"""Layer 3, planetary: where the planets of a stage sit and how every gear turns at assembly.

The planet centre angles (equal, or the feasible unequal spacing of the assembly condition) and
the rotation of every gear that puts each mesh in phase: at each line of centres a tooth of one
gear faces a space of the other (:class:`Placement`). The functions take a
:class:`~trains.planetary.stage.Planetary` (``stage``) and are the bodies of its
:meth:`~trains.planetary.stage.Planetary.placement` and ``phasing``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from trains.errors import TrainError
from trains.planetary.schemes import phasing_class

__all__ = ["Placement"]


@dataclass(frozen=True)
class Placement:
    """Where each planet sits and how every gear is turned at assembly (degrees).

    A gear's *rotation* is the direction of the centre line of its tooth 0 in the stage frame
    (external gear: a tooth; ring: a ring tooth); the sun is at rotation 0. Every mesh is in
    phase: at each line of centres a tooth of one gear faces a space of the other. Stepped
    planets carry both steps with their tooth 0 on the same centre line.

    Attributes
    ----------
    planet_angles : tuple of float
        Centre angle of each planet (the sun-side planet of a double-planet cluster).
    planet_radius : float
        Distance from the stage axis to the planet centres, mm.
    planet_rotations : tuple of float
    planet2_angles, planet2_radius, planet2_rotations
        The outer planets of a double-planet stage (empty otherwise).
    sun_rotation, ring_rotation : float
    residual : float
        Largest mesh phase error in teeth (0 up to rounding when the stage assembles).
    """

    planet_angles: tuple[float, ...]
    planet_radius: float
    planet_rotations: tuple[float, ...]
    sun_rotation: float
    ring_rotation: float
    planet2_angles: tuple[float, ...] = ()
    planet2_radius: float = 0.0
    planet2_rotations: tuple[float, ...] = ()
    residual: float = 0.0


def phasing(stage) -> dict[str, str]:
    """Mesh phasing class of each central-gear mesh (:func:`phasing_class`)."""
    z1, _, _, z3 = stage.teeth
    names = list(stage._pairs)
    return {names[0]: phasing_class(z1, stage.n_planets),
            names[-1]: phasing_class(z3, stage.n_planets)}  # fmt: skip


def placement(stage, angles: Iterable[float] | None = None) -> Placement:
    """Planet positions and gear rotations at assembly (:meth:`Planetary.placement`)."""
    if angles is None:
        asm = stage.assembly()
        th = [s / 360.0 for s in asm.spacing]
    else:
        th = planet_turns(angles, stage.n_planets)
    z1, zc, zd, z3 = stage.teeth
    pairs = stage._pairs
    first = next(iter(pairs.values()))
    a1 = first.center_distance
    sun_internal = stage.scheme == "internal"
    ring_internal = stage.scheme != "external"
    # phases in teeth; angles in turns. External pair: p1 + p2 = 1/2; internal: p_r - p_p = 1/2
    rot_p, rot_p2, th2 = [], [], []
    ring_rot = None
    resid = 0.0
    a2 = 0.0
    psi = 0.0
    if stage.scheme == "double-planet":
        a12 = pairs["planet-planet2"].center_distance
        a2 = pairs["planet2-ring"].center_distance
        cos_psi = (a1 * a1 + a2 * a2 - a12 * a12) / (2 * a1 * a2)
        psi = math.acos(min(1.0, max(-1.0, cos_psi))) / (2 * math.pi)
        # direction from inner to outer planet centre, relative to the inner planet's angle
        dx = a2 * math.cos(2 * math.pi * psi) - a1
        dy = a2 * math.sin(2 * math.pi * psi)
        beta = math.atan2(dy, dx) / (2 * math.pi)
    for t in th:
        p_sun = z1 * t  # sun phase at direction t (sun rotation 0)
        best = None
        for n in range(zc):
            if sun_internal:  # planet inside the sun ring: p_s - p_p = 1/2 at direction t
                phi = t - (p_sun - 0.5 - n) / zc
            else:  # planet phase at direction t + 1/2: z_c (t + 1/2 - phi)
                phi = t + 0.5 - (0.5 - p_sun + n) / zc
            if stage.scheme == "double-planet":
                b = t + beta
                p_in = zc * (b - phi)
                phi2 = b + 0.5 - (0.5 - p_in) / zd
                t2 = t + psi
                p_out = zd * (t2 - phi2)
                direction, phase = t2, p_out
            else:
                phi2 = phi
                direction = t
                # ring-side planet phase towards the ring mesh
                phase = zd * (t - phi) if ring_internal else zd * (t + 0.5 - phi)
            if ring_internal:  # p_r - p_d = 1/2 with p_r = z3 (direction - rho)
                target = lambda rho, d=direction, ph=phase: z3 * (d - rho) - ph - 0.5  # noqa: E731
            else:  # external ring at the axis: p_r + p_d = 1/2 with p_r = z3 (direction - rho)
                target = lambda rho, d=direction, ph=phase: z3 * (d - rho) + ph - 0.5  # noqa: E731
            if ring_rot is None:
                ring_rot = direction - (phase + 0.5) / z3 if ring_internal else (
                    direction - (0.5 - phase) / z3)  # fmt: skip
            err = target(ring_rot)
            err = abs(err - round(err))
            if best is None or err < best[0] - 1e-12:
                best = (err, phi, phi2)
            if err < 1e-9:
                break
        resid = max(resid, best[0])
        rot_p.append(360.0 * (best[1] % 1.0))
        if stage.scheme == "double-planet":
            rot_p2.append(360.0 * (best[2] % 1.0))
            th2.append(360.0 * ((t + psi) % 1.0))
    return Placement(
        planet_angles=tuple(360.0 * (t % 1.0) for t in th),
        planet_radius=a1,
        planet_rotations=tuple(rot_p),
        sun_rotation=0.0,
        ring_rotation=360.0 * (ring_rot % 1.0) if ring_rot is not None else 0.0,
        planet2_angles=tuple(th2),
        planet2_radius=a2,
        planet2_rotations=tuple(rot_p2),
        residual=resid,
    )


def planet_turns(angles: Any, n_planets: int) -> list[float]:
    """Planet centre angles (degrees) as fractions of a turn, refused unless there is one
    finite angle per planet and no two planets share a place."""
    try:
        values = [float(a) for a in angles]
    except (TypeError, ValueError):
        raise TrainError(f"angles = {angles!r}; valid is one angle in degrees per planet") from None
    if len(values) != n_planets or not all(math.isfinite(a) for a in values):
        raise TrainError(f"angles = {values}; valid is {n_planets} finite planet angles in degrees")
    turns = sorted(a / 360.0 % 1.0 for a in values)
    gaps = [b - a for a, b in zip(turns, [*turns[1:], turns[0] + 1.0], strict=True)]
    if n_planets > 1 and min(gaps) < 1e-9:
        raise TrainError(
            f"angles = {values}: two planets would sit at the same place; valid is "
            f"{n_planets} distinct angles (mod 360 deg)"
        )
    return [a / 360.0 for a in values]
