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
