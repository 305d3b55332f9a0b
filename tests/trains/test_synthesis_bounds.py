"""Issue 11: synthesize works in fixed-size blocks and refuses oversized requests before work.

Reference values: the unblocked search itself (blocks must not change the answer), and the
size arithmetic stated at each test (n = z_max - z_min + 1 values per gear).
"""

from __future__ import annotations

import pytest

from trains import TrainError, synthesize, synthesize_gearbox
from trains.design import synthesis


def _teeth(found):
    return [(c.teeth, c.n_planets, c.ratio) for c in found]


@pytest.mark.parametrize(
    ("args", "kwargs"),
    [
        ((7, 3), {"limit": 50}),
        ((16, 3), {"scheme": "stepped", "z_max": 120, "limit": 50}),
        ((-3, 3), {"scheme": "double-planet", "z_max": 80, "limit": 50}),
        ((6.2, 3), {"tolerance": 0.01, "allow_shift": True, "z_max": 120, "limit": 30}),
    ],
)
def test_block_size_does_not_change_the_answer(monkeypatch, args, kwargs):
    whole = synthesize(*args, **kwargs)
    seen = []
    monkeypatch.setattr(synthesis, "BLOCK", 997)  # many small blocks
    blocked = synthesize(*args, **kwargs, progress=lambda d, n: seen.append((d, n)))
    assert _teeth(blocked) == _teeth(whole) and len(whole) > 0
    assert blocked.examined == whole.examined and blocked.removed == whole.removed
    assert seen[-1][0] == seen[-1][1] > 1  # progress ran over the blocks


def test_oversized_requests_are_refused_before_work():
    # z 17 ... 10^6: n = 999 984, n^2 = 1.0e12 sets (the 7.28 TiB request of issue 11)
    with pytest.raises(TrainError, match=r"about 1e\+12 tooth-number sets.*lower z_max"):
        synthesize(7, 3, z_max=10**6)
    # stepped, z 17 ... 1000: n^3 = 984^3 = 9.53e8 sets, about 95 s at 1e7 sets/s > 30 s
    with pytest.raises(TrainError, match=r"9\.53e\+08 tooth-number sets, about 95 s.*max_seconds"):
        synthesize(16, 3, scheme="stepped", z_max=1000)
    # the budget is a parameter: 0.001 s refuses even a small stepped search
    with pytest.raises(TrainError, match=r"max_seconds = 0\.001"):
        synthesize(16, 3, scheme="stepped", z_max=120, max_seconds=0.001)
    with pytest.raises(TrainError, match="max_seconds"):
        synthesize(7, 3, max_seconds=-1)
    # the gearbox search passes the refusal on instead of dropping the scheme
    with pytest.raises(TrainError, match="tooth-number sets"):
        synthesize_gearbox(37, 2, schemes="stepped", z_max=1000, progress=False)
