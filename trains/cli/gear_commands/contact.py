"""Loaded tooth contact analysis of a gear pair under a torque on gear 1: the transmission error
over one mesh cycle (um along the line of action and arcseconds, peak to peak), the mesh
stiffness and its mean, how the tooth pairs share the load, the largest Hertzian pressure,
and the face and transverse load factors K_Hbeta and K_Halpha taken from the load
distribution. Tip and root relief and crowning (mm, the same on both gears) and a
misalignment across the face (one number, or its parts f_ma and f_sh) enter the analysis;
--internal analyses a ring pair; --best searches the tip relief and crowning of the least peak
to peak at the torque. With --output, a figure is written: the
transmission-error curve, the contact pattern, or the Harris map (peak to peak over tip
relief and torque). The exit status is 1 when the peak to peak exceeds --max-te.

Examples:
    geartrain contact 20 50 --module 3 --face-width 30 --torque 300
    geartrain contact 20 50 -m 3 --face-width 30 --torque 300 --tip-relief 0.015 -o te.png
    geartrain contact 17 103 -m 8 --helix 15.8 --face-width 100 --torque 9000 --misalignment 0.02
    geartrain contact 29 77 -m 2 --internal --face-width 20 --torque 60 --f-ma 0.01 --best
"""

from __future__ import annotations

import argparse

from trains.cli._common import CHECK_FAILED, OK, PAIR_NAMES, output_file, pair_arguments
from trains.cli._types import bounded, integer, non_negative, positive

HELP = "loaded tooth contact: transmission error, mesh stiffness, load sharing, K_Hbeta"

