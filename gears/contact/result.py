"""Layer 8, classes: :class:`Contact`, the loaded tooth contact analysis of one pair as a thin
view, :class:`HarrisMap`, the transmission error over relief and load, and
:class:`ModificationSearch`, the tip relief and crowning that minimise it at a design load.

``GearPair.contact(torque, ...)`` calls :func:`contact`, which reads the pair's geometry and
its gears' :class:`gears.contact.modification.Modification` and calls the vectorised
:func:`gears.contact.analysis.loaded_contact`. Transmission error is in um along the line of
action (positive: gear 2 lags) and in arcseconds of gear 1; stiffness in N/(mm um), per mm of
face width; loads in N along the transverse line of action (F_bt = T1 / r_b1).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property
from typing import TYPE_CHECKING, Any

import numpy as np

from gears.arguments import check_choice, check_integer, check_positive, check_real
from gears.contact.analysis import (
    contact_factors,
    harris_map,
    loaded_contact,
    modification_grid,
    pair_gaps,
    share_load,
)
from gears.contact.modification import KINDS, Modification, lead_relief
from gears.errors import GearError

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from numpy.typing import ArrayLike

__all__ = [
    "MAX_CELLS",
    "Contact",
    "HarrisMap",
    "ModificationSearch",
    "best_modification",
    "contact",
    "contact_geometry",
    "harris",
    "rating_factors",
]

#: The most cells (positions x tooth pairs x slices, times loads x reliefs for a map) one call
#: solves: about 100 MB of arrays and a second of work.
MAX_CELLS = 4_000_000

#: Steel (ISO 6336-5): Young's modulus (MPa) and Poisson's ratio.
STEEL = (206000.0, 0.3)

ARCSEC = 180.0 / math.pi * 3600.0


def contact_geometry(pair, center_distance_error: float = 0.0) -> dict:
    """The pair as the numbers :func:`gears.contact.analysis.loaded_contact` takes, or a
    :class:`GearError` for a pair the analysis does not cover (racks, no face width, a contact
    ratio below 1)."""
    if getattr(pair, "is_rack", False):
        raise GearError(
            "contact analysis covers external and internal gear pairs; got a rack as gear 2 "
            "(a rack's tooth is a straight-sided beam the compliance model does not cover)"
        )
    internal = bool(pair.internal)
    sigma = -1.0 if internal else 1.0
    pair.path_of_contact  # noqa: B018 - refuses a tip inside its base circle, naming it
    g1, g2 = pair.g1, pair.g2
    widths = [w for w in (g1.face_width, g2.face_width) if w]
    if not widths:
        raise GearError("contact analysis needs a face_width on g1 or g2")
    ra1, ra2 = (d / 2 for d in pair.tip_diameters)
    rb1, rb2 = g1.base_diameter / 2, g2.base_diameter / 2
    a = pair.center_distance
    da = check_real("center_distance_error", center_distance_error, -0.5 * g1.module,
                    0.5 * g1.module)  # fmt: skip
    base_sum = rb1 + sigma * rb2
    if a + da <= abs(base_sum):
        what = "difference" if internal else "sum"
        raise GearError(f"center_distance_error = {da:g} mm puts the centres within the base "
                        f"circles' {what}: no line of action")  # fmt: skip
    geometry = {
        "rb1": rb1, "rb2": rb2, "ra1": ra1, "ra2": ra2, "center_distance": a + da,
        "base_pitch": g1.base_pitch, "face_width": min(widths),
        "tan_base_helix": math.tan(math.radians(g1.base_helix_angle)),
        "gear1": (rb1, g1.base_thickness / g1.base_diameter, g1.root_diameter / 2, None),
        "gear2": (rb2, _half_angle(g2), g2.root_diameter / 2, None),
        "internal": internal,
    }  # fmt: skip
    tan_wt = math.sqrt((a + da) ** 2 / base_sum**2 - 1.0)
    n2 = base_sum * tan_wt
    path = math.sqrt(ra1**2 - rb1**2) - (n2 - sigma * math.sqrt(ra2**2 - rb2**2))
    total = (path + geometry["face_width"] * abs(geometry["tan_base_helix"])) / g1.base_pitch
    if total < 1.0:
        raise GearError(
            f"total contact ratio {total:.4f} < 1 at centre distance {a + da:.4f} mm: the teeth "
            "lose contact within each mesh cycle; valid is a pair with eps_gamma >= 1"
        )
    geometry["path"] = path
    return geometry


def _half_angle(gear) -> float:
    """Half the angle a tooth subtends on the base circle, radians: s_b / d_b for an external
    gear; a ring's ``s_t / d - inv alpha_t`` (its teeth widen outward and may not reach the
    base circle, so the value may be negative)."""
    if not gear.internal:
        return gear.base_thickness / gear.base_diameter
    alpha_t = math.radians(gear.transverse_pressure_angle)
    s_t = gear.tooth_thickness(gear.reference_diameter)
    return float(s_t / gear.reference_diameter - (math.tan(alpha_t) - alpha_t))


def _modifications(pair):
    return tuple(getattr(g, "modification", None) for g in (pair.g1, pair.g2))


def _lengths(mod, short, face_width):
    return (0.0, 0.0, 0.0) if mod is None else mod.lengths(short, face_width)


def _checked(torque, positions, slices, geometry, extra=1):
    torque = check_positive("torque", torque, "N m")
    positions = check_integer("positions", positions, 4, 4096)
    slices = check_integer("slices", slices, 1, 1000)
    g = geometry
    pairs = (g["path"] + g["face_width"] * abs(g["tan_base_helix"])) / g["base_pitch"]
    per_position = slices * (math.ceil(pairs) + 1) * extra
    cells = positions * per_position
    if cells > MAX_CELLS:
        fits = MAX_CELLS // per_position
        hint = f"positions <= {fits} at these slices" if fits >= 4 else "fewer slices"
        raise GearError(
            f"positions = {positions} x slices = {slices} (x {extra} loads and reliefs) makes "
            f"about {cells:.3g} cells; valid is at most {MAX_CELLS:.3g} cells: {hint}"
        )
    return torque, positions, slices


@dataclass(frozen=True)
class Contact:
    """The loaded tooth contact of one pair over one mesh cycle (one base pitch).

    Attributes
    ----------
    pair : GearPair
        The pair analysed.
    torque : float
        Torque on gear 1, N m.
    load : float
        The transverse load along the line of action F_bt = T1 / r_b1, N.
    arrays : dict
        Everything :func:`gears.contact.analysis.loaded_contact` returns, for this pair.
    settings : dict
        positions, slices, misalignment, centre-distance error, modulus, Poisson's ratio.
    """

    pair: object
    torque: float
    load: float
    arrays: dict = field(repr=False)
    settings: dict = field(default_factory=dict)

    @cached_property
    def _ideal_forces(self) -> np.ndarray:
        """The cell loads of the same pair without modification or misalignment (the same
        cells and stiffness, every gap 0), for K_Halpha."""
        a = self.arrays
        k = a["stiffness"].reshape(a["u"].shape[0], -1)
        gaps = np.where(k > 0, 0.0, np.inf)
        _, forces = share_load(k, gaps, np.full(k.shape[0], self.load))
        return forces.reshape(a["u"].shape)

    @property
    def face(self) -> np.ndarray:
        """Face positions of the slices' centres, mm from the face centre."""
        return self.arrays["y"]

    @property
    def roll(self) -> np.ndarray:
        """Each position as the roll distance of tooth pair 0 on the first slice, mm from N1."""
        return self.arrays["u"][:, 0, 0]

    @property
    def angle(self) -> np.ndarray:
        """Each position as gear 1's rotation from the first, degrees."""
        return np.degrees((self.roll - self.roll[0]) / (self.pair.g1.base_diameter / 2))

    @property
    def transmission_error(self) -> np.ndarray:
        """Loaded transmission error at each position, um along the line of action."""
        return self.arrays["delta"] * 1000.0

    @property
    def transmission_error_arcsec(self) -> np.ndarray:
        """Loaded transmission error at each position as gear 1's rotation, arcseconds."""
        return self.arrays["delta"] / (self.pair.g1.base_diameter / 2) * ARCSEC

    @property
    def unloaded_transmission_error(self) -> np.ndarray:
        """The geometric (unloaded) transmission error, um: the smallest gap in contact."""
        return self.arrays["unloaded"] * 1000.0

    @property
    def peak_to_peak(self) -> float:
        """Peak-to-peak loaded transmission error, um."""
        te = self.transmission_error
        return float(te.max() - te.min())

    @property
    def mesh_stiffness(self) -> np.ndarray:
        """Mesh stiffness at each position: the stiffness of the loaded cells per mm of face
        width, N/(mm um)."""
        a = self.arrays
        loaded = a["forces"] > 0
        width = self.settings["face_width"]
        return np.sum(np.where(loaded, a["stiffness"], 0.0), axis=(-1, -2)) / width / 1000.0

    @property
    def mean_mesh_stiffness(self) -> float:
        """The mean of :attr:`mesh_stiffness` over the mesh cycle (c_gamma), N/(mm um)."""
        return float(np.mean(self.mesh_stiffness))

    @property
    def single_stiffness(self) -> float:
        """The largest stiffness of one tooth pair per mm of its contact length over the mesh
        cycle (the analogue of ISO 6336-1's c'), N/(mm um)."""
        a = self.arrays
        k = a["stiffness"].sum(axis=-1)
        length = a["active"].sum(axis=-1) * (self.settings["face_width"] / a["y"].size)
        per_mm = np.where(length > 0, k / np.maximum(length, 1e-300), 0.0)
        return float(per_mm.max() / 1000.0)

    @property
    def load_sharing(self) -> np.ndarray:
        """Load of each tooth pair (rows; pair k is k base pitches ahead of pair 0) at each
        position (columns), N; every column sums to :attr:`load`."""
        return self.arrays["forces"].sum(axis=-1).T

    @cached_property
    def _pressure(self) -> tuple[np.ndarray, np.ndarray]:
        a = self.arrays
        start, end, n2 = a["start"], a["end"], a["n2"]
        modulus, poisson = self.settings["modulus"], self.settings["poisson"]
        cos_b = 1.0 / math.sqrt(1.0 + self._tan_base_helix**2)
        width = self.settings["face_width"] / a["y"].size
        q = a["forces"] / width  # N/mm along the contact line (F_n / (L / cos beta_b))
        u = np.clip(a["u"], start, end)
        radius = u * (n2 - u) / n2 / cos_b  # relative curvature radius, normal section
        e_star = modulus / (2.0 * (1.0 - poisson**2))
        p = np.sqrt(q * e_star / (math.pi * np.maximum(radius, 1e-9)))
        span = (end - start) / self.pair.g1.base_pitch
        grid = np.linspace(start, end, max(round(span * self.settings["positions"]), 2) + 1)
        out = np.zeros((a["y"].size, grid.size))
        for j in range(a["y"].size):
            live = a["active"][:, :, j]
            uj, pj = a["u"][:, :, j][live], p[:, :, j][live]
            order = np.argsort(uj)
            out[j] = np.interp(grid, uj[order], pj[order])  # the ends held: within a step
        return grid, out

    @property
    def _tan_base_helix(self) -> float:
        return math.tan(math.radians(self.pair.g1.base_helix_angle))

    @property
    def pressure(self) -> np.ndarray:
        """Hertzian pressure p_0 (MPa) over the flank of gear 1: rows the slices across the
        face (:attr:`face`), columns the roll positions on the path of contact (:attr:`profile`):
        the contact pattern."""
        return self._pressure[1]

    @property
    def profile(self) -> np.ndarray:
        """The roll positions of :attr:`pressure`'s columns, mm from N1."""
        return self._pressure[0]

    @cached_property
    def _factors(self) -> tuple[float, float]:
        kb, ka = contact_factors(self.arrays["forces"], self._ideal_forces,
                                 self.arrays["y"].size)  # fmt: skip
        return float(kb), float(ka)

    @property
    def K_Hbeta(self) -> float:
        """Face load factor from the load distribution: the largest mean load per unit face
        width over the mean (ISO 6336-1 clause 7 definition)."""
        return self._factors[0]

    @property
    def K_Halpha(self) -> float:
        """Transverse load factor: the heaviest tooth pair's line load against that of the
        ideal pair (no modification or misalignment) at the same load."""
        return self._factors[1]

    def plot(self, kind: str = "te", ax: Axes | None = None) -> Figure:
        """A matplotlib figure: ``"te"`` the transmission error and mesh stiffness over the
        mesh cycle, ``"pattern"`` the contact pattern (:mod:`gears.contact.plot`)."""
        from gears.contact.plot import pattern_figure, te_figure

        kind = check_choice("kind", kind, ("te", "pattern"))
        return (te_figure if kind == "te" else pattern_figure)(self, ax=ax)

    def _repr_html_(self) -> str:
        """The results as a table (notebooks)."""
        from gears.display import html_table

        te = self.transmission_error
        rows = [
            ("torque on gear 1", f"{self.torque:g}", "N m"),
            ("load along the line of action F_bt", f"{self.load:.1f}", "N"),
            ("transmission error", f"{te.min():.3f} ... {te.max():.3f}", "um"),
            ("peak to peak", f"{self.peak_to_peak:.3f}", "um"),
            ("mean mesh stiffness", f"{self.mean_mesh_stiffness:.3f}", "N/(mm um)"),
            ("largest single-pair stiffness", f"{self.single_stiffness:.3f}", "N/(mm um)"),
            ("largest Hertzian pressure", f"{self.pressure.max():.1f}", "MPa"),
            ("K_Hbeta", f"{self.K_Hbeta:.4f}", ""),
            ("K_Halpha", f"{self.K_Halpha:.4f}", ""),
        ]
        return html_table(["", "value", "unit"], rows, caption="loaded tooth contact")

    def __repr__(self) -> str:
        return (
            f"Contact(torque={self.torque:g} N m, peak_to_peak={self.peak_to_peak:.4g} um, "
            f"mean_mesh_stiffness={self.mean_mesh_stiffness:.4g} N/(mm um), "
            f"K_Hbeta={self.K_Hbeta:.4g}, K_Halpha={self.K_Halpha:.4g})"
        )


