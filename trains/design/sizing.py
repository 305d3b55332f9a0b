"""Layer 6, design: planetary stages sized for a load, over arrays (issue 20).

:func:`size_stages` gives many zero-shift stages of one scheme (ring fixed, sun in, carrier
out), each with its own input torque and speed, the smallest module of a list that carries the
load and, at that module, the smallest face width of a set: every mesh is rated by
:func:`gears.rating.sizing.rate` (ISO 6336 method B, vectorised) exactly as
:meth:`trains.Planetary.rating` rates it (with ``root="standard"``):

* the torque on a mesh's gear 1 (its external gear) per planet and its speed relative to the
  carrier follow from the lossless power flow of the stage (:func:`stage_meshes`; the sun
  carries T/k per planet, a planet T/k z2/z1, the outer planet of a double-planet stage
  T/k z2'/z1), held to :func:`trains.power_flow` by the tests;
* a central gear meets one planet per planet pass (``contacts``), a planet loaded on both
  flanks is an idler (Y_M), K_gamma is :func:`trains.load_sharing` of the planet count;
* a ring whose tip reaches the planet's fillet is relieved as :class:`trains.Planetary`
  relieves it (``ring_tip_relief``: the tip circle enlarged to the limit, rounded up to 1 um).

With its module and face width, :func:`stage_efficiency` gives the stage's efficiency from its
meshes at the load (ISO/TR 14179-2 per mesh, combined by Ozols (14.26)); :func:`size_stages`
returns it for every stage it sizes.

The stage's volume counts the sun, ``k`` planets (both gears of a stepped planet) and the ring
(:func:`gears.rating.sizing.gear_volume`: pitch cylinders, a ring's annulus out to its rim).
"""

from __future__ import annotations

import numpy as np

from gears.rack import BasicRack
from gears.rating.losses import pair_losses
from gears.rating.sizing import Load, gear_volume, rate
from trains.capacity import LOAD_SHARING
from trains.planetary.checks import ring_tip_alteration
from trains.planetary.schemes import canonical_scheme
from trains.power import planetary_efficiency

__all__ = [
    "MODULE_WINDOW",
    "ring_tip_alteration",
    "size_stages",
    "stage_efficiency",
    "stage_gears",
    "stage_meshes",
]

#: modules rated at once for the stages still without one (the first that carries a stage is
#: its module: most stages find it within the first window)
MODULE_WINDOW = 4


def _planet_idler(scheme: str, z2, z2p) -> np.ndarray:
    """A two-gear planet whose gears are alike (z2 = z2') is one gear loaded on both flanks, as
    :func:`trains.rating` finds it (the gears compare equal)."""
    if scheme == "simple":
        return np.ones(np.shape(z2), bool)
    return np.asarray(z2) == np.asarray(z2p)


