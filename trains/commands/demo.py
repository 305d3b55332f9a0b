"""Run the built-in default design and print its report, section by section.

The design is a list of sections (title, function returning the text), so a later stage (a
planetary set, its train) is one more entry in :data:`SECTIONS`.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

from gears.gear import Gear
from gears.pair import GearPair
from trains.commands.pair import pair_report

HELP = "run the built-in default design (a profile-shifted pair) and print its report"


def shifted_pair() -> str:
    """The profile-shifted spur pair 12/24, m = 3 mm, x = 0.6 / 0.36."""
    pair = GearPair(Gear(12, 3.0, profile_shift=0.6), Gear(24, 3.0, profile_shift=0.36))
    return pair_report(pair)


def planetary_stage() -> str:
    """Design a three-planet stage for ratio 7 (lectures §4.3) and validate it."""
    from trains.synthesis import synthesize

    found = synthesize(7, n_planets=3, module=2.0, limit=3)
    return "\n".join([found.table(), "", found[0].stage.describe()])


SECTIONS: list[tuple[str, Callable[[], str]]] = [
    ("Profile-shifted spur pair 12/24, m_n = 3 mm, x = 0.6 / 0.36", shifted_pair),
    (
        "Planetary stage for ratio 7, three planets, m = 2 mm (synthesized, then checked)",
        planetary_stage,
    ),
]
"""(title, report function) of each part of the default design, printed in order."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """No options yet."""


def run(args: argparse.Namespace) -> int:
    for i, (title, section) in enumerate(SECTIONS):
        if i:
            print()
        print(title)
        print("=" * len(title))
        print(section())
    return 0
