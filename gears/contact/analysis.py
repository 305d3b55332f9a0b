"""Layer 3, loaded tooth contact analysis over arrays: the mesh cut into cells, their stiffness,
the load shared among them by a non-negative (active-set) solve, and the results over a mesh
cycle: transmission error, mesh stiffness, load sharing, pressure, K_Hbeta and K_Halpha.

The model (the "slice" model of loaded tooth contact analysis). The face width b is cut into
``slices`` transverse slices of width L = b / slices; in each slice the teeth are spur teeth of
the transverse profile whose contact lies ``u`` mm along the transverse line of action from
N1 (gear 1's base-circle tangent point); a helical slice is displaced along the line by its
face position times tan beta_b. A mesh cycle (one base pitch p_bt) is sampled at
``positions`` positions; at each, tooth pair ``k`` touches slice ``j`` at
``u = u0 + (y_j + b/2) tan beta_b + k p_bt`` where that lies on the path of contact
``[u_A, u_E]``. Each such cell is a spring of stiffness
``k = E L / C(u)`` (:func:`gears.contact.compliance.mesh_compliance`: both teeth and the Hertzian
approach in series), preceded by a gap ``g`` (mm) that the flank modifications and the
misalignment open. The transmission error ``delta`` (mm along the line of action; positive =
gear 2 lags) is the approach of the gears' bodies: a cell carries ``F = k max(delta - g, 0)``
and the cells carry the transverse load ``F_bt = T / r_b1`` together. This is a non-negative
least-squares problem (the minimum of the complementary energy with F >= 0); with independent
springs its exact solution is found by the active set: cells sorted by gap enter one by one
until the next gap lies above the approach (:func:`share_load`, vectorised over positions,
loads and reliefs at once). A test solves the same problem by ``scipy.optimize.nnls``.

An internal pair (gear 2 a ring) is the same model on its own path of contact: N2 lies behind
N1 (``u_N2 = (r_b1 - r_b2) tan alpha_wt``), the ring's tooth is the stockier internal tooth of
:func:`gears.contact.compliance.tooth_compliance` and the Hertzian radius of a convex on a
concave flank, ``rho_1 rho_2 / (rho_2 - rho_1)``, keeps the external form ``u (u_N2 - u) /
u_N2``.

Slices do not couple (each slice bends on its own), the Hertzian approach is linear, and the
teeth are perfect involutes apart from their modifications: the model of the slice method
(e.g. Harris 1958; Tavakoli and Houser 1986; Velex and Maatar 1996 without the coupling).

Examples
--------
>>> d, f = share_load(np.array([2.0, 2.0]), np.array([0.0, 0.5]), 1.0)   # one spring touches
>>> float(d), [float(v) for v in f]
(0.5, [1.0, 0.0])
"""

from __future__ import annotations

import math

import numpy as np

from gears.contact.compliance import mesh_compliance
from gears.contact.modification import lead_relief, profile_relief
from gears.meshing import line_positions

__all__ = [
    "TABLE",
    "cell_stiffness",
    "contact_factors",
    "harris_map",
    "loaded_contact",
    "mesh_cells",
    "modification_grid",
    "pair_gaps",
    "share_load",
]

#: Points on the path of contact at which the pair's compliance is integrated; a cubic spline
#: through them gives every cell's (a smooth function: within 5e-6 relative of the integral at
#: the cell, measured on a 20/50 pair and on an 8/12 pair with shifts 0.5; linear
#: interpolation would need 1000 points for that).
TABLE = 65