def contact(pair, torque: float, *, misalignment: float = 0.0, f_ma: float = 0.0,
            f_sh: float = 0.0, positions: int = 64, slices: int = 30,
            center_distance_error: float = 0.0, modulus: float = STEEL[0],
            poisson: float = STEEL[1]) -> Contact:  # fmt: skip
    """The loaded tooth contact analysis of ``pair`` under ``torque`` (N m on gear 1).

    Parameters
    ----------
    pair : GearPair
        An external pair; each gear's ``modification`` (if any) opens its gaps.
    torque : float
        Torque on gear 1, N m > 0.
    misalignment : float
        Mesh misalignment in the plane of action, mm over the face width, as one number
        (the sum of ``f_ma`` and ``f_sh`` when those are not given apart), within +- one
        module.
    f_ma, f_sh : float
        The two parts of the misalignment ISO 6336-1 (clause 7.6) separates: f_ma from
        manufacture (the helix slope deviations and the bores' alignment; either sign, fixed
        with the load) and f_sh from the deflection of the shafts and bearings at this
        torque (its sign: the end of the face it closes); each mm over the face width in
        the plane of action, within +- one module. The analysis tilts the flanks by
        ``misalignment + f_ma + f_sh``: its gaps are the real tilt, so ISO's 1.33 on f_sh
        (an allowance for the estimate of method C) does not apply.
    positions, slices : int
        Positions over one base pitch (4 ... 4096) and slices across the face (1 ... 1000).
    center_distance_error : float
        Delta a, mm (+- half a module): the pair runs at a_w + Delta a.
    modulus, poisson : float
        Young's modulus (MPa) and Poisson's ratio of both gears (steel by default).

    Raises
    ------
    GearError
        Bad input, naming it; racks, internal pairs, no face width; more than
        :data:`MAX_CELLS` cells.
    """
    geometry = contact_geometry(pair, center_distance_error)
    torque, positions, slices = _checked(torque, positions, slices, geometry)
    limit = pair.g1.module
    misalignment = check_real("misalignment", misalignment, -limit, limit)
    f_ma = check_real("f_ma", f_ma, -limit, limit)
    f_sh = check_real("f_sh", f_sh, -limit, limit)
    tilt = misalignment + f_ma + f_sh
    if abs(tilt) > limit:
        raise GearError(f"misalignment + f_ma + f_sh = {tilt:g} mm; valid is within +- one "
                        f"module ({limit:g} mm)")  # fmt: skip
    modulus = check_real("modulus", modulus, 1.0, 1e7)
    poisson = check_real("poisson", poisson, 0.0, 0.5, False, True)
    load = 1000.0 * torque / geometry["rb1"]
    b = geometry["face_width"]
    m1, m2 = _modifications(pair)

    def gaps(u, y, start, end):
        short = max(end - start - geometry["base_pitch"], 0.0)
        return pair_gaps(u, y, start, end, b, m1, m2, _lengths(m1, short, b),
                         _lengths(m2, short, b), tilt)  # fmt: skip

    plain = m1 is None and m2 is None and tilt == 0.0
    arrays = loaded_contact(geometry, load, None if plain else gaps, positions, slices,
                            modulus, poisson)  # fmt: skip
    settings = {
        "positions": positions, "slices": slices, "misalignment": tilt, "f_ma": f_ma,
        "f_sh": f_sh,
        "center_distance_error": center_distance_error, "modulus": modulus,
        "poisson": poisson, "face_width": b,
    }  # fmt: skip
    return Contact(pair, torque, load, arrays, settings)


