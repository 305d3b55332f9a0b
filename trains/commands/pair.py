"""Geometry and checks of one meshing pair: every dimension of both gears, the working pressure
angle and centre distance, contact ratios, sliding, efficiency and every check with its margin.

Example: ``geartrain pair 12 24 --module 3 --shift 0.6 0.36``. With ``--center-distance`` the
shifts follow from the centre distance (``GearPair.at_center_distance``, split by ``--split``).
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable

from gears.errors import GearError
from gears.gear import Gear
from gears.pair import GearPair

HELP = "geometry, contact ratios and checks of a gear pair (external, internal, helical)"

SPLITS = ("equal_sliding", "proportional", "keep")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("z1", type=int, help="teeth of gear 1 (the pinion)")
    parser.add_argument("z2", type=int, help="teeth of gear 2 (the ring with --internal)")
    parser.add_argument("--module", "-m", type=float, default=1.0, help="normal module, mm")
    parser.add_argument(
        "--shift", "-x", type=float, nargs=2, default=(0.0, 0.0), metavar=("X1", "X2"),
        help="profile-shift coefficients of gear 1 and gear 2 (default 0 0)",
    )  # fmt: skip
    parser.add_argument("--internal", action="store_true", help="gear 2 is an internal ring")
    parser.add_argument(
        "--helix", type=float, default=0.0, metavar="BETA",
        help="helix angle of gear 1 in degrees (+ right hand); gear 2 gets the mating hand",
    )  # fmt: skip
    parser.add_argument(
        "--pressure-angle", type=float, default=20.0, metavar="ALPHA",
        help="normal pressure angle in degrees (default 20)",
    )  # fmt: skip
    parser.add_argument("--face-width", type=float, default=None, metavar="B", help="mm")
    parser.add_argument(
        "--center-distance", type=float, default=None, metavar="A",
        help="working centre distance in mm: the shifts follow from it (overrides --shift X2)",
    )  # fmt: skip
    parser.add_argument(
        "--split", choices=SPLITS, default="equal_sliding",
        help="how --center-distance divides the shift sum (default equal_sliding; "
        "'keep' keeps X1 of --shift)",
    )  # fmt: skip
    parser.add_argument(
        "--min-contact-ratio", type=float, default=1.1, help="required contact ratio (1.1)"
    )
    parser.add_argument(
        "--min-tip-land", type=float, default=0.2, help="required tip land in modules (0.2)"
    )
    parser.add_argument(
        "--friction", type=float, default=0.1, help="friction coefficient for efficiency (0.1)"
    )


def build_pair(args: argparse.Namespace) -> GearPair:
    """The :class:`GearPair` the arguments describe."""
    x1, x2 = args.shift
    beta = args.helix
    g1 = Gear(args.z1, args.module, args.pressure_angle, beta, x1, args.face_width, internal=False)
    g2 = Gear(
        args.z2, args.module, args.pressure_angle, beta if args.internal else -beta, x2,
        args.face_width, internal=args.internal,
    )  # fmt: skip
    if args.center_distance is not None:
        return GearPair.at_center_distance(g1, g2, args.center_distance, split=args.split)
    return GearPair(g1, g2)


def _value(fn: Callable[[], object], fmt: str = "{:.4f}") -> str:
    """Format ``fn()``; a quantity that does not exist for this gear shows as '-'."""
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
    g1, g2 = pair.gears
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
    pair = build_pair(args)
    kind = "internal" if pair.internal else "external"
    g1, g2 = pair.gears
    print(
        f"gear pair {g1.teeth}/{g2.teeth} ({kind}), m_n = {g1.module:g} mm, "
        f"x = {g1.profile_shift:.4f} / {g2.profile_shift:.4f}"
    )
    print()
    print(pair_report(pair, args.min_contact_ratio, args.min_tip_land, args.friction))
    return 0
