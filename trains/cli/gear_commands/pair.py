"""Geometry and checks of one meshing pair: every dimension of both gears (as mounted, after
tip shortening), the working pressure angle and centre distance, contact ratios, sliding,
efficiency and every check with its margin. The exit status is 1 when a check fails.

With --center-distance the profile shifts follow from the centre distance, divided between the
two gears by --split. With --torque (N m on gear 1) the mesh forces follow: tangential, radial,
axial and normal, on each gear, in the pair's frame (ISO 6336-1; Ozols (11.8)).

Examples:
    geartrain pair 12 24 --module 3 --shift 0.6 0.36
    geartrain pair 20 80 --module 2 --internal --shift 0 -0.5 --helix 15 --face-width 20
    geartrain pair 12 24 --module 3 --center-distance 56.5
    geartrain pair 20 40 --module 5 --torque 100
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from trains.cli._common import (
    CHECK_FAILED,
    OK,
    PAIR_NAMES,
    build_pair,
    pair_arguments,
    refuse_split_alone,
    scene_argument,
    write_scene,
)
from trains.cli._types import bounded, finite, non_negative, positive

if TYPE_CHECKING:
    from gears import Gear, GearPair

HELP = "geometry, contact ratios and checks of a gear pair (external, internal, helical)"


NAMES = {
    **PAIR_NAMES,
    "min_contact_ratio": "--min-contact-ratio",
    "min_tip_land": "--min-tip-land",
    "friction": "--friction",
    "torque": "--torque",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pair_arguments(
        parser,
        face_width_help="face width in mm: the overlap ratio of a helical pair, the gears of "
        "--scene (default there: 10 modules)",
    )
    parser.add_argument(
        "--min-contact-ratio", type=non_negative("--min-contact-ratio"), default=1.1,
        help="required transverse contact ratio",
    )  # fmt: skip
    parser.add_argument(
        "--min-tip-land", type=non_negative("--min-tip-land", "modules"), default=0.2,
        help="required tip land in modules",
    )  # fmt: skip
    parser.add_argument(
        "--friction", type=bounded("--friction", 0, 1, high_open=True), default=0.1,
        help="friction coefficient for the mesh efficiency",
    )  # fmt: skip
    scene_argument(parser, "both gears in mesh")
    parser.add_argument(
        "--tolerance", type=positive("--tolerance", "mm"), default=None,
        help="mesh tolerance of --scene, mm (default 0.02)",
    )  # fmt: skip
    parser.add_argument(
        "--torque", type=finite("--torque"), default=None,
        help="torque on gear 1, N m (signed about its axis): print the mesh forces",
    )  # fmt: skip


def refuse_unused(args: argparse.Namespace) -> None:
    """A TrainError (exit 2) for an option that means nothing for this pair."""
    from trains.errors import TrainError

    refuse_split_alone(args)
    if args.tolerance is not None and args.scene is None:
        raise TrainError("--tolerance is the mesh tolerance of --scene: it applies with --scene "
                         "only")  # fmt: skip
    if args.face_width is not None and not args.helix and args.scene is None:
        raise TrainError("--face-width gives a helical pair's overlap ratio and the --scene "
                         "gears' width; a spur pair (--helix 0) without --scene does not use "
                         "it")  # fmt: skip


def _value(fn: Callable[[], object], fmt: str = "{:.4f}") -> str:
    """Format ``fn()``; a quantity that does not exist for this gear shows as '-'."""
    from gears import GearError

    try:
        v = fn()
    except GearError:
        return "-"
    if isinstance(v, tuple):
        return " / ".join(fmt.format(e) if isinstance(e, float) else str(e) for e in v)
    if isinstance(v, float) and not math.isfinite(v):
        return "-"
    return fmt.format(v) if isinstance(v, float) else str(v)


def _gear_rows(g: Gear) -> list[tuple[str, str, Callable[[], object]]]:
    m = g.module

    def tip_land() -> float:
        beta_a = math.atan(
            math.tan(math.radians(g.helix_angle)) * g.tip_diameter / g.reference_diameter
        )
        return g.tip_thickness * math.cos(beta_a)

    return [
        ("teeth z", "", lambda: g.teeth),
        ("type", "", lambda: ("internal" if g.internal else "external") + f", {g.hand}"),
        ("profile shift x", "", lambda: g.profile_shift),
        ("tip alteration k", "", lambda: g.tip_alteration),
        ("reference diameter d", "mm", lambda: g.reference_diameter),
        ("base diameter d_b", "mm", lambda: g.base_diameter),
        ("tip diameter d_a", "mm", lambda: g.tip_diameter),
        ("root diameter d_f", "mm", lambda: g.root_diameter),
        ("form diameter d_Ff", "mm", lambda: g.form_diameter),
        ("pointed-tip diameter", "mm", lambda: g.pointed_tip_diameter),
        ("thickness at d, s_t", "mm", lambda: g.reference_thickness),
        ("base thickness s_b", "mm", lambda: g.base_thickness),
        ("tip land s_an", "mm", tip_land),
        ("tip land / m_n", "", lambda: tip_land() / m),
        ("x_min (undercut)", "", lambda: g.min_profile_shift if not g.internal else math.nan),
        ("span k / W_k", "mm", lambda: g.span()),
        ("chordal s / h", "mm", lambda: g.chordal_thickness()),
    ]


def pair_report(pair: GearPair, min_contact_ratio=1.1, min_tip_land=0.2, friction=0.1) -> str:
    """A readable report of ``pair``: both gears' dimensions (as mounted, after tip
    shortening), the mesh quantities and ``pair.check()`` with every margin."""
    g1, g2 = pair.mounted
    lines = []
    rows1, rows2 = _gear_rows(g1), _gear_rows(g2)
    lines.append(f"{'':28s} {'gear 1':>18s} {'gear 2':>18s}")
    for (name, unit, f1), (_, _, f2) in zip(rows1, rows2, strict=True):
        label = f"{name} [{unit}]" if unit else name
        lines.append(f"{label:28s} {_value(f1):>18s} {_value(f2):>18s}")
    lines.append("")
    mesh = [
        ("module m_n", "mm", lambda: g1.module),
        ("normal pressure angle alpha_n", "deg", lambda: g1.pressure_angle),
        ("helix angle beta (gear 1)", "deg", lambda: g1.helix_angle),
        ("transverse pressure angle alpha_t", "deg", lambda: g1.transverse_pressure_angle),
        ("working pressure angle alpha_wt", "deg", lambda: pair.working_pressure_angle),
        ("reference centre distance a_d", "mm", lambda: pair.reference_center_distance),
        ("centre distance a_w", "mm", lambda: pair.center_distance),
        ("centre distance modification y", "", lambda: pair.center_distance_modification),
        ("tip alteration k", "", lambda: pair.tip_alteration),
        ("ratio u = z2/z1", "", lambda: pair.ratio),
        ("working diameters d_w1 / d_w2", "mm", lambda: pair.working_diameters),
        ("contact ratio eps_alpha", "", lambda: pair.contact_ratio),
        ("overlap ratio eps_beta", "", lambda: pair.overlap_ratio),
        ("total contact ratio eps_gamma", "", lambda: pair.total_contact_ratio),
        ("max specific sliding 1 / 2", "", lambda: pair.max_specific_sliding),
        (f"mesh efficiency (f = {friction:g})", "", lambda: pair.mesh_efficiency(friction)),
    ]
    for name, unit, f in mesh:
        label = f"{name} [{unit}]" if unit else name
        lines.append(f"{label:40s} {_value(f):>24s}")
    lines.append("")
    lines.append("checks: " + str(pair.check(min_contact_ratio, min_tip_land)))
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    refuse_unused(args)
    pair = build_pair(args)
    ok = pair.check(args.min_contact_ratio, args.min_tip_land).ok
    kind = "internal" if pair.internal else "external"
    g1, g2 = pair.mounted
    print(
        f"gear pair {g1.teeth}/{g2.teeth} ({kind}), m_n = {g1.module:g} mm, "
        f"x = {g1.profile_shift:.4f} / {g2.profile_shift:.4f}"
    )
    print()
    print(pair_report(pair, args.min_contact_ratio, args.min_tip_land, args.friction))
    if args.torque is not None:
        print()
        print(pair.forces(args.torque))
    write_scene(args, lambda tol: pair.scene(tolerance=tol), 0.02,
                lambda _, tol: f"both gears in mesh, tolerance {tol:g} mm")  # fmt: skip
    return OK if ok else CHECK_FAILED