def rating_factors(pair, torque, misalignment, factors: dict) -> dict:
    """``K_Hbeta="contact"`` / ``K_Halpha="contact"`` of :meth:`gears.GearPair.rating`: the
    factors from the loaded contact analysis at ``torque`` (N m, times K_A), with
    ``misalignment`` F_betax in um."""
    f_bx = 0.0 if misalignment is None else check_real("misalignment", misalignment, -1e4, 1e4)
    c = contact(pair, torque, misalignment=f_bx / 1000.0)
    out = dict(factors)
    if out.get("K_Hbeta") == "contact":
        out["K_Hbeta"] = c.K_Hbeta
    if out.get("K_Halpha") == "contact":
        out["K_Halpha"] = c.K_Halpha
        out.setdefault("K_Falpha", c.K_Halpha)  # ISO 6336-1 clause 8: K_Falpha = K_Halpha
    return out


@dataclass(frozen=True)
class HarrisMap:
    """Peak-to-peak transmission error (um) over tip relief (rows, mm) and torque (columns,
    N m): tip relief of the same amount, length and kind on both gears (Harris 1958)."""

    reliefs: np.ndarray
    torques: np.ndarray
    peak_to_peak: np.ndarray
    relief_length: float

    def best_relief(self) -> np.ndarray:
        """For each torque, the relief (mm) of the smallest peak-to-peak."""
        return self.reliefs[np.argmin(self.peak_to_peak, axis=0)]

    def plot(self, ax: Axes | None = None) -> Figure:
        """The map as a matplotlib figure (:func:`gears.contact.plot.harris_figure`)."""
        from gears.contact.plot import harris_figure

        return harris_figure(self, ax=ax)


