"""Ferguson's paradox
==================

Ferguson's paradox (Ozols example 7-3): three gears on one idler, one turning each way.

Design task: show that with a fixed sun of 100 teeth, the satellite of 100 teeth translates, the
one of 101 teeth turns with the carrier and the one of 99 teeth against it.
"""

from trains import ferguson

t = ferguson(sun=100, idler=20, satellites=(99, 100, 101))
m = t.solve(carrier=1, sun=0)
for k in (1, 2, 3):
    print(f"satellite{k}: {m[f'satellite{k}']} turns per carrier turn")
assert m["satellite1"] < 0 and m["satellite2"] == 0 and m["satellite3"] > 0

# the three satellites' turns per carrier turn: one turns back, one stands, one turns forward
try:
    import matplotlib.pyplot as plt
except ImportError:
    pass
else:
    names = [f"satellite{k} ({z} teeth)" for k, z in zip((1, 2, 3), (99, 100, 101), strict=True)]
    turns = [float(m[f"satellite{k}"]) for k in (1, 2, 3)]
    fig, ax = plt.subplots(figsize=(6, 2.8))
    ax.barh(names, turns, color=["tab:red", "0.6", "tab:blue"])
    ax.axvline(0, color="k", lw=0.8)
    ax.invert_yaxis()
    ax.set_xlabel("turns per carrier turn")
    ax.xaxis.set_major_locator(plt.MaxNLocator(5))
    ax.set_title("Ferguson's paradox: sun 100 held, idler 20")
    fig.tight_layout()
