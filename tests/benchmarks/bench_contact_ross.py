"""Comparison: single-tooth stiffness against ROSS's potential-energy implementation.

Run as ``ROSS_PYTHON=/path/to/python python tests/benchmarks/bench_contact_ross.py``, where
``ROSS_PYTHON`` is the interpreter of a separate environment holding the peer,
``pip install ross-rotordynamics "plotly<6"`` (its version 3.1 imports a plotly trace that
plotly 6 removed); it is no dependency of geartrain. Prints, for spur teeth of module 2 mm, face
width 20 mm and a bore of 35 mm (ROSS's documented example), at seven points of the flank from
the start of the involute to the tip, the stiffness of one tooth along the line of action
(bending, shear, axial compression and the fillet foundation of Sainsot et al. 2004, no Hertz)
by ``gears.contact.compliance.tooth_compliance`` and by ROSS's
``GearElementTVMS._compute_stiffness`` (Ma et al. 2014), and their ratio.

The two are independent implementations of the same energy method with two differences of
model: ROSS integrates the trochoid fillet of the rack's tip round down to the root circle
(geartrain: the involute, or the base circle's thickness below it, as Chen and Shao 2011), and
takes Sainsot's u_f from the contact point's height (geartrain: from where the load line
crosses the centre line, as Sainsot et al. define it). Not a test: pytest does not collect
``bench_*.py``. Results: docs/contact.md.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import numpy as np

from gears import Gear
from gears.contact.compliance import tooth_compliance

CASES = [(20, 2.0, 20.0, 35.0), (40, 2.0, 20.0, 35.0), (62, 2.0, 20.0, 70.0)]

PEER = r"""
import json, sys, warnings
import numpy as np
warnings.simplefilter("ignore")
from ross.materials import steel
from ross.gear_element import GearElementTVMS
out = []
for z, m, b, bore in json.loads(sys.argv[1]):
    g = GearElementTVMS(n=0, material=steel, width=b / 1000, bore_diameter=bore / 1000,
                        module=m / 1000, n_teeth=z, pr_angle=np.radians(20))
    angles = np.linspace(g.pr_angles_dict["start_point"], g.pr_angles_dict["addendum"], 7)
    k = [float(g._compute_stiffness(a)) for a in angles]
    out.append({"angles": angles.tolist(), "k": k, "E": float(steel.E),
                "nu": float(steel.Poisson)})
print("RESULT " + json.dumps(out))
"""


def peer(cases):
    python = os.environ.get("ROSS_PYTHON")
    if not python:
        return None
    run = subprocess.run([python, "-c", PEER, json.dumps(cases)], capture_output=True, text=True,
                         timeout=600, check=True)  # fmt: skip
    line = [ln for ln in run.stdout.splitlines() if ln.startswith("RESULT ")][-1]
    return json.loads(line[len("RESULT ") :])


def ours(z, m, b, bore, angles, modulus, poisson):
    """One tooth's stiffness along the line of action, N/m, at the pressure angles given."""
    g = Gear(z, m)
    rb = g.base_diameter / 2
    c = tooth_compliance(np.tan(angles), rb, g.base_thickness / g.base_diameter,
                         g.root_diameter / 2, bore / 2, poisson)  # fmt: skip
    return modulus * 1e-6 * b / sum(c.values()) * 1000.0  # E in MPa, N/mm -> N/m


if __name__ == "__main__":
    theirs = peer(CASES)
    if theirs is None:
        sys.exit("set ROSS_PYTHON to a Python with ross-rotordynamics (see the docstring)")
    for (z, m, b, bore), r in zip(CASES, theirs, strict=True):
        angles = np.asarray(r["angles"])
        k = ours(z, m, b, bore, angles, r["E"], r["nu"])
        print(f"z = {z}, m = {m:g} mm, b = {b:g} mm, bore {bore:g} mm "
              f"(E = {r['E'] / 1e9:g} GPa, nu = {r['nu']:g})")  # fmt: skip
        for a, ko, kr in zip(angles, k, r["k"], strict=True):
            print(f"  alpha_y {math.degrees(a):6.2f} deg: geartrain {ko / 1e6:8.1f} N/um, "
                  f"ROSS {kr / 1e6:8.1f} N/um, ratio {ko / kr:.3f}")  # fmt: skip