def harris(
    pair, torques: ArrayLike, reliefs: ArrayLike, *, relief_length: float | None = None,
    kind: str = "linear", positions: int = 64, slices: int | None = None,
) -> HarrisMap:  # fmt: skip
    """The Harris map of ``pair``: transmission error peak to peak over tip ``reliefs`` (mm,
    on both gears) and ``torques`` (N m on gear 1), solved at once over arrays.

    ``relief_length`` (mm of roll on the line of action) defaults to the short relief,
    (eps_alpha - 1) p_bt; ``slices`` to 1 for spur pairs (every slice alike), else 30.
    """
    geometry = contact_geometry(pair)
    torques = _array("torques", torques, 0.0, 1e9)
    reliefs = _array("reliefs", reliefs, -1e-12, 1.0)
    if slices is None:
        slices = 1 if pair.g1.helix_angle == 0 else 30
    _checked(float(torques.max()), positions, slices, geometry, torques.size * reliefs.size)
    kind = check_choice("kind", kind, KINDS)
    if relief_length is not None:
        relief_length = check_real("relief_length", relief_length, 0.0, 1e6)
    b = geometry["face_width"]

    def shape(u, y, start, end):
        short = max(end - start - geometry["base_pitch"], 0.0)
        length = short if relief_length is None else relief_length
        unit = Modification(tip_relief=1.0, tip_relief_length=length, kind=kind)
        lengths = unit.lengths(short, b)
        return pair_gaps(u, y, start, end, b, unit, unit, lengths, lengths)

    p2p = harris_map(geometry, 1000.0 * torques / geometry["rb1"], reliefs, shape,
                     int(positions), int(slices))  # fmt: skip
    short = max(geometry["path"] - geometry["base_pitch"], 0.0)
    length = short if relief_length is None else relief_length
    return HarrisMap(reliefs, torques, p2p * 1000.0, float(length))