NAMES = {
    **PAIR_NAMES,
    "torque": "--torque",
    "misalignment": "--misalignment",
    "f_ma": "--f-ma",
    "f_sh": "--f-sh",
    "positions": "--positions",
    "slices": "--slices",
    "tip_relief_length": "--relief-length",
    "tip_relief": "--tip-relief",
    "root_relief": "--root-relief",
    "crowning": "--crowning",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""

FIGURES = (".png", ".svg", ".pdf")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pair_arguments(parser, face_width_help="face width in mm (required: the face is cut into "
                   "slices)")  # fmt: skip
    parser.add_argument("--torque", "-T", type=positive("--torque", "N m"), required=True,
                        help="torque on gear 1, N m")  # fmt: skip
    parser.add_argument("--tip-relief", type=non_negative("--tip-relief", "mm"), default=0.0,
                        help="tip relief C_a on both gears, mm")  # fmt: skip
    parser.add_argument("--root-relief", type=non_negative("--root-relief", "mm"), default=0.0,
                        help="root relief C_f on both gears, mm")  # fmt: skip
    parser.add_argument(
        "--relief-length", type=positive("--relief-length", "mm"), default=None,
        help="length of the tip and root relief along the path of contact, mm (default: from "
        "the tip to the nearest point of single contact)",
    )  # fmt: skip
    parser.add_argument("--relief-kind", choices=("linear", "parabolic"), default="linear",
                        help="shape of the reliefs")  # fmt: skip
    parser.add_argument("--crowning", type=non_negative("--crowning", "mm"), default=0.0,
                        help="lead crowning C_b on gear 1, mm")  # fmt: skip
    parser.add_argument("--misalignment", type=bounded("--misalignment", -10, 10), default=0.0,
                        help="mesh misalignment across the face (f_ma + f_sh), mm")  # fmt: skip
    parser.add_argument("--f-ma", type=bounded("--f-ma", -10, 10), default=0.0,
                        help="misalignment from manufacture (ISO 6336-1 f_ma), mm across the "
                        "face; adds to --misalignment")  # fmt: skip
    parser.add_argument("--f-sh", type=bounded("--f-sh", -10, 10), default=0.0,
                        help="misalignment from shaft and bearing deflection at this "
                        "torque (ISO 6336-1 f_sh), mm across the face; adds to "
                        "--misalignment")  # fmt: skip
    parser.add_argument("--best", action="store_true",
                        help="also search the tip relief (both gears) and crowning (gear 1) of "
                        "the least peak to peak at this torque")  # fmt: skip
    parser.add_argument("--positions", type=integer("--positions", 4, 4096), default=64,
                        help="positions over one mesh cycle")  # fmt: skip
    parser.add_argument("--slices", type=integer("--slices", 1, 1000), default=30,
                        help="slices across the face")  # fmt: skip
    parser.add_argument("--max-te", type=positive("--max-te", "um"), default=None,
                        help="fail (exit 1) when the peak-to-peak transmission error exceeds "
                        "this, um")  # fmt: skip
    parser.add_argument("-o", "--output", type=output_file(FIGURES), default=None,
                        help="write a figure (.png, .svg, .pdf)")  # fmt: skip
    parser.add_argument("--figure", choices=("te", "pattern", "harris"), default="te",
                        help="which figure --output writes: the transmission error curve, the "
                        "contact pattern, or the Harris map")  # fmt: skip


def run(args: argparse.Namespace) -> int:
    import numpy as np

    from gears.contact.modification import Modification
    from trains.cli._common import build_pair

    if args.face_width is None:
        from trains.errors import TrainError

        raise TrainError("--face-width is required: the contact analysis divides the face "
                         "width")  # fmt: skip
    pair = build_pair(args)
    kw = {"tip_relief_length": args.relief_length, "root_relief_length": args.relief_length}
    m1 = Modification(tip_relief=args.tip_relief, root_relief=args.root_relief,
                      crowning=args.crowning, kind=args.relief_kind, **kw)  # fmt: skip
    m2 = Modification(tip_relief=args.tip_relief, root_relief=args.root_relief,
                      kind=args.relief_kind, **kw)  # fmt: skip
    g1 = pair.g1.with_(modification=None if m1.is_none else m1)
    g2 = pair.g2.with_(modification=None if m2.is_none else m2)
    pair = type(pair)(g1, g2, pair.tip_shortening)
    tilt = {"misalignment": args.misalignment, "f_ma": args.f_ma, "f_sh": args.f_sh}
    c = pair.contact(args.torque, positions=args.positions, slices=args.slices, **tilt)
    te = c.transmission_error
    arcsec = c.transmission_error_arcsec
    lines = [
        f"loaded tooth contact, T1 = {args.torque:g} N m (F_bt = {c.load:.1f} N), "
        f"{args.positions} positions x {args.slices} slices",
        f"transmission error      {te.min():9.3f} ... {te.max():9.3f} um "
        f"({arcsec.min():.2f} ... {arcsec.max():.2f} arcsec)",
        f"peak to peak            {c.peak_to_peak:9.3f} um ({np.ptp(arcsec):.3f} arcsec)",
        f"unloaded TE, p-p        {np.ptp(c.unloaded_transmission_error):9.3f} um",
        f"mesh stiffness          {c.mesh_stiffness.min():9.3f} ... "
        f"{c.mesh_stiffness.max():.3f} N/(mm um), mean {c.mean_mesh_stiffness:.3f}",
        f"single pair stiffness   {c.single_stiffness:9.3f} N/(mm um) (largest)",
        f"largest pair load       {c.load_sharing.max():9.1f} N of {c.load:.1f} N",
        f"largest Hertz pressure  {c.pressure.max():9.1f} MPa",
        f"K_Hbeta                 {c.K_Hbeta:9.4f}",
        f"K_Halpha                {c.K_Halpha:9.4f}",
    ]
    if args.best:
        s = pair.best_modification(args.torque, relief_length=args.relief_length,
                                   kind=args.relief_kind, **tilt)  # fmt: skip
        lines.append(f"best tip relief         {s.tip_relief * 1000:9.2f} um, crowning "
                     f"{s.crowning * 1000:.2f} um: peak to peak {s.best_peak_to_peak:.3f} um "
                     f"(K_Hbeta {s.K_Hbeta[s.index]:.4f})")  # fmt: skip
    print("\n".join(lines))
    if args.output is not None:
        if args.figure == "harris":
            top = max(2.0 * float(te.max()) / 1000.0, 1e-4)
            fig = pair.harris(np.linspace(0.2, 2.0, 10) * args.torque, np.linspace(0, top, 21),
                              relief_length=args.relief_length, kind=args.relief_kind,
                              positions=min(args.positions, 64)).plot()  # fmt: skip
        else:
            fig = c.plot(args.figure)
        fig.savefig(args.output, dpi=110)
        print(f"wrote {args.output}")
    if args.max_te is not None and c.peak_to_peak > args.max_te:
        print(f"FAIL: peak to peak {c.peak_to_peak:.3f} um > --max-te {args.max_te:g} um")
        return CHECK_FAILED
    return OK
