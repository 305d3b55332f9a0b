"""Bevel differential
==================

Bevel (car) differential with its final drive, cornering (Ozols Fig 7-11, (7.9)).

Design task: wheel and pinion speeds when the inner wheel runs 10 % slower than the case; the
file examples/train_bevel_differential.toml describes the same train for `geartrain train`.
"""

import sys
from pathlib import Path

from trains import bevel_differential, read_train

t = bevel_differential(side=16, pinion=10, drive=(11, 41))
m = t.solve(input=3000, left=float(3000 * 11 / 41 * 0.9))
print(t.name)
print(f"case {float(m['carrier']):.2f} rpm, left {m['left']:.2f}, right {m['right']:.2f},"
      f" pinions spin {float(m.relative('pinion', 'carrier')):.2f} rpm")  # fmt: skip
assert abs(m["left"] + m["right"] - 2 * m["carrier"]) < 1e-9
toml = read_train(Path(sys.argv[0]).with_name("train_bevel_differential.toml"))
assert toml.solve(carrier=100, left=90)["right"] == 110
