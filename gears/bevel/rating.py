"""Layer 3, bevel gears' load capacity through their virtual cylindrical gears (after ISO 10300
method B1; the formulas as math: docs/bevel.md, "Load capacity").

ISO 10300 rates a bevel pair on its virtual cylindrical gears at the mean cone
(``BevelPair.virtual_pair``: z_v = z / cos delta, d_v = d_m / cos delta, the mean module) with
the formulas of ISO 6336. :func:`bevel_rating` does this:

* the tangential force at the mean cone, F_mt = 2000 T_1 / d_m1, and the pitch-line speed v_mt
  are the bevel pair's: the virtual pinion carries T_v1 = T_1 / cos delta_1 at
  n_v1 = n_1 cos delta_1;
* the load cycles are the real gears' (60 n L per contact), so Z_NT and Y_NT are taken at them
  (:mod:`gears.rating.life`), not at the virtual speeds;
* the face load factor K_Hbeta = K_Fbeta = 1.5 K_Hbeta-be with the mounting factor K_Hbeta-be
  (:data:`MOUNTING_FACTORS`: 1.00 with both members straddle-mounted, 1.10 one, 1.25 neither)
  for a contact pattern checked under load (ISO 10300-1), unless given;
* the contact stress carries the bevel gear factor Z_K = 0.85 (ISO 10300-2, method B1):
  sigma_H = Z_K sigma_H,v, so S_H = S_H,v / Z_K.

What is ISO 6336's and not ISO 10300's here: the virtual gears' zone, contact-ratio and helix
factors (ISO 10300-2's mid-zone factor Z_M-B and load-sharing factor Z_LS are not computed), K_v
by ISO 6336-1 on the virtual pair, and the root stress of ISO 6336-3 on the virtual gears (ISO
10300-3's own bending factors are not applied). Straight bevel gears only (the only kind
geartrain builds); a crown or internal bevel wheel is not rated.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from gears.errors import GearError
from gears.rating.life import bending_life_factor, pitting_life_factor
from gears.rating.materials import material as as_material

__all__ = ["BEVEL_FACTOR", "MOUNTING_FACTORS", "bevel_rating"]

#: Bevel gear factor Z_K of the contact stress (ISO 10300-2, method B1).
BEVEL_FACTOR = 0.85
#: Mounting factor K_Hbeta-be by how many members are straddle-mounted (ISO 10300-1).
MOUNTING_FACTORS = {"both-straddle": 1.00, "one-straddle": 1.10, "neither-straddle": 1.25}


def bevel_rating(pair: Any, torque: float, speed: float, material: Any = "case-carburized", *,
                 life: float = 20000.0, mounting: str = "both-straddle",
                 contacts: tuple[int, int] = (1, 1), **options: Any):  # fmt: skip
    """The rating of a straight bevel ``pair`` (a :class:`gears.BevelPair`) under ``torque`` N m
    on its pinion at ``speed`` rpm, through its virtual cylindrical pair (module docstring).

    ``options`` go to :meth:`gears.GearPair.rating` of the virtual pair (``quality``,
    ``roughness``, ``oil_viscosity``, ``idler``, factors by symbol such as ``K_v=1.0``;
    ``K_Hbeta`` given replaces the mounting factor's). Returns a :class:`gears.Rating` whose
    ``pair`` is the virtual pair, with ``S_H``, ``sigma_H`` and ``Z_B`` / ``Z_D`` (as
    ``Z_B Z_K``) carrying Z_K, and ``settings`` naming the bevel pair's torque and speed.
    """
    if mounting not in MOUNTING_FACTORS:
        raise GearError(f"mounting = {mounting!r}; valid are {', '.join(MOUNTING_FACTORS)}")
    for name, value in (("torque", torque), ("speed", speed), ("life", life)):
        if (isinstance(value, bool) or not isinstance(value, int | float)
                or not (math.isfinite(value) and value > 0)):  # fmt: skip
            raise GearError(f"{name} = {value!r}; valid is a finite number > 0")
    for key in ("Z_NT", "Y_NT", "face_width", "spectrum"):
        if key in options:
            raise GearError(f"{key} is set by the bevel rating; it cannot be given")
    delta1, delta2 = pair.pitch_angles
    if not (delta1 < 90.0 and delta2 < 90.0):
        raise GearError(
            f"pitch angles {delta1:.4g} / {delta2:.4g} deg: a crown or internal bevel wheel "
            "(delta >= 90 deg) is not rated"
        )
    vp = pair.virtual_pair
    c1 = math.cos(math.radians(delta1))
    mats = material if isinstance(material, tuple | list) else (material, material)
    if len(mats) != 2:
        raise GearError(f"material = {material!r}; give one material or a pair")
    m1, m2 = (as_material(m) for m in mats)
    if not (isinstance(contacts, tuple | list) and len(contacts) == 2):
        raise GearError(f"contacts = {contacts!r}; valid is a pair of integers >= 1")
    # the real load cycles, on the real speeds (the virtual pinion turns at n cos delta_1)
    n_l1 = 60.0 * life * speed * contacts[0]
    n_l2 = 60.0 * life * speed * pair.z1 / pair.z2 * contacts[1]
    factors = {
        "Z_NT": tuple(float(pitting_life_factor(n, m.kind)) for n, m in ((n_l1, m1), (n_l2, m2))),
        "Y_NT": tuple(float(bending_life_factor(n, m.kind)) for n, m in ((n_l1, m1), (n_l2, m2))),
    }
    k_beta = 1.5 * MOUNTING_FACTORS[mounting]
    options.setdefault("K_Hbeta", k_beta)
    options.setdefault("K_Fbeta", options["K_Hbeta"])
    r = vp.rating(torque / c1, speed * c1, (m1, m2), life=life, face_width=pair.face_width,
                  contacts=tuple(contacts), **factors, **options)  # fmt: skip
    v = r.values
    values = v._replace(
        S_H1=v.S_H1 / BEVEL_FACTOR, S_H2=v.S_H2 / BEVEL_FACTOR,
        sigma_H0=v.sigma_H0 * BEVEL_FACTOR, sigma_H1=v.sigma_H1 * BEVEL_FACTOR,
        sigma_H2=v.sigma_H2 * BEVEL_FACTOR, Z_B=v.Z_B * BEVEL_FACTOR, Z_D=v.Z_D * BEVEL_FACTOR,
        N_L1=np.float64(n_l1), N_L2=np.float64(n_l2),
    )  # fmt: skip
    settings = {**r.settings, "torque": float(torque), "speed": float(speed),
                "bevel": f"ISO 10300 (virtual cylindrical gears, Z_K = {BEVEL_FACTOR}, "
                         f"K_Hbeta-be = {MOUNTING_FACTORS[mounting]:g}, {mounting})"}  # fmt: skip
    return type(r)(r.pair, values, settings, r.roots)
