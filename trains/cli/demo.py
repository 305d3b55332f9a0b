"""Run the built-in example design and print its validated report: a profile-shifted spur pair
12/24 (module 3 mm, shifts 0.6 / 0.36) with every check, then a three-planet stage for ratio 7,
synthesized and checked; with --scene, that stage is also written as a 3D scene with real teeth,
its planets phased and instanced. The exit status is 1 when a check fails.

Examples:
    geartrain demo
    geartrain demo --scene stage.glb
"""

# The design is a list of sections (title, function returning the text and whether its checks
# pass), so a later stage is one more entry in SECTIONS.

from __future__ import annotations

import argparse
import functools
from collections.abc import Callable

from trains.cli._common import CHECK_FAILED, OK, SCENE_FORMATS, output_file

HELP = "run the built-in example design (a shifted pair, a planetary stage) and check it"


def shifted_pair() -> tuple[str, bool]:
    """The profile-shifted spur pair 12/24, m = 3 mm, x = 0.6 / 0.36."""
    from gears import Gear, GearPair
    from trains.cli.gear_commands.pair import pair_report

    pair = GearPair(Gear(12, 3.0, profile_shift=0.6), Gear(24, 3.0, profile_shift=0.36))
    return pair_report(pair), pair.check().ok


@functools.cache
def _synthesized():
    """The three-planet stages for ratio 7 (lectures §4.3), m = 2 mm: the best is the demo's."""
    from trains.design.synthesis import synthesize

    return synthesize(7, n_planets=3, module=2.0, limit=3)


def planetary_stage() -> tuple[str, bool]:
    """Design a three-planet stage for ratio 7 (lectures §4.3) and validate it."""
    from trains.cli.train_commands.synthesize import LEGEND

    found = _synthesized()
    stage = found[0].stage
    return "\n".join([found.table(), LEGEND, "", stage.describe()]), stage.check().ok


SECTIONS: list[tuple[str, Callable[[], tuple[str, bool]]]] = [
    ("Profile-shifted spur pair 12/24, m_n = 3 mm, x = 0.6 / 0.36", shifted_pair),
    (
        "Planetary stage for ratio 7, three planets, m = 2 mm (synthesized, then checked)",
        planetary_stage,
    ),
]
"""(title, function returning (report, checks pass)) of each part, printed in order."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--scene", type=output_file(SCENE_FORMATS, "--scene"), default=None, metavar="FILE",
        help="also write the demo's planetary stage as a 3D scene with real teeth, planets "
        f"phased and instanced ({', '.join(SCENE_FORMATS)})",
    )  # fmt: skip


def run(args: argparse.Namespace) -> int:
    ok = True
    for i, (title, section) in enumerate(SECTIONS):
        text, passed = section()
        ok = ok and passed
        if i:
            print()
        print(title)
        print("=" * len(title))
        print(text)
    if args.scene is not None:
        from gears.solid.export import save

        stage = _synthesized()[0].stage
        scene = stage.scene(face_width=10 * stage.module, tolerance=0.05, check=False)
        save(args.scene, scene)
        triangles = sum(len(g.faces) for g in scene.geometry.values())
        print(f"\nwrote {args.scene}: {len(scene.graph.nodes_geometry)} gears, {triangles} "
              f"triangles stored once per distinct gear (planets instanced)")  # fmt: skip
    return OK if ok else CHECK_FAILED
