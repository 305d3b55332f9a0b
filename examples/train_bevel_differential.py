"""Bevel differential
==================

Bevel (car) differential with its final drive, cornering (Ozols Fig 7-11, (7.9)).

Design task: wheel and pinion speeds when the inner wheel runs 10 % slower than the case; the
file examples/train_bevel_differential.toml describes the same train for `geartrain train`.
"""

import sys
from pathlib import Path

import numpy as np

from trains import bevel_differential, read_train

t = bevel_differential(side=16, pinion=10, drive=(11, 41))
m = t.solve(input=3000, left=float(3000 * 11 / 41 * 0.9))
print(t.name)
print(f"case {float(m['carrier']):.2f} rpm, left {m['left']:.2f}, right {m['right']:.2f},"
      f" pinions spin {float(m.relative('pinion', 'carrier')):.2f} rpm")  # fmt: skip
assert abs(m["left"] + m["right"] - 2 * m["carrier"]) < 1e-9
toml = read_train(Path(sys.argv[0]).with_name("train_bevel_differential.toml"))
assert toml.solve(carrier=100, left=90)["right"] == 110

# cornering: the wheels' speeds as the inner (left) wheel slows, 3000 rpm in
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    case = 3000 * 11 / 41
    left = np.linspace(0.5, 1.0, 51) * case
    sweep = [t.solve(input=3000, left=float(v)) for v in left]
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for name in ("right", "carrier"):
        ax.plot(left, [float(s[name]) for s in sweep], label=name.replace("carrier", "case"))
    ax.plot(left, [float(s.relative("pinion", "carrier")) for s in sweep], label="pinion in case")
    ax.set_xlabel("left (inner) wheel, rpm")
    ax.set_ylabel("rpm")
    ax.grid(alpha=0.3)
    ax.legend()
    ax.set_title("differential 16/10, final drive 11/41: left + right = 2 case")
    fig.tight_layout()
