"""Design search: a gear pair and a two-stage gearbox
==================================================

Search a gear pair for a housing and a two-stage planetary gearbox, locally and on a Dask
cluster.

Task 1: a pair for a = 100 mm, ratio 3.2 +- 1 %, modules 2 / 2.5 / 3, no undercut, a tip land of
at least 0.25 m, a contact ratio of at least 1.3, the least specific sliding. The shift sum of
each tooth pair is solved exactly for a = 100 mm; x1 runs over a grid and x2 takes the rest.
Then the Pareto front of sliding against contact ratio over a free grid of shifts (m = 2.5).

Task 2: a 1:37 gearbox of two planetary stages (simple or stepped, 3 planets, z <= 120) with the
smallest ring.

Both run on the local cores, then again on a LocalCluster started here (the same call with
``client=``), and the answers agree row by row.
"""

import numpy as np

from gears import search
from trains import synthesize_gearbox

LIMITS = {"min_contact_ratio": 1.3, "min_tip_land": 0.25}
HOUSING = dict(ratio=3.2, center_distance=100.0, module=[2, 2.5, 3], teeth=(12, 120),
               shifts=(-0.5, 1.0, 0.05), split="keep", limits=LIMITS, top=5,
               progress=False)  # fmt: skip
FRONT = dict(ratio=3.2, module=2.5, teeth=(14, 60), shifts=(-0.3, 1.0, 0.05), limits=LIMITS,
             objective=("sliding", "-contact_ratio"), top=None, progress=False)  # fmt: skip
GEARBOX = dict(ratio=37, stages=2, schemes=("simple", "stepped"), z_max=120, top=3,
               progress=False)  # fmt: skip


def same_rows(a, b) -> bool:
    """The same rows: integer columns exactly, float columns to 1e-12 relative (chunks of other
    lengths may round the last bit differently)."""
    return a.dtype == b.dtype and all(
        np.allclose(a[n], b[n], rtol=1e-12, atol=1e-12) if a.dtype[n].kind == "f"
        else np.array_equal(a[n], b[n])
        for n in a.dtype.names
    )  # fmt: skip


if __name__ == "__main__":
    pairs = search.pairs(**HOUSING, client=False)
    print(pairs)
    best = pairs.pair(0)  # a GearPair: its own check gives the same margins
    report = best.check(min_contact_ratio=1.3, min_tip_land=0.25)
    assert report.ok and abs(best.center_distance - 100.0) < 1e-9
    print(f"\nbest pair: z {best.g1.teeth}/{best.g2.teeth}, m {best.g1.module:g}, "
          f"x {best.g1.profile_shift:+.4f}/{best.g2.profile_shift:+.4f}, "
          f"a_w {best.center_distance:.4f} mm, eps {best.contact_ratio:.4f}")  # fmt: skip

    front = search.pairs(**FRONT, client=False)
    print(f"\nPareto front, sliding vs contact ratio: {len(front)} of {front.feasible} feasible "
          f"among {front.examined} candidates")  # fmt: skip
    print("\n".join(front.format(("z1", "z2", "x1", "x2", "sliding", "contact_ratio"))
                    .splitlines()[:8]) + "\n...")  # fmt: skip

    try:  # the front over every feasible pair: no pair is both smoother and steadier
        import matplotlib.pyplot as plt
    except ImportError:
        pass
    else:
        every = search.pairs(**{**FRONT, "objective": "sliding"}, client=False)
        fig, ax = plt.subplots(figsize=(6, 4))
        ax.scatter(every["sliding"], every["contact_ratio"], s=4, color="0.7",
                   label=f"{every.feasible} feasible pairs")  # fmt: skip
        ax.plot(front["sliding"], front["contact_ratio"], "o-", color="tab:red", ms=3,
                label=f"Pareto front ({len(front)} pairs)")  # fmt: skip
        ax.set_xlabel("largest specific sliding")
        ax.set_ylabel("transverse contact ratio")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        ax.set_title("3.2:1 pairs, m = 2.5: the least sliding for each contact ratio")
        fig.tight_layout()

    boxes = synthesize_gearbox(**GEARBOX, client=False)
    print("\n" + boxes.table())
    assert all(g.ratio == 37 for g in boxes)

    from dask.distributed import Client, LocalCluster

    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                           dashboard_address=None)  # fmt: skip
    with cluster, Client(cluster) as client:
        remote = search.pairs(**HOUSING, client=client, chunk_size=32)
        remote_front = search.pairs(**FRONT, client=client, chunk_size=4096)
        remote_boxes = synthesize_gearbox(**GEARBOX, client=client)
    assert same_rows(remote.table, pairs.table)
    assert same_rows(remote_front.table, front.table)
    assert [str(g) for g in remote_boxes] == [str(g) for g in boxes]
    print(f"\nLocalCluster (2 workers): the same {len(remote)} pairs ({remote.chunks} chunks), "
          f"the same front and the same {len(remote_boxes)} gearboxes")  # fmt: skip
