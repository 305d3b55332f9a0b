"""Biplanetary train
=================

Biplanetary train (Ozols Fig 7-10): ratio and the path of a point on the inner satellite.

Design task: r3 = 60, r2 = 20, rH = 10, r1 = 5 (module 2: teeth 60, 20, 10, 5) gives i_1H = 10;
a point on satellite 1 at 4 mm from its axis draws a looped curve, saved as CSV and drawn
(with matplotlib, the ``plot`` extra).

Writes into the directory given as the first argument (default: a new temporary directory).
"""

import pathlib
import sys
import tempfile

import numpy as np

from trains import biplanetary, point_path

out = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else pathlib.Path(tempfile.mkdtemp())
out.mkdir(parents=True, exist_ok=True)
t = biplanetary(fixed=60, planet=20, inner_sun=10, satellite=5)
i = t.ratio("1", "H", fixed=["3"])
print("i_1H =", i)
assert i == 10
# module 2: each radius in mm equals the tooth count
r = {z: z for z in (60, 20, 10, 5)}
time = np.linspace(0.0, 2 * np.pi, 2001)
angles = t.solve(H=np.ones_like(time), **{"3": 0}).integrate(time)
arms = [("H", r[60] + r[20]), ("2", r[10] + r[5]), ("1", 4.0)]
x, y = point_path(angles, arms)
np.savetxt(out / "biplanetary_path.csv", np.column_stack([x, y]), delimiter=",", header="x,y")
rho = np.hypot(x, y)
print(f"path of {len(x)} points, radius from {rho.min():.2f} to {rho.max():.2f} mm")
assert abs(rho.max() - (80 + 15 + 4)) < 1e-3

try:
    import matplotlib.pyplot as plt
except ImportError:  # the CSV is still written
    pass
else:
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.plot(x, y, lw=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("mm")
    ax.set_title("path of a point on satellite 1 (carrier turns once)")
    fig.savefig(out / "biplanetary_path.png", dpi=100)
print("wrote biplanetary_path.csv and .png")
