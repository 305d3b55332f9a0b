"""Benchmark: the cycloidal drive beside an open peer, ``cycloidgen`` (issue 28).

Run as ``python tests/benchmarks/bench_cycloidal.py [rounds]`` in an environment where
``cycloidgen`` is installed (``pip install cycloidgen shapely`` into a benchmark environment of
its own, with this repository on ``PYTHONPATH``; it is no dependency of geartrain). Prints, for
the peer's default drive (R 50, pin radius 4, e 1.5, 11 lobes on 12 pins):

* agreement: the largest distance between the two disc curves (both exact formulas, sampled
  densely) and between the sorted pin forces at 10 N m (both take the equal-rigidity sharing);
  the ratio each gives with the pins fixed;
* accuracy at a tolerance of 5 um: each drawn disc's vertex count and its largest deviation from
  the exact curve (measured from 200 000 exact points to the polygon);
* a placed drive without interference: the largest overlap area of the disc and the pins over
  36 crank angles, for each (the peer's disc placed by its own pose law);
* time, best of ``rounds``, interleaved: the disc drawn at 5 um, and the pin forces at one angle;
* non-circular teeth (no open peer cuts them): one gear of the elliptical pair A 40, e 0.2,
  module 2 (40 teeth) cut by the rolled rack at 20 and 5 um, beside the library's own simulated
  rack cutting of a circular 40-tooth gear of module 2 at the same tolerance (the baseline), and
  the transmission error of the cut pair per input angle.

Not a test: pytest does not collect ``bench_*.py``. Results: docs/performance.md.
"""

from __future__ import annotations

import math
import os
import platform
import sys
import time

import numpy as np
import shapely

from gears.noncircular.cycloid import disc_profile
from trains import CycloidalDrive

R, RP, E, LOBES = 50.0, 4.0, 1.5, 11
TOL = 0.005
TORQUE = 10_000.0  # N mm


def _best(fn, rounds):
    best = math.inf
    for _ in range(rounds):
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def _deviation(poly: shapely.Polygon, exact: np.ndarray) -> float:
    return float(shapely.distance(poly.exterior, shapely.points(exact)).max())


def _peer_disc(cp) -> shapely.Polygon:
    """The peer's disc at TOL as a new design would draw it (its sample-count cache cleared)."""
    cp.sample_count_for_chord_tolerance.cache_clear()
    n = cp.sample_count_for_chord_tolerance(R, RP, E, LOBES, TOL)
    return shapely.Polygon(cp.sampled_profile(R, RP, E, LOBES, n).points)


def main(rounds: int = 7) -> None:
    from cycloidgen.core import kinematics as ck
    from cycloidgen.core import profile as cp
    from cycloidgen.core.spec import GearSpec

    print(f"python {platform.python_version()}, numpy {np.__version__}, {os.cpu_count()} cpu, "
          f"load {os.getloadavg()[0]:.2f}")  # fmt: skip
    ours = CycloidalDrive(LOBES + 1, RP, E, R)
    spec = GearSpec()
    assert (spec.pin_circle_radius, spec.pin_radius, spec.eccentricity, spec.lobes) == (
        R, RP, E, LOBES)  # fmt: skip

    # agreement of the exact curves: the same curve, traversed the other way
    t = np.linspace(0.0, 2 * np.pi, 200_000, endpoint=False)
    exact = disc_profile(t * LOBES, LOBES + 1, RP, E, R)
    theirs = cp.disc_profile(t, R, RP, E, LOBES)
    d = shapely.distance(shapely.LineString(np.vstack([theirs, theirs[:1]])),
                         shapely.points(exact[::50])).max()  # fmt: skip
    print(f"disc curves: largest distance {d:.2e} mm")
    f_ours = np.sort(ours.contact_forces(TORQUE, 0.0))
    f_theirs = np.sort(ck.contacts_at(R, RP, E, LOBES, 0.0).forces(TORQUE))
    print(
        f"pin forces at 10 N m: ours max {f_ours.max():.3f} N, cycloidgen max "
        f"{f_theirs.max():.3f} N, largest difference {np.abs(f_ours - f_theirs).max():.2e} N"
    )
    print(f"ratio, pins fixed: ours {ours.ratio} (Willis), cycloidgen {spec.ratio}")

    # accuracy at the same tolerance
    disc = ours.disc_outline(TOL)
    n = cp.sample_count_for_chord_tolerance(R, RP, E, LOBES, TOL)
    peer = shapely.Polygon(cp.sampled_profile(R, RP, E, LOBES, n).points)
    print(
        f"at {TOL * 1000:g} um: ours {len(disc.exterior.coords) - 1} vertices, deviation "
        f"{_deviation(disc, exact) * 1000:.2f} um; cycloidgen {len(peer.exterior.coords) - 1} "
        f"vertices, deviation {_deviation(peer, exact) * 1000:.2f} um"
    )

    # placed without interference
    worst_ours = worst_theirs = 0.0
    for a in np.linspace(0.0, 350.0, 36):
        d_ours, pins = ours.outlines(float(a), TOL)
        worst_ours = max(worst_ours, d_ours.intersection(pins).area)
        placed = shapely.Polygon(ck.to_world(np.asarray(peer.exterior.coords), math.radians(a),
                                             E, LOBES))  # fmt: skip
        worst_theirs = max(worst_theirs, placed.intersection(pins).area)
    print(
        f"largest disc-pin overlap over 36 angles: ours {worst_ours:.2e} mm^2, cycloidgen "
        f"{worst_theirs:.2e} mm^2"
    )

    # time, interleaved
    cp.sample_count_for_chord_tolerance.cache_clear()
    tasks = {
        "disc at 5 um, ours": lambda: ours.disc_outline(TOL),
        "disc at 5 um, cycloidgen": lambda: _peer_disc(cp),
        "pin forces, ours": lambda: ours.contact_forces(TORQUE, 10.0),
        "pin forces, cycloidgen": lambda: ck.contacts_at(R, RP, E, LOBES, 0.1).forces(TORQUE),
    }
    best = dict.fromkeys(tasks, math.inf)
    for _ in range(rounds):
        for name, fn in tasks.items():
            best[name] = min(best[name], _best(fn, 1))
    for name, s in best.items():
        print(f"{name:28s} {s * 1e3:9.3f} ms")
    print(f"load after {os.getloadavg()[0]:.2f}")


def noncircular(rounds: int = 3) -> None:
    from gears import Gear, NonCircularPair

    for tol in (0.02, 0.005):
        best_nc = best_circle = math.inf
        for _ in range(rounds):
            p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
            t0 = time.perf_counter()
            p.outline(1, tol)
            best_nc = min(best_nc, time.perf_counter() - t0)
            t0 = time.perf_counter()
            Gear(40, 2.0).outline(tol, method="rack")
            best_circle = min(best_circle, time.perf_counter() - t0)
        print(
            f"cut at {tol * 1000:g} um: elliptical gear {best_nc:.3f} s, circular gear by "
            f"the rack {best_circle:.3f} s, ratio {best_nc / best_circle:.2f}"
        )
    p = NonCircularPair.elliptical(40.0, 0.2, module=2.0)
    p.outlines(0.0, 0.02)
    angles = np.linspace(0.0, 360.0, 73)
    t0 = time.perf_counter()
    te = p.transmission_error(angles, 0.02)
    s = time.perf_counter() - t0
    arc = np.abs(np.radians(te)) * p.radius2(angles)
    print(
        f"transmission error at 20 um: {s / angles.size * 1e3:.1f} ms an angle, largest "
        f"{arc.max() * 1000:.2f} um of arc"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 7)
    noncircular()