def share_load(stiffness, gaps, load):
    """The approach ``delta`` and the cell loads of springs ``stiffness`` (N/mm; 0 = no
    contact) behind ``gaps`` (mm) pressed together by ``load`` (N): ``sum k max(delta - g, 0)
    = load`` with every load >= 0. The last axis holds the cells; the leading axes (positions,
    loads, reliefs) broadcast with ``load``. Returns ``(delta, forces)``."""
    k = np.asarray(stiffness, float)
    g = np.where(k > 0, np.asarray(gaps, float), np.inf)
    load = np.asarray(load, float)
    k, g = np.broadcast_arrays(k, g)
    order = np.argsort(g, axis=-1)
    gs = np.take_along_axis(g, order, axis=-1)
    ks = np.take_along_axis(k, order, axis=-1)
    live = np.isfinite(gs)
    ks = np.where(live, ks, 0.0)
    s_k = np.cumsum(ks, axis=-1)
    s_kg = np.cumsum(ks * np.where(live, gs, 0.0), axis=-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        delta_m = (load[..., None] + s_kg) / s_k
    g_next = np.concatenate([gs[..., 1:], np.full((*gs.shape[:-1], 1), np.inf)], axis=-1)
    valid = (s_k > 0) & (delta_m <= g_next)
    first = np.argmax(valid, axis=-1)
    delta = np.take_along_axis(delta_m, first[..., None], axis=-1)[..., 0]
    with np.errstate(invalid="ignore"):
        forces = np.where(np.isfinite(g), k * np.maximum(delta[..., None] - g, 0.0), 0.0)
    return delta, forces


def mesh_cells(start, end, base_pitch, face_width, tan_base_helix, positions, slices):
    """The cells of one mesh cycle: ``(u, y, active)`` with ``u`` of shape (positions, pairs,
    slices) the roll positions (mm from N1), ``y`` the slices' centres (mm from the face
    centre) and ``active`` where ``u`` lies on the path of contact ``[start, end]``. Position 0
    has the first pair not behind the others entering at ``start`` on the slice at -b/2."""
    y = face_width * ((np.arange(slices) + 0.5) / slices - 0.5)
    spread = face_width * abs(tan_base_helix)
    behind = math.ceil(spread / base_pitch)  # pairs behind 0 reach the face's far end
    ahead = math.ceil((end - start) / base_pitch)
    k = np.arange(-behind, ahead + 1)
    u0 = start + base_pitch * np.arange(positions) / positions
    shift = (y + face_width / 2.0) * abs(tan_base_helix)
    u = u0[:, None, None] + shift[None, None, :] + base_pitch * k[None, :, None]
    active = (u >= start - 1e-12) & (u <= end + 1e-12)
    return u, y, active


def cell_stiffness(u, start, end, n2, gear1, gear2, modulus, poisson, width, internal=False):
    """Stiffness (N/mm) of cells of width ``width`` (mm) at the roll positions ``u``: the
    pair's compliance integrated at :data:`TABLE` points of ``[start, end]``, a cubic spline
    between them.
    ``gear1``/``gear2`` are ``(rb, alpha2, rf, bore_radius)``; ``n2`` is u at N2 (a ring's
    N2 lies behind N1: its roll length is ``u - n2``)."""
    from scipy.interpolate import CubicSpline  # heavy: imported where used

    grid = np.linspace(start, end, TABLE)
    t2 = (grid - n2 if internal else n2 - grid) / gear2[0]
    table = mesh_compliance(grid / gear1[0], t2, gear1, gear2, poisson, internal=internal)
    return modulus * width / CubicSpline(grid, table)(u)


def loaded_contact(geometry: dict, load, gaps_from, positions=64, slices=30, modulus=206000.0,
                   poisson=0.3):  # fmt: skip
    """The loaded contact of one pair over a mesh cycle, as a dict of arrays.

    ``geometry`` holds the pair as numbers: ``rb1, rb2, ra1, ra2, center_distance,
    base_pitch, face_width, tan_base_helix``, ``gear1``/``gear2`` (``(rb, alpha2, rf,
    bore_radius)``) and ``internal`` (gear 2 a ring; a ring's ``ra2`` is its inner tip).
    ``load`` is the transverse load F_bt along the line of action (N; an array broadcasts in
    front). ``gaps_from(u, y, start, end)`` gives the gaps (mm) of cells at roll
    ``u`` and face position ``y``, with leading axes of its own in front (reliefs), or None.

    Returns ``start, end, n2, u, y, active, stiffness (cells, N/mm), gaps, delta (mm), forces
    (N), unloaded (mm)`` over (..., positions, pairs, slices).
    """
    g = geometry
    internal = bool(g.get("internal", False))
    sigma = -1.0 if internal else 1.0
    base_sum = g["rb1"] + sigma * g["rb2"]
    tan_wt = math.sqrt(max((g["center_distance"] / base_sum) ** 2 - 1.0, 0.0))
    start, end, n2 = (float(v) for v in line_positions(g["ra1"], g["ra2"], g["rb1"], g["rb2"],
                                                        tan_wt, sigma))  # fmt: skip
    b, pb = g["face_width"], g["base_pitch"]
    u, y, active = mesh_cells(start, end, pb, b, g["tan_base_helix"], positions, slices)
    k = cell_stiffness(np.clip(u, start, end), start, end, n2, g["gear1"], g["gear2"], modulus,
                       poisson, b / slices, internal)  # fmt: skip
    k = np.where(active, k, 0.0)
    gaps = np.zeros(u.shape) if gaps_from is None else gaps_from(u, y, start, end)
    gaps = np.where(active, gaps, np.inf)
    flat_k = k.reshape(u.shape[0], -1)
    flat_g = gaps.reshape((*gaps.shape[:-2], -1))
    delta, forces = share_load(flat_k, flat_g, np.asarray(load, float)[..., None])
    unloaded = np.min(flat_g, axis=-1)
    return {
        "start": start, "end": end, "n2": n2, "u": u, "y": y, "active": active,
        "stiffness": k, "gaps": gaps, "delta": delta, "unloaded": unloaded,
        "forces": forces.reshape(forces.shape[:-1] + u.shape[1:]),
    }  # fmt: skip


def contact_factors(forces, active_ideal_forces, slices):
    """``(K_Hbeta, K_Halpha)`` from the cell loads (..., positions, pairs, slices).

    K_Hbeta: the largest mean line load of a slice over the mesh cycle against the mean over
    the face (ISO 6336-1 clause 7: the maximum over the mean load per unit face width).
    K_Halpha: the heaviest tooth pair's mean line load (its load over its loaded contact
    length) against the same for the ideal pair (no modification, no misalignment) at the same
    load: how much less evenly the pairs in contact share the transverse load.
    """
    per_slice = forces.sum(axis=-2).mean(axis=-2)  # (..., slices)
    k_hbeta = per_slice.max(axis=-1) / per_slice.mean(axis=-1)

    def heaviest(f):
        loaded = (f > 0).sum(axis=-1)  # slices carrying load, per pair and position
        line = f.sum(axis=-1) / np.maximum(loaded, 1)
        return line.max(axis=(-1, -2))

    return k_hbeta, heaviest(forces) / heaviest(active_ideal_forces)


def harris_map(geometry: dict, loads, reliefs, shape_of, positions=64, slices=30,
               modulus=206000.0, poisson=0.3):  # fmt: skip
    """Transmission error peak to peak (mm) over reliefs (rows) and loads (columns): the gaps
    are ``relief * shape_of(u, y, start, end)`` (the relief's shape per unit amount)."""
    reliefs = np.asarray(reliefs, float)

    def gaps(u, y, start, end):
        return reliefs[:, None, None, None, None] * shape_of(u, y, start, end)

    out = loaded_contact(geometry, np.asarray(loads, float)[None, :], gaps, positions,
                         slices, modulus, poisson)  # fmt: skip
    d = out["delta"]
    return d.max(axis=-1) - d.min(axis=-1)


def modification_grid(geometry: dict, load, tip_reliefs, crownings, shapes_of, positions=64,
                      slices=30, modulus=206000.0, poisson=0.3):  # fmt: skip
    """Transmission error peak to peak (mm) and K_Hbeta over a grid of tip reliefs (rows, mm)
    and crownings (columns, mm) at one load (N): the gaps are ``base + C_a tip + C_b crown``
    where ``shapes_of(u, y, start, end)`` returns ``(base, tip, crown)`` (the gaps the pair
    has anyway, and the shapes per unit amount). One solve over the whole grid."""
    ca = np.asarray(tip_reliefs, float)[:, None]
    cb = np.asarray(crownings, float)[None, :]
    grid = (ca + 0.0 * cb).ravel(), (cb + 0.0 * ca).ravel()

    def gaps(u, y, start, end):
        base, tip, crown = shapes_of(u, y, start, end)
        return base + grid[0][:, None, None, None] * tip + grid[1][:, None, None, None] * crown

    out = loaded_contact(geometry, load, gaps, positions, slices, modulus, poisson)
    d = out["delta"]
    shape = (ca.shape[0], cb.shape[1])
    p2p = (d.max(axis=-1) - d.min(axis=-1)).reshape(shape)
    per_slice = out["forces"].sum(axis=-2).mean(axis=-2)
    k_hbeta = (per_slice.max(axis=-1) / per_slice.mean(axis=-1)).reshape(shape)
    return p2p, k_hbeta


def pair_gaps(u, y, start, end, face_width, mods1, mods2, lengths1, lengths2, misalignment=0.0):
    """Gaps (mm) of cells at roll ``u`` and face ``y`` from the modifications of both gears
    (gear 1's tip lies at ``end``, gear 2's at ``start``) and the misalignment (a tilt of
    ``misalignment`` mm over the face, 0 at the face's start)."""
    out = np.zeros(np.broadcast(u, y).shape)
    for m, (la, lf, li), root, tip in (
        (mods1, lengths1, start, end),
        (mods2, lengths2, end, start),
    ):
        if m is None:
            continue
        out = out + profile_relief(u, root, tip, m.tip_relief, la, m.root_relief, lf, m.kind)
        out = out + lead_relief(y, face_width, m.crowning, m.end_relief, li, m.helix_slope,
                                m.kind)  # fmt: skip
    return out + misalignment * (y / face_width + 0.5)