def stage_meshes(scheme: str, z1, z2, z2p, z3, n_planets, num, den) -> list[dict]:
    """The meshes of stages (ring fixed, sun in, carrier out; arrays broadcast) as dicts:
    ``name``, ``z1``, ``z2`` (gear 1 is the mesh's external gear), ``internal``,
    ``torque`` (torque on gear 1 per planet over the stage's input torque), ``speed`` (gear
    1's speed relative to the carrier over the input speed), ``contacts``, ``idler``.

    The stage ratio is ``num/den`` (w_sun / w_carrier); the sun turns at ``(i - 1)/i`` of the
    input relative to the carrier, a planet meshing it at that times z1/z2 (lossless: the
    torques follow the speeds).

    >>> [m["name"] for m in stage_meshes("double-planet", 20, 15, 16, 80, 3, 5, 1)]
    ['sun-planet', 'planet-planet2', 'planet2-ring']
    """
    scheme = canonical_scheme(scheme)
    z1, z2, z2p, z3, k = (np.asarray(v, float) for v in (z1, z2, z2p, z3, n_planets))
    rel = (np.asarray(num, float) - np.asarray(den, float)) / np.asarray(num, float)
    one = np.ones(np.broadcast_shapes(z1.shape, z2.shape, z3.shape, k.shape, rel.shape))
    idle = _planet_idler(scheme, z2, z2p)
    planet_t, planet_n = z2 / z1 / k, rel * z1 / z2
    if scheme == "simple":
        return [
            dict(name="sun-planet", z1=z1, z2=z2, internal=False, torque=1 / k, speed=rel,
                 contacts=(k, one), idler=(False, idle)),
            dict(name="planet-ring", z1=z2, z2=z3, internal=True, torque=planet_t,
                 speed=planet_n, contacts=(one, k), idler=(idle, False)),
        ]  # fmt: skip
    if scheme in ("stepped", "external"):
        return [
            dict(name="sun-planet", z1=z1, z2=z2, internal=False, torque=1 / k, speed=rel,
                 contacts=(k, one), idler=(False, idle)),
            dict(name="planet-ring", z1=z2p, z2=z3, internal=scheme == "stepped",
                 torque=planet_t, speed=planet_n, contacts=(one, k), idler=(idle, False)),
        ]  # fmt: skip
    if scheme == "internal":  # the sun is a ring: gear 1 of both meshes is a planet gear
        return [
            dict(name="sun-planet", z1=z2, z2=z1, internal=True, torque=planet_t,
                 speed=planet_n, contacts=(one, k), idler=(idle, False)),
            dict(name="planet-ring", z1=z2p, z2=z3, internal=True, torque=planet_t,
                 speed=planet_n, contacts=(one, k), idler=(idle, False)),
        ]  # fmt: skip
    return [  # double-planet: sun - planet - planet2 - ring, both planets idlers
        dict(name="sun-planet", z1=z1, z2=z2, internal=False, torque=1 / k, speed=rel,
             contacts=(k, one), idler=(False, True)),
        dict(name="planet-planet2", z1=z2, z2=z2p, internal=False, torque=planet_t,
             speed=planet_n, contacts=(one, one), idler=(True, True)),
        dict(name="planet2-ring", z1=z2p, z2=z3, internal=True, torque=z2p / z1 / k,
             speed=rel * z1 / z2p, contacts=(one, k), idler=(True, False)),
    ]  # fmt: skip


def stage_gears(scheme: str, z1, z2, z2p, z3, n_planets) -> list[tuple]:
    """``(teeth, internal, copies)`` of every gear of stages: the sun, each planet gear
    (``n_planets`` copies), the ring."""
    scheme = canonical_scheme(scheme)
    k = np.asarray(n_planets, float)
    if scheme == "simple":
        return [(z1, False, 1.0), (z2, False, k), (z3, True, 1.0)]
    return [(z1, scheme == "internal", 1.0), (z2, False, k), (z2p, False, k),
            (z3, scheme in ("simple", "stepped", "internal", "double-planet"), 1.0)]  # fmt: skip


