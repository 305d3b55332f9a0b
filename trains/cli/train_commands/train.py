"""Solve a gear train read from a TOML file (see docs/trains.md for the format): the speed of
every member, the speeds relative to the carriers (planet bearing speeds), the ratios and, with
an output member, the torques, powers, losses and efficiency, and the forces: every mesh force
and every member's bearing load at --torque (N m), when every mesh has real gears or --module
gives the pitch diameters of the meshes given by tooth counts.

Speeds given as integers, decimals or fractions are exact. The file's [run] table supplies a
default for every option; an option given here overrides it.

Examples:
    geartrain train examples/train_closed_differential.toml
    geartrain train examples/train_closed_differential.toml --input 1=880 --output 4
    geartrain train examples/train_simple_planetary.toml --fixed ring --input sun=1500
    geartrain train examples/train_simple_planetary.toml --torque 100 --module 2
"""

from __future__ import annotations

import argparse
from fractions import Fraction
from typing import Any

from trains.cli._common import input_file
from trains.cli._types import bounded, exact, finite, positive

HELP = "solve a gear train from a TOML file (speeds, ratios, torques, efficiency)"

NAMES = {
    r"Train\.link": "a [[link]] table",
    "mesh_efficiency": "--efficiency",
    "input_torque": "--torque",
    "input_speed": "--input",
    "module": "--module",
}
"""The library's names in error messages -> this command's options (see trains.cli.app)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "file", type=input_file("FILE"), metavar="FILE",
        help="train description (TOML; see docs/trains.md)",
    )  # fmt: skip
    parser.add_argument(
        "--fixed", action="append", default=None, metavar="MEMBER",
        help="member held at speed 0 (repeat, or comma-separated; default: the file's [run])",
    )  # fmt: skip
    parser.add_argument(
        "--input", action="append", default=None, metavar="MEMBER=SPEED",
        help="a driving member and its speed (repeat for a differential; default: the file's "
        "[run])",
    )  # fmt: skip
    parser.add_argument(
        "--output", default=None,
        help="driven member, for torques and efficiency (default: the file's [run])",
    )  # fmt: skip
    parser.add_argument(
        "--efficiency", type=bounded("--efficiency", 0, 1, low_open=True), default=None,
        metavar="ETA",
        help="efficiency of every mesh in its carrier frame (default: the file's, else 1)",
    )  # fmt: skip
    parser.add_argument(
        "--torque", type=finite("--torque"), default=1.0, help="input torque, N m (non-zero)"
    )
    parser.add_argument(
        "--module", type=positive("--module", "mm"), default=None,
        help="module of the meshes given by tooth counts, mm: their forces (pitch diameters m z)",
    )  # fmt: skip


def _speed(name: str, text: str) -> Fraction:
    from trains.errors import TrainError

    try:
        return exact(f"{name}: speed", text)
    except ValueError as exc:
        raise TrainError(str(exc)) from None


def _parse_inputs(items: Any) -> dict[str, Fraction]:
    """``--input MEMBER=SPEED`` items (or the file's ``[run] input`` table) as exact speeds."""
    from trains.errors import TrainError

    if isinstance(items, dict):
        return {str(k): _speed(f"[run] input {k}", str(v)) for k, v in items.items()}
    out: dict[str, Fraction] = {}
    for item in items or []:
        name, sep, value = str(item).partition("=")
        if not sep or not name.strip():
            raise TrainError(f"--input must be MEMBER=SPEED, got {item!r}")
        out[name.strip()] = _speed(f"--input {item}", value)
    return out


def _fmt(x: Any) -> str:
    if isinstance(x, Fraction):
        if x.denominator == 1:
            return str(x.numerator)
        return f"{float(x):.10g} (= {x})"
    return f"{float(x):.10g}"


def run(args: argparse.Namespace) -> int:
    from trains.errors import TrainError
    from trains.power import power_flow
    from trains.toml_format import read_train
    from trains.willis import FRAME

    t = read_train(args.file)
    run_defaults = t.run_defaults
    fixed: list[str] = []
    for f in args.fixed if args.fixed is not None else run_defaults.get("fixed", []):
        fixed += [s.strip() for s in str(f).split(",") if s.strip()]
    inputs = _parse_inputs(args.input if args.input is not None else run_defaults.get("input"))
    output = args.output or run_defaults.get("output")
    eta = args.efficiency if args.efficiency is not None else run_defaults.get("mesh_efficiency")
    if not inputs:
        raise TrainError("give at least one --input MEMBER=SPEED (or an input in the file's [run])")

    s = t.structure
    print(t.name or args.file)
    print(
        f"mobility {s.mobility} (Chebyshev {s.chebyshev} with {s.redundant} redundant"
        f" constraint{'s' if s.redundant != 1 else ''}); fixed: {', '.join(fixed) or 'none'}"
    )
    motion = t.solve({**inputs, **{f: 0 for f in fixed if f != FRAME}})
    width = max(len(m) for m in t.members)
    print("\nspeeds")
    for m in t.members:
        print(f"  {m:<{width}s}  {_fmt(motion[m])}")
    bearings = {}
    for r in t.relations:
        if r.kind != "couple" and r.carrier != FRAME:
            for m in (r.a, r.b):
                bearings.setdefault((m, r.carrier), motion.relative(m, r.carrier))
    if bearings:
        print("\nspeeds relative to carriers (bearing speeds)")
        for (m, c), v in bearings.items():
            print(f"  {m} on {c}: {_fmt(v)}")
    first = next(iter(inputs))
    print(f"\nratios i = w_{first} / w_member")
    for m in t.members:
        if m not in (FRAME, first) and motion[m] != 0:
            print(f"  {first}/{m:<{width}s}  {_fmt(motion[first] / motion[m])}")
    if output is None:
        print("\n(no --output: torques and efficiency need the driven member)")
        return _checks(t)
    pf = power_flow(t,
        list(inputs), output, fixed=fixed, mesh_efficiency=1.0 if eta is None else eta,
        input_torque=args.torque if inputs[first] >= 0 else -args.torque,  # input supplies power
        input_speed={k: float(v) for k, v in inputs.items()},
        friction=run_defaults.get("friction"),
    )  # fmt: skip
    print(f"\npower flow: input {', '.join(inputs)} -> output {output}, mesh efficiency "
          f"{1.0 if eta is None else eta}")  # fmt: skip
    print(f"  {'member':<{width}s}  {'torque':>14s}  {'power':>14s}")
    for m in t.members:
        print(f"  {m:<{width}s}  {pf.torques[m]:14.6g}  {pf.powers[m]:14.6g}")
    print(f"  {'relation':<16s} {'driver':>10s} {'power':>12s} {'loss':>12s}")
    for r in pf.relations.values():
        print(f"  {r.name:<16s} {r.driver or '-':>10s} {r.power:12.6g} {r.loss:12.6g}")
    print(f"efficiency {pf.efficiency:.6g}")
    if pf.self_locking:
        print("SELF-LOCKING: the output cannot be driven from this input")
    if pf.circulating_power > 0:
        print(f"circulating power {pf.circulating_power:.6g} (input power {pf.input_power:.6g})")
    _print_loads(t, args, list(inputs), output, fixed, eta, pf)
    return _checks(t)


def _print_loads(t, args, inputs, output, fixed, eta, pf) -> None:
    """Every mesh force and bearing load (trains.loads), or why there are none."""
    from trains.loading import loads

    kinematic = [r.name for r in t.relations if r.kind == "mesh" and r.pair is None]
    if kinematic and args.module is None:
        print(f"\n(forces: give --module for the meshes of tooth counts {', '.join(kinematic)})")
        return
    from trains.errors import TrainError

    try:
        ld = loads(t, inputs, output, fixed, pf.torques[inputs[0]],
                   {k: float(pf.speeds[k]) for k in inputs}, 1.0 if eta is None else eta,
                   t.run_defaults.get("friction"), args.module)  # fmt: skip
    except TrainError as exc:  # the speeds and torques above stand; the forces need geometry
        print(f"\n(no forces: {exc})")
        return
    print(f"\nforces at {pf.torques[inputs[0]]:g} N m on {inputs[0]} (N, N m)")
    print(ld)


def _checks(t) -> int:
    """Print the train's check report (meshes of real gears, coaxiality, planets); 1 if one
    fails. A train of tooth counts only has nothing to check."""
    if t.run_defaults.get("friction") is not None:
        print(f"(meshes of real gears: efficiency from their geometry, friction "
              f"{t.run_defaults['friction']:g}, Ozols (14.25))")  # fmt: skip
    report = t.check()
    if not len(report):
        return 0
    print("\nchecks")
    print(report)
    return 0 if report.ok else 1
