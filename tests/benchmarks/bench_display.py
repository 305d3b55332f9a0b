"""Benchmark: the notebook displays (issue 21): time and size of ``_repr_svg_`` of gears, pairs,
a bevel pair, a stage and a differential, and of the HTML tables of a Report and a Rating.

Each display is timed as the best of N wall times (``time.perf_counter``), beside a baseline
measured in the same run: the same gear written as :func:`gears.solid.export.to_svg` writes a file
(the outline at the library's default tolerance, 0.001 mm, 6 decimals), which is what a
drawing would cost without the display tolerance. The target is under 20 ms for a gear. Prints
a Markdown table for docs/performance.md, with the machine's load average.

Run: ``python tests/benchmarks/bench_display.py``. Not collected by pytest.
"""

from __future__ import annotations

import os
import time

from gears import BevelPair, Gear, GearPair
from gears.display import svg
from trains import Differential, Planetary


def best_of(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def main() -> None:
    pinion = Gear(12, 3, profile_shift=0.6)
    cases = [
        ("gear z = 12, m = 3, x = 0.6", pinion, 30),
        ("gear z = 80, m = 2", Gear(80, 2), 30),
        ("helical gear z = 40, beta = 20", Gear(40, 2, helix_angle=20), 30),
        ("ring z = 80, m = 2", Gear(80, 2, internal=True), 30),
        ("pair 12/24, m = 3", GearPair(pinion, Gear(24, 3, profile_shift=0.36)), 20),
        ("internal pair 20/80, m = 2",
         GearPair(Gear(20, 2, profile_shift=0.3), Gear(80, 2, internal=True, profile_shift=-0.5)),
         20),
        ("stage 18/45/108 x 3, m = 2", Planetary(18, 45, 108, n_planets=3, module=2), 5),
        ("bevel pair 20/40, m = 3, b = 20", BevelPair(20, 40, module=3, face_width=20), 30),
        ("differential 16/10 x 2, m = 3", Differential(16, 10, module=3, gleason=True), 30),
    ]  # fmt: skip
    print(f"load average before: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    print("| display | `_repr_svg_` | SVG size | baseline: file SVG at 0.001 mm | ratio |")
    print("|---|---|---|---|---|")
    style = {"fill": "none", "stroke": "black"}
    for name, obj, repeat in cases:
        # the outlines are not cached: every call samples and writes the picture again
        t = best_of(obj._repr_svg_, repeat)
        size = len(obj._repr_svg_())
        if isinstance(obj, Gear):

            def file(g=obj) -> str:
                return svg([(g.outline(0.001), style)], declaration=True)

            base = best_of(file, max(3, repeat // 5))
            big = len(file())
            row = (f"{base * 1e3:.1f} ms, {big / 1024:.0f} kB | {base / t:.1f} x the time, "
                   f"{big / size:.0f} x the size")  # fmt: skip
        else:
            row = " | "
        print(f"| {name} | {t * 1e3:.1f} ms | {size / 1024:.1f} kB | {row} |")
    report = GearPair(pinion, Gear(24, 3, profile_shift=0.36)).check()
    t = best_of(report._repr_html_, 200)
    print(f"| `Report._repr_html_` (11 findings) | {t * 1e3:.3f} ms | "
          f"{len(report._repr_html_()) / 1024:.1f} kB | | |")  # fmt: skip
    rating = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30)).rating(200, 1500)
    t = best_of(rating._repr_html_, 50)
    print(f"| `Rating._repr_html_` (20/50, 200 N m) | {t * 1e3:.2f} ms | "
          f"{len(rating._repr_html_()) / 1024:.1f} kB | | |")  # fmt: skip
    print(f"load average after: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")


if __name__ == "__main__":
    main()
