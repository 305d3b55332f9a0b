"""Benchmark: ISO 6336 rating of one pair and of 10^6 pairs (issue 18).

Run as ``python tests/benchmarks/bench_rating.py [n] [rounds]``. Prints

* the time to rate one pair (19/61, m 3, b 30, 150 N m at 1450 rpm, case-carburized, 20 000 h):
  ``GearPair.rating`` (the whole call: every factor, the Rating view; the pair's
  load-independent part cleared before each call, as for a new pair), the same pair rated again
  at other torques (that part kept) and ``gears.rate_pairs`` for the one pair (geometry
  included), beside python-gearbox's ISO pitting and bending rating of the same pair where that
  package is installed (``pip install python-gearbox`` into a benchmark environment; it is no
  dependency of geartrain), timed in the same rounds, and the ratio;
* rated pairs per second for ``n`` random external helical pairs (z 14 ... 40 / 40 ... 120,
  m 1 ... 8, x 0 ... 0.5 / -0.2 ... 0.3, beta 15 deg, b 10 m, T 10 ... 500 m^2 N m, 1500 rpm)
  through ``rate_pairs``: the four safeties only (what a search needs) and every field, on 1 and
  2 threads, beside ``pair_geometry`` of the same pairs as the baseline (its unloaded figure is
  in docs/performance.md), interleaved round by round so that a shared machine's load falls on
  each alike.

``python tests/benchmarks/bench_rating.py --tree PATH [--rounds R]`` times the one-pair routes
only, of this source tree and of the tree at PATH (e.g. ``git archive`` of an older commit:
before/after), each round a fresh process of each in turn, so that both see the same machine
load; best per route, the ratios after/before and ``uptime``'s load at the start and the end.
The routes: a first rating, the same pair at other torques through ``GearPair.rating`` and,
where the tree has it, through ``Rating.at``.

Not a test: pytest does not collect ``bench_*.py``. Results: docs/performance.md.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import platform
import subprocess
import sys
import time

import numpy as np

from gears import Gear, GearPair, pair_geometry, rate_pairs

T1, N1 = 150.0, 1450.0
SAFETIES = ("S_H1", "S_H2", "S_F1", "S_F2")


def our_pair():
    """A first rating of the pair: the load-independent part is not kept from the last call."""
    from gears.rating import iso6336

    pair = GearPair(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30))

    def run():
        for kept in (iso6336._GEARS, iso6336._ARGUMENTS, iso6336._GEOMETRY):
            kept.clear()  # as if the pair were new
        return pair.rating(T1, N1)

    return run


def our_pair_loads():
    """The same pair rated again at other torques (a load spectrum, a torque sweep)."""
    pair = GearPair(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30))
    torques = iter(np.tile(np.linspace(50.0, 300.0, 97), 10**5))
    return lambda: pair.rating(float(next(torques)), N1)


def our_rating_at():
    """The same pair at other torques through ``Rating.at`` (None where the tree lacks it)."""
    pair = GearPair(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30))
    first = pair.rating(T1, N1)
    if not hasattr(first, "at"):
        return None
    torques = iter(np.tile(np.linspace(50.0, 300.0, 97), 10**5))
    return lambda: first.at(float(next(torques)))


def our_vectorised():
    from gears.rating import iso6336

    def run():
        for kept in (iso6336._GEARS, iso6336._ARGUMENTS, iso6336._GEOMETRY):
            kept.clear()
        return rate_pairs(19, 61, 3, 30, T1, N1)

    return run


def gearbox_pair():
    """python-gearbox's ISO 6336 pitting and bending of the same pair, or None (not installed).

    Its Z_W needs a Brinell hardness between 130 and 470 (it fails outside, a bug of the
    package), so the case-hardened flank is given 400 HB; its results differ from ours (it takes
    Z_eps of a helical gear for a spur gear, among others), the timing compares the work."""
    try:
        from gearbox.standards.iso import Bending, Pitting
        from gearbox.transmition.gears import Gear as GbGear
        from gearbox.transmition.gears import Lubricant, Material, Tool, Transmition
    except ImportError:
        return None
    lub = Lubricant(name="VG220", v40=220)
    mat = Material(name="16MnCr5", classification="Eh", sh_limit=1500.0, sf_limit=500.0,
                   e=206000.0, poisson=0.3, density=7.83e-6, brinell=400.0)  # fmt: skip
    tool = Tool(ha_p=1, hf_p=1.25, rho_fp=0.38, x=0, rho_ao=0, delta_ao=0, nc=10.0)

    def gear(z):
        return GbGear(profile=tool, material=mat, z=float(z), beta=0.0, alpha=20.0, m=3.0, x=0.0,
                      b=30.0, bs=30.0, sr=0.0, rz=6.0, precision_grade=6.0, shaft_diameter=40.0,
                      schema=3.0, l=60.0, s=15.0, backlash=0.0)  # fmt: skip

    power = T1 * N1 * 2 * math.pi / 60 / 1000  # kW

    def run():
        t = Transmition(gears=[gear(19), gear(61)], lubricant=lub, rpm_in=N1,
                        rpm_out=N1 * 19 / 61, n=power, l=20000.0, gear_box_type=2, ka=1.0,
                        sh_min=1, sf_min=1)  # fmt: skip
        return Pitting(transmition=t).calculate(), Bending(transmition=t).calculate

    return run


def per_call(fn, calls: int) -> float:
    t0 = time.perf_counter()
    for _ in range(calls):
        fn()
    return (time.perf_counter() - t0) / calls


def single(rounds: int = 7, calls: int = 200) -> dict[str, float]:
    """Best seconds per call of each route, the routes interleaved round by round."""
    routes = {
        "GearPair.rating": our_pair(),
        "GearPair.rating, other T": our_pair_loads(),
        "rate_pairs (1 pair)": our_vectorised(),
    }
    at = our_rating_at()
    if at is not None:
        routes["Rating.at, other T"] = at
    peer = gearbox_pair()
    if peer is not None:
        routes["python-gearbox ISO"] = peer
    for fn in routes.values():
        fn()  # warm up (imports, caches)
    best = dict.fromkeys(routes, math.inf)
    for _ in range(rounds):
        for name, fn in routes.items():
            best[name] = min(best[name], per_call(fn, calls))
    return best


def random_pairs(n: int, seed: int = 1):
    rng = np.random.default_rng(seed)
    z1 = rng.integers(14, 41, n)
    z2 = rng.integers(40, 121, n)
    m = rng.uniform(1.0, 8.0, n)
    x1 = rng.uniform(0.0, 0.5, n)
    x2 = rng.uniform(-0.2, 0.3, n)
    torque = rng.uniform(10.0, 500.0, n) * m * m
    return z1, z2, m, x1, x2, torque


def many(n: int = 1_000_000, rounds: int = 3) -> dict[tuple[str, int], float]:
    """Best rated pairs per second: (fields, threads) -> pairs/s."""
    z1, z2, m, x1, x2, torque = random_pairs(n)

    def run(fields, threads):
        r = rate_pairs(z1, z2, m, 10 * m, torque, 1500.0, x1=x1, x2=x2, helix_angle=15.0,
                       errors="mask", fields=fields, threads=threads)  # fmt: skip
        assert r.valid.mean() > 0.99 and np.isfinite(r.S_H1).all()
        return r

    cases = [(f, k) for f in ("safeties", "all", "pair_geometry") for k in (1, 2)]
    best = dict.fromkeys(cases, 0.0)
    for _ in range(rounds):
        for f, k in cases:
            t0 = time.perf_counter()
            if f == "pair_geometry":  # the baseline: the geometry alone, same pairs, same round
                pair_geometry(z1, z2, m, x1, x2, 20.0, 15.0, threads=k)
            else:
                run(SAFETIES if f == "safeties" else None, k)
            best[(f, k)] = max(best[(f, k)], n / (time.perf_counter() - t0))
    return best


def before_after(tree: str, rounds: int) -> None:
    """The one-pair routes of this tree and of ``tree``, a fresh process each in turn."""
    here = str(pathlib.Path(__file__).resolve().parents[2])
    trees = {"after": here, "before": str(pathlib.Path(tree).resolve())}
    best: dict[str, dict[str, float]] = {k: {} for k in trees}
    extra = [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]
    load0 = os.getloadavg()
    for _ in range(rounds):
        for name, path in trees.items():
            # the tree first; the rest of the path stays (python-gearbox's environment)
            env = dict(os.environ, PYTHONPATH=os.pathsep.join([path, *extra]))
            out = subprocess.run([sys.executable, __file__, "--worker"], env=env, check=True,
                                 capture_output=True, text=True).stdout  # fmt: skip
            for route, sec in json.loads(out.splitlines()[-1]).items():
                best[name][route] = min(best[name].get(route, math.inf), sec)
    load1 = os.getloadavg()
    print(f"load average {load0[0]:.2f} {load0[1]:.2f} {load0[2]:.2f} at the start, "
          f"{load1[0]:.2f} {load1[1]:.2f} {load1[2]:.2f} at the end (uptime)")  # fmt: skip
    peer = best["after"].get("python-gearbox ISO")
    for route in best["after"]:
        after, before = best["after"][route], best["before"].get(route)
        line = f"{route:26s} after {after * 1e3:7.3f} ms"
        if before is not None:
            line += f"  before {before * 1e3:7.3f} ms  after/before {after / before:5.2f}"
        if peer:
            line += f"  / python-gearbox {after / peer:5.2f}"
        print(line)


if __name__ == "__main__":
    if "--worker" in sys.argv:  # one round of the one-pair routes, as JSON (before_after)
        print(json.dumps(single(rounds=3, calls=200)))
        sys.exit()
    if "--tree" in sys.argv:
        i = sys.argv.index("--tree")
        r = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 5
        before_after(sys.argv[i + 1], r)
        sys.exit()
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1_000_000
    rounds = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    load = os.getloadavg()
    print(f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}, numpy {np.__version__}; load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f} (uptime)")  # fmt: skip
    one = single()
    for name, s in one.items():
        print(f"one pair, {name:22s} {s * 1e3:8.3f} ms")
    if "python-gearbox ISO" in one:
        ratio = one["GearPair.rating"] / one["python-gearbox ISO"]
        print(f"GearPair.rating / python-gearbox: {ratio:.2f}")
    rates = many(n, rounds)
    for (fields, threads), rate in rates.items():
        print(f"{n} pairs, {fields:13s} {threads} thread(s): {rate:12.4g} pairs/s")
    for k in (1, 2):
        ratio = rates[("pair_geometry", k)] / rates[("safeties", k)]
        print(f"rating (safeties) costs {ratio:.1f} x pair_geometry on {k} thread(s)")
    load = os.getloadavg()
    print(f"load average at the end {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
