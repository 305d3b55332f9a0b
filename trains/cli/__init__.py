"""Layer 8, command line: the ``geartrain`` program.

``main`` (the console script) and ``build_parser`` live in :mod:`trains.cli.app`; the gear
commands (``pair``, ``profile``, ``mesh``, ``bevel``, ``rate``, ``search``) in
:mod:`trains.cli.gear_commands`, the train commands (``train``, ``planetary``, ``synthesize``,
``differential``) in :mod:`trains.cli.train_commands`, and ``demo``, which reuses both, in
:mod:`trains.cli.demo`. Nothing is imported until it is called, so ``geartrain --help`` does not
load numpy.
"""

from __future__ import annotations

import argparse


def main(argv: list[str] | None = None) -> int:
    """Run ``geartrain`` with ``argv`` (default ``sys.argv[1:]``); see
    :func:`trains.cli.app.main`."""
    from trains.cli.app import main as run

    return run(argv)


def build_parser() -> argparse.ArgumentParser:
    """The ``geartrain`` parser; see :func:`trains.cli.app.build_parser`."""
    from trains.cli.app import build_parser as build

    return build()