def size_stages(load: Load, scheme: str, z1, z2, z2p, z3, n_planets, num, den, torque, speed,
                modules, widths, load_sharing=None, rack: BasicRack | None = None,
                block: int = 1 << 16) -> dict:  # fmt: skip
    """The smallest module of ``modules`` (ascending) at which each stage carries its input
    ``torque`` (N m on the sun) at ``speed`` (rpm), and the smallest face width of ``widths``
    at that module: every mesh of the stage meets the load's minimum safeties. Each rating
    call takes at most ``block`` (stage, module, width) rows (about ``block`` x 8 bytes a
    temporary: a Dask worker, which returns every larger one to the system at once, runs
    faster on 8192).

    Returns a dict of arrays of the inputs' broadcast shape: ``module_index`` and
    ``width_index`` (-1 where no module of the list carries it), ``module``, ``face_width``
    (mm), ``S_H``, ``S_F`` (the smallest safety of any gear of any mesh), ``volume`` (mm^3),
    ``mass`` (kg), ``ring`` (the ring's reference diameter, mm) and ``efficiency`` (the
    stage's, :func:`stage_efficiency` at its module and face width); NaN-free (0 where it does
    not carry).
    """
    scheme = canonical_scheme(scheme)
    rack = rack or BasicRack.iso53()
    arrays = np.broadcast_arrays(
        *(np.asarray(v) for v in (z1, z2, z2p, z3, n_planets, num, den, torque, speed))
    )
    shape = arrays[0].shape
    z1, z2, z2p, z3, k, num, den, torque, speed = (a.ravel() for a in arrays)
    modules = np.asarray(modules, float)
    widths = np.asarray(widths, float)
    n = z1.size
    if load_sharing is None:
        k_gamma = np.vectorize(lambda c: LOAD_SHARING.get(int(c), 1.54), otypes=[float])(k)
    else:
        k_gamma = np.broadcast_to(float(load_sharing), k.shape)
    meshes = stage_meshes(scheme, z1, z2, z2p, z3, k, num, den)
    mi = np.full(n, -1, np.int64)
    wi = np.full(n, -1, np.int64)
    s_h = np.zeros(n)
    s_f = np.zeros(n)
    pending = np.arange(n)
    nw = widths.size
    for lo in range(0, modules.size, MODULE_WINDOW):
        if not pending.size:
            break
        window = modules[lo : lo + MODULE_WINDOW]
        per = max(1, block // (window.size * nw))  # stages a rating call takes
        left = []
        for a in range(0, pending.size, per):
            left.append(_window(load, meshes, pending[a : a + per], window, lo, widths, torque,
                                speed, k_gamma, rack, mi, wi, s_h, s_f))  # fmt: skip
        pending = np.concatenate(left)
    found = mi >= 0
    m_of = np.where(found, modules[np.maximum(mi, 0)], 0.0)
    b_of = np.where(found, widths[np.maximum(wi, 0)], 0.0)
    volume = np.zeros(n)
    mass = np.zeros(n)
    density = load.materials[0].density
    for teeth, internal, copies in stage_gears(scheme, z1, z2, z2p, z3, k):
        v = gear_volume(teeth, m_of, b_of, 0.0, internal, 0.0, rack.dedendum) * copies
        volume += np.where(found, v, 0.0)
    mass = volume * density
    eta = np.zeros(n)
    if found.any():
        f = np.flatnonzero(found)
        eta[f] = stage_efficiency(load, scheme, z1[f], z2[f], z2p[f], z3[f], k[f], num[f], den[f],
                                  torque[f], speed[f], m_of[f], b_of[f], rack)  # fmt: skip
    out = {
        "module_index": mi, "width_index": wi, "module": m_of, "face_width": b_of,
        "S_H": s_h, "S_F": s_f, "volume": volume, "mass": mass,
        "ring": np.asarray(z3, float) * m_of, "efficiency": eta,
    }  # fmt: skip
    return {key: v.reshape(shape) for key, v in out.items()}


def stage_efficiency(load: Load, scheme: str, z1, z2, z2p, z3, n_planets, num, den, torque,
                     speed, module, face_width, rack: BasicRack | None = None):  # fmt: skip
    """The efficiency of zero-shift stages (ring fixed, sun in, carrier out; arrays broadcast)
    from their meshes at the load: each mesh's ISO/TR 14179-2 efficiency
    (:func:`gears.rating.losses.pair_losses`, the load's flank roughness and
    :meth:`gears.GearPair.efficiency`'s oil) at its torque per planet and its speed relative to
    the carrier (:func:`stage_meshes`: the lossless flow, as the sizing rates them), the ring's
    tip relieved as :class:`trains.Planetary` relieves it; their product is the basic
    efficiency eta_0 of the stage in the carrier frame, and the stage's is Ozols (14.26),
    :func:`trains.power.planetary_efficiency` of the stage ratio ``num/den`` (sun driving), as
    :meth:`trains.Planetary.efficiency` finds it with those mesh efficiencies. ``torque`` in
    N m on the sun, ``speed`` in rpm, ``module`` and ``face_width`` in mm.

    Returns the efficiencies: at most 1, in (0, 1] for a reduction (``num/den > 1``, the
    gearbox search's stages); at or below 0 where a stage locks (a step-up or negative ratio
    with a poor eta_0, Ozols (14.27)); 0 where the friction equation does not give a mesh's
    loss (a loss reaching its power, no continuous mesh).

    >>> from gears.rating.sizing import load_case
    >>> round(float(stage_efficiency(load_case(60, 1500), "simple", 20, 31, 31, 82, 3, 102,
    ...                              20, 60, 1500, 2.0, 20.0)), 4)   # Planetary.efficiency: 0.9894
    0.9894
    """
    scheme = canonical_scheme(scheme)
    rack = rack or BasicRack.iso53()
    m, b = np.asarray(module, float), np.asarray(face_width, float)
    torque, speed = np.asarray(torque, float), np.asarray(speed, float)
    eta0 = 1.0
    ok = True
    for ms in stage_meshes(scheme, z1, z2, z2p, z3, n_planets, num, den):
        relief = ring_tip_alteration(ms["z1"], ms["z2"], m, rack) if ms["internal"] else 0.0
        r = pair_losses(torque * ms["torque"], speed * np.abs(ms["speed"]), ms["z1"], ms["z2"],
                        m, b, pressure_angle=rack.pressure_angle, internal=ms["internal"],
                        roughness=load.options.get("roughness", 1.0), addendum=rack.addendum,
                        tip_alteration=(0.0, relief), errors="mask")  # fmt: skip
        eta0 = eta0 * r.efficiency
        ok = ok & (r.efficiency > 0.0)
    ratio = np.asarray(num, float) / np.asarray(den, float)
    eta = planetary_efficiency(np.where(ok, ratio, 2.0), np.where(ok, eta0, 1.0))
    return np.where(ok, eta, 0.0)[()]


def _window(load, meshes, pending, window, lo, widths, torque, speed, k_gamma, rack, mi, wi,
            s_h, s_f) -> np.ndarray:  # fmt: skip
    """Rate stages ``pending`` at every module of ``window`` (modules ``lo ...``) and width;
    write the first (module, width) that carries each into ``mi``, ``wi``, ``s_h``, ``s_f``;
    return the stages none carries."""
    nw = widths.size
    # every pending stage x module of the window x width, rated at once (one call a mesh);
    # the first (module, width) in that order that carries the load is the stage's
    grid = (pending.size, window.size, nw)
    rows = np.broadcast_to(pending[:, None, None], grid).ravel()
    m = np.broadcast_to(window[None, :, None], grid).ravel()
    b = np.broadcast_to(widths[None, None, :], grid).ravel()
    ok = np.ones(rows.size, bool)
    low_h = np.full(rows.size, np.inf)
    low_f = np.full(rows.size, np.inf)
    for ms in meshes:
        relief = 0.0
        if ms["internal"]:  # per stage and module, then per width
            r2 = ring_tip_alteration(ms["z1"][pending][:, None], ms["z2"][pending][:, None],
                                     window[None, :], rack)  # fmt: skip
            relief = np.broadcast_to(r2[:, :, None], grid).ravel()
        r = rate(
            load, ms["z1"][rows], ms["z2"][rows], m, b, internal=ms["internal"], rack=rack,
            torque=torque[rows] * ms["torque"][rows],
            speed=speed[rows] * np.abs(ms["speed"][rows]),
            contacts=tuple(_at(c, rows) for c in ms["contacts"]),
            idler=tuple(_at(v, rows) for v in ms["idler"]),
            load_sharing=k_gamma[rows], tip_alteration=(0.0, relief),
        )  # fmt: skip
        ok &= load.meets(r)
        low_h = np.minimum(low_h, np.minimum(r.S_H1, r.S_H2))
        low_f = np.minimum(low_f, np.minimum(r.S_F1, r.S_F2))
    ok = ok.reshape(pending.size, -1)
    hit = ok.any(axis=1)
    first = np.argmax(ok, axis=1)[hit]  # module-major: the smallest module, then width
    where = pending[hit]
    flat = np.flatnonzero(hit) * ok.shape[1] + first
    mi[where] = lo + first // nw
    wi[where] = first % nw
    s_h[where] = low_h[flat]
    s_f[where] = low_f[flat]
    pending = pending[~hit]
    return pending


def _at(value, rows):
    """``value[rows]`` for an array, the value itself for a scalar or bool."""
    if isinstance(value, np.ndarray) and value.ndim:
        return value[rows]
    return value