@dataclass(frozen=True)
class ModificationSearch:
    """Peak-to-peak transmission error (um) and K_Hbeta over tip relief (rows, mm, the same on
    both gears) and crowning (columns, mm, on gear 1: the pair's C_b) at one design torque
    (:func:`best_modification`)."""

    tip_reliefs: np.ndarray
    crownings: np.ndarray
    peak_to_peak: np.ndarray
    K_Hbeta: np.ndarray
    torque: float
    relief_length: float
    kind: str = "linear"
    max_K_Hbeta: float | None = None
    base: tuple = (None, None)

    @property
    def index(self) -> tuple[int, int]:
        """(row, column) of the best cell: the smallest peak to peak among the cells whose
        K_Hbeta is within ``max_K_Hbeta`` (all cells when it is None or none is)."""
        p2p = self.peak_to_peak
        if self.max_K_Hbeta is not None and np.any(self.K_Hbeta <= self.max_K_Hbeta):
            p2p = np.where(self.K_Hbeta <= self.max_K_Hbeta, p2p, np.inf)
        i, j = np.unravel_index(int(np.argmin(p2p)), p2p.shape)
        return int(i), int(j)

    @property
    def tip_relief(self) -> float:
        """The best tip relief C_a, mm."""
        return float(self.tip_reliefs[self.index[0]])

    @property
    def crowning(self) -> float:
        """The best crowning C_b, mm."""
        return float(self.crownings[self.index[1]])

    @property
    def best_peak_to_peak(self) -> float:
        """The peak to peak at the best cell, um."""
        return float(self.peak_to_peak[self.index])

    @property
    def modifications(self) -> tuple[Modification, Modification]:
        """The best cell as ``(gear 1's, gear 2's)`` :class:`Modification`: the tip relief on
        both, the crowning on gear 1, each gear's other modifications (root relief, end
        relief, helix slope) kept as the search took them (their ``kind`` becomes the
        search's)."""
        kw = {"tip_relief": self.tip_relief, "tip_relief_length": self.relief_length,
              "kind": self.kind}  # fmt: skip
        b1, b2 = (Modification() if m is None else m for m in self.base)
        return replace(b1, crowning=self.crowning, **kw), replace(b2, crowning=0.0, **kw)

    def apply(self, pair: Any) -> Any:
        """``pair`` (a :class:`gears.GearPair`) with the best :attr:`modifications` on its
        gears, as a new pair."""
        m1, m2 = self.modifications
        return type(pair)(pair.g1.with_(modification=m1), pair.g2.with_(modification=m2),
                          pair.tip_shortening)  # fmt: skip


def best_modification(
    pair, torque: float, *, tip_reliefs: ArrayLike | None = None,
    crownings: ArrayLike | None = None, relief_length: float | None = None,
    kind: str = "linear", misalignment: float = 0.0, f_ma: float = 0.0, f_sh: float = 0.0,
    max_K_Hbeta: float | None = None, positions: int = 32, slices: int | None = None,
) -> ModificationSearch:  # fmt: skip
    """The tip relief and crowning that minimise the transmission error's peak to peak at the
    design ``torque`` (N m on gear 1), over a grid solved at once
    (:func:`gears.contact.analysis.modification_grid`).

    ``tip_reliefs`` (mm, on both gears) default to 41 values from 0 to twice the unmodified
    pair's largest loaded transmission error at this torque (the relief that cancels the
    deflection lies below it, Harris 1958); ``crownings`` (mm, on gear 1) to 0 for an aligned
    pair, else 9 values from 0 to the larger of the tilt and that deflection. The tilt is
    ``misalignment + f_ma + f_sh`` (mm over the face, as in :func:`contact`); ``max_K_Hbeta``
    keeps the best cell among those whose face load factor is within it. The gears' own tip
    relief and crowning are replaced; their other modifications stay (in the search and in
    :meth:`ModificationSearch.apply`). ``slices`` defaults to 1
    for an aligned spur pair without lead modification, else 20.

    >>> from gears import Gear, GearPair
    >>> p = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))
    >>> s = p.best_modification(300)
    >>> round(s.tip_relief * 1000, 1), round(s.best_peak_to_peak, 2)   # um, um
    (25.1, 1.83)
    """
    geometry = contact_geometry(pair)
    torque = check_positive("torque", torque, "N m")
    limit = pair.g1.module
    tilt = sum(check_real(n, v, -limit, limit) for n, v in
               (("misalignment", misalignment), ("f_ma", f_ma), ("f_sh", f_sh)))  # fmt: skip
    kind = check_choice("kind", kind, KINDS)
    if relief_length is not None:
        relief_length = check_real("relief_length", relief_length, 0.0, 1e6)
    if max_K_Hbeta is not None:
        max_K_Hbeta = check_real("max_K_Hbeta", max_K_Hbeta, 1.0, 1e3, False)
    positions = check_integer("positions", positions, 4, 4096)
    own = [None if m is None else replace(m, tip_relief=0.0, crowning=0.0)
           for m in _modifications(pair)]  # fmt: skip
    load = 1000.0 * torque / geometry["rb1"]
    if tip_reliefs is None or crownings is None:
        d = loaded_contact(geometry, load, None, positions, 1)["delta"]
        deflection = float(np.max(d))
    tip_reliefs = (np.linspace(0.0, min(2.0 * deflection, 1.0), 41) if tip_reliefs is None
                   else _array("tip_reliefs", tip_reliefs, -1e-12, 1.0))  # fmt: skip
    if crownings is None:
        top = min(max(abs(tilt), deflection), 1.0)
        crownings = np.linspace(0.0, top, 9) if tilt != 0.0 else np.zeros(1)
    else:
        crownings = _array("crownings", crownings, -1e-12, 1.0)
    lead = any(m is not None and (m.end_relief or m.helix_slope) for m in own)
    if slices is None:
        aligned = tilt == 0.0 and not lead and not np.any(crownings > 0)
        slices = 1 if pair.g1.helix_angle == 0 and aligned else 20
    _checked(torque, positions, slices, geometry, tip_reliefs.size * crownings.size)
    b = geometry["face_width"]
    m1, m2 = own

    def shapes(u, y, start, end):
        short = max(end - start - geometry["base_pitch"], 0.0)
        base = pair_gaps(u, y, start, end, b, m1, m2, _lengths(m1, short, b),
                         _lengths(m2, short, b), tilt)  # fmt: skip
        length = short if relief_length is None else relief_length
        unit = Modification(tip_relief=1.0, tip_relief_length=length, kind=kind)
        lengths = unit.lengths(short, b)
        tip = pair_gaps(u, y, start, end, b, unit, unit, lengths, lengths)
        crown = lead_relief(y, b, crowning=1.0) + 0.0 * u
        return base, tip, crown

    p2p, k_hbeta = modification_grid(geometry, load, tip_reliefs, crownings, shapes, positions,
                                     int(slices))  # fmt: skip
    short = max(geometry["path"] - geometry["base_pitch"], 0.0)
    length = short if relief_length is None else relief_length
    return ModificationSearch(tip_reliefs, crownings, p2p * 1000.0, k_hbeta, torque,
                              float(length), kind, max_K_Hbeta, tuple(own))  # fmt: skip


def _array(name, values, low, high) -> np.ndarray:
    try:
        arr = np.asarray(values, dtype=float).ravel()
    except (TypeError, ValueError):
        raise GearError(f"{name} = {values!r}; valid is a sequence of numbers") from None
    if arr.size == 0 or arr.size > 10_000 or not np.all(np.isfinite(arr)):
        raise GearError(f"{name} = {values!r}; valid is 1 ... 10000 finite numbers")
    if np.any(arr <= low) or np.any(arr > high):
        rel = ">= 0" if low < 0 else f"> {low:g}"
        raise GearError(f"{name} = {values!r}; valid are numbers {rel} and <= {high:g}")
    return arr
