"""Layer 9, classes: :class:`GearPair`, one mesh as a thin view (its mates and path of contact
in :mod:`gears.mating`, its interference findings in :mod:`gears.interference`).

External, internal (gear 2 is the ring) or pinion-and-rack, spur or helical. The formulas are
the vectorised functions of :mod:`gears.meshing` (its docstring defines the positions on the line
of action); the outlines in mesh come from :mod:`gears.cutting.outline`.
"""

from __future__ import annotations

import math
import numbers
import os
import pathlib
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np
import shapely

from gears.arguments import (
    check_positive,
)
from gears.checks import (
    center_distance_reach,
    form_lengths,
    split_shift_sum,
    tip_diameter_limits,
)
from gears.errors import GearError
from gears.forces import PairForces, pair_forces
from gears.gear import Gear
from gears.geometry import check_real
from gears.interference import interference_findings
from gears.involute import inv
from gears.mating import PathOfContact, Rack
from gears.meshing import (
    PairGeometry,
    center_distance_shift_sum,
    line_positions,
    mesh_efficiency,
    pair_geometry,
    specific_sliding,
)
from gears.report import Finding, Report
from gears.solid.mesh import COLOURS

if TYPE_CHECKING:
    import trimesh
    from numpy.typing import ArrayLike

    from gears.contact.result import Contact, HarrisMap, ModificationSearch
    from gears.cutting.cutter import ShaperCutter
    from gears.rating.capacity import Rating
    from gears.rating.losses import MeshLosses
    from gears.rating.materials import Material
    from gears.rating.scuffing import Oil
    from gears.rating.spectrum import SpectrumRating

__all__ = ["GearPair"]


def _same(name: str, a: float, b: float) -> None:
    if not math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-12):
        raise GearError(f"the gears of a pair need equal {name}; got {a:g} and {b:g}")


@dataclass(frozen=True, init=False)
class GearPair:
    """Two gears in mesh at the centre distance that their shifts give (zero backlash).

    Parameters
    ----------
    g1 : Gear
        Gear 1 (the pinion; external).
    g2 : Gear or Rack
        Gear 2: external, internal (the ring: ``internal=True``) or a :class:`Rack`.
    tip_shortening : bool
        External pairs: shorten both tips by k m_n (DIN 3960, k = y - (x1 + x2) when negative)
        to keep the bottom clearance of the basic rack. Internal pairs keep their tips.

    Raises
    ------
    GearError
        Unequal modules or pressure angles, wrong hands (external helical pairs need opposite
        hands, internal ones the same hand), gear 1 internal, or a ring with no more teeth than
        its pinion.

    Examples
    --------
    >>> p = GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36))
    >>> round(p.working_pressure_angle, 4), round(p.center_distance, 4)   # KHK example
    (26.0886, 56.4999)
    >>> round(p.contact_ratio, 4)
    1.2021
    """

    g1: Gear
    g2: Gear | Rack
    tip_shortening: bool

    def __init__(self, g1: Gear, g2: Gear | Rack, tip_shortening: bool = True) -> None:
        if not isinstance(g1, Gear):
            raise GearError(f"g1 must be a Gear; got {g1!r}")
        if g1.internal:
            raise GearError("gear 1 must be external; pass the internal gear (ring) as g2")
        if isinstance(g2, Rack):
            _same("modules", g1.module, g2.module)
            _same("pressure angles", g1.pressure_angle, g2.pressure_angle)
            if not math.isclose(g1.helix_angle, -g2.helix_angle, abs_tol=1e-12):
                raise GearError(
                    f"a pinion with helix {g1.helix_angle:g} deg meshes with a rack of helix "
                    f"{-g1.helix_angle:g} deg (opposite hand); got {g2.helix_angle:g}"
                )
        elif isinstance(g2, Gear):
            _same("modules", g1.module, g2.module)
            _same("pressure angles", g1.pressure_angle, g2.pressure_angle)
            want = g1.helix_angle if g2.internal else -g1.helix_angle
            if not math.isclose(g2.helix_angle, want, abs_tol=1e-12):
                kind = "the same hand" if g2.internal else "opposite hands"
                raise GearError(
                    f"an {'internal' if g2.internal else 'external'} helical pair needs {kind}: "
                    f"gear 1 has {g1.helix_angle:g} deg, so gear 2 needs {want:g} deg; got "
                    f"{g2.helix_angle:g} deg"
                )
            if g2.internal and g2.teeth <= g1.teeth:
                raise GearError(
                    f"a ring needs more teeth than its pinion: z2 = {g2.teeth} <= z1 = {g1.teeth}"
                )
        else:
            raise GearError(f"g2 must be a Gear or a Rack; got {g2!r}")
        object.__setattr__(self, "g1", g1)
        object.__setattr__(self, "g2", g2)
        object.__setattr__(self, "tip_shortening", bool(tip_shortening))
        if isinstance(g2, Gear):
            _ = self._geometry  # a working pressure angle exists (else the error names the sum)
            if not g2.internal and tip_shortening:
                self._require_tooth_after_shortening()

    def _require_tooth_after_shortening(self) -> None:
        """Refuse a pair whose DIN 3960 tip shortening would take the whole tooth of a gear (a
        large shift sum of either sign), naming the valid range of x1 + x2 (the constructor
        decides it once: a pair it accepts is checked, measured and drawn without raising)."""
        g1, g2 = self.g1, self.g2
        k = self.tip_alteration
        if all((g.tip_diameter - g.root_diameter) / (2 * g.module) + k > 0 for g in (g1, g2)):
            return
        total = g1.profile_shift + g2.profile_shift
        low, high = self.center_distance_range(g1, g2)

        def shift_sum(a: float) -> float:
            return float(center_distance_shift_sum(
                g1.teeth, g2.teeth, g1.module, a, g1.pressure_angle, g1.helix_angle
            ))  # fmt: skip

        least = shift_sum(low) if math.isfinite(low) else -math.inf
        most = shift_sum(high) if math.isfinite(high) else math.inf
        bound = f"x1 + x2 < {most:.4f}" if total > 0 else f"x1 + x2 > {least:.4f}"
        raise GearError(
            f"x1 + x2 = {total:g} is too {'large' if total > 0 else 'small'} for z = "
            f"{g1.teeth}/{g2.teeth}: the tip shortening k = {k:.4f} it needs (DIN 3960) would "
            f"take the whole tooth (or pass tip_shortening=False); valid is {bound}"
        )

    # --- construction ------------------------------------------------------------------------
    @classmethod
    def at_center_distance(
        cls, g1: Gear, g2: Gear, center_distance: float, split: str = "equal_sliding",
        tip_shortening: bool = True,
    ) -> GearPair:  # fmt: skip
        """The pair whose shifts give ``center_distance`` (mm), split between the gears.

        The sum x1 + x2 (a ring's x2 in the sign of DIN 3960) follows from the centre distance
        (:func:`center_distance_shift_sum`); ``split`` distributes it:

        * ``"equal_sliding"``: the maximum specific sliding of the two flanks is equal (the
          physically based choice; solved on the line of action);
        * ``"proportional"``: the DIN 3992 / ISO/TR 4467 style suggestion as approximated by
          Roloff/Matek, x1 = S/2 + (0.5 - S/2) lg(u) / lg(z1 z2 / 100) (Roloff/Matek; a
          suggestion, not a standard value; external pairs);
        * ``"keep"``: keep g1's shift, gear 2 takes the rest.

        Raises
        ------
        GearError
            If no shift reaches the centre distance, or for an unknown split.
        """
        if not isinstance(g2, Gear):
            raise GearError("at_center_distance needs two Gears (a rack has no centre distance)")
        zero = {"profile_shift": 0.0, "tip_alteration": 0.0}  # the shifts are replaced below
        cls(g1.with_(**zero), g2.with_(**zero))  # validates modules, hands, counts
        if split not in ("equal_sliding", "proportional", "keep"):
            raise GearError(f"split = {split!r}; valid are 'equal_sliding', 'proportional', 'keep'")
        low, high = cls.center_distance_range(g1, g2, tip_shortening)
        finite = isinstance(center_distance, numbers.Real) and not isinstance(center_distance, bool)
        a_w = float(center_distance) if finite else math.nan
        # the range ends are roots found to 1e-12: a pair's own centre distance next to an end
        # is the constructor's to judge, not the rounding's
        if not low * (1 - 1e-9) <= a_w <= high * (1 + 1e-9):
            raise GearError(
                f"center_distance = {center_distance!r} mm cannot be reached by profile shift for "
                f"z = {g1.teeth}/{g2.teeth}, m = {g1.module:g}; valid is {low:.6f} <= "
                f"center_distance <= {high:.6f} mm"
            )
        total = float(
            center_distance_shift_sum(
                g1.teeth, g2.teeth, g1.module, center_distance, g1.pressure_angle,
                g1.helix_angle, g2.internal,
            )
        )  # fmt: skip
        x1 = split_shift_sum(
            g1.teeth, g2.teeth, g1.module, total, g1.pressure_angle, g1.helix_angle,
            g2.internal, g1.rack.addendum, tip_shortening, split, g1.profile_shift,
        )  # fmt: skip
        x2 = total - x1  # x1 + x2 = S, a ring's x2 too (DIN 3960)
        try:
            return cls(
                g1.with_(profile_shift=x1, tip_alteration=0.0),
                g2.with_(profile_shift=x2, tip_alteration=0.0),
                tip_shortening,
            )
        except GearError as exc:
            raise GearError(
                f"center_distance = {a_w:g} mm with split = {split!r} needs x1 = {x1:.4f}, "
                f"x2 = {x2:.4f}, which no real gear has ({exc}); try another split"
            ) from None

    @staticmethod
    def center_distance_range(
        g1: Gear, g2: Gear, tip_shortening: bool = True
    ) -> tuple[float, float]:
        """The centre distances profile shift can reach, ``(low, high)`` in mm.

        ``low`` is a_d cos(alpha_t) (working pressure angle 0, ISO 21771). The DIN 3960
        tip shortening k = y - (x1 + x2) <= 0 of an external pair grows on both sides of a zero
        shift sum; where it would take the whole tooth (k = -(h_a* + h_f*)) no tooth is left,
        which bounds ``high`` (and, for large tooth sums, ``low``). Internal pairs (and pairs
        without tip shortening) have no upper bound (``inf``).

        >>> low, high = GearPair.center_distance_range(Gear(12, 3), Gear(24, 3))
        >>> round(low, 4), round(high, 4)
        (50.7434, 66.5654)
        """
        whole = min(g.rack.addendum + g.rack.dedendum for g in (g1, g2))
        return center_distance_reach(
            g1.teeth, g2.teeth, g1.module, g1.pressure_angle, g1.helix_angle, g2.internal,
            bool(tip_shortening), whole,
        )  # fmt: skip

    # --- basic quantities ----------------------------------------------------------------------
    @property
    def internal(self) -> bool:
        """True when gear 2 is a ring."""
        return isinstance(self.g2, Gear) and self.g2.internal

    @property
    def is_rack(self) -> bool:
        return isinstance(self.g2, Rack)

    @property
    def _sigma(self) -> float:
        return -1.0 if self.internal else 1.0

    @cached_property
    def _geometry(self) -> PairGeometry:
        g1, g2 = self.g1, self.g2
        s = self._sigma
        at = math.radians(g1.transverse_pressure_angle)
        total = g1.profile_shift + g2.profile_shift  # a ring's x2 in DIN 3960's sign
        zs = g1.teeth + s * g2.teeth  # DIN 3960: z2 < 0 for a ring
        if 2 * math.tan(math.radians(g1.pressure_angle)) * total / zs + float(inv(at)) < 0:
            limit = -zs * float(inv(at)) / (2 * math.tan(math.radians(g1.pressure_angle)))
            too, rel = ("large", "<") if self.internal else ("negative", ">")
            raise GearError(
                f"x1 + x2 = {total:g} is too {too} for {g1.teeth}/{g2.teeth} teeth"
                f"{' (internal)' if self.internal else ''}: no working pressure angle exists "
                f"(inv alpha_wt < 0); valid is x1 + x2 {rel} {limit:.4f}"
            )
        return pair_geometry(
            g1.teeth, g2.teeth, g1.module, g1.profile_shift, g2.profile_shift,
            g1.pressure_angle, g1.helix_angle, g2.internal, g1.rack.addendum,
            self.tip_shortening,
        )  # fmt: skip

    @property
    def working_pressure_angle(self) -> float:
        """Working transverse pressure angle alpha_wt in degrees."""
        if self.is_rack:
            return self.g1.transverse_pressure_angle
        return float(self._geometry.working_pressure_angle)

    @property
    def center_distance(self) -> float:
        """Working centre distance a_w in mm (rack: from the pinion axis to the rack's reference
        line, r1 + x1 m_n)."""
        if self.is_rack:
            return self.g1.reference_diameter / 2 + self.g1.profile_shift * self.g1.module
        return float(self._geometry.center_distance)

    @property
    def reference_center_distance(self) -> float:
        """a_d = m_n (z2 +- z1) / (2 cos beta): the centre distance of the zero-shift pair."""
        if self.is_rack:
            return self.g1.reference_diameter / 2
        s = self._sigma
        return abs(self.g1.reference_diameter + s * self.g2.reference_diameter) / 2

    @property
    def center_distance_modification(self) -> float:
        """y = (a_w - a_d) / m_n."""
        if self.is_rack:
            return self.g1.profile_shift
        return float(self._geometry.center_distance_modification)

    @property
    def tip_alteration(self) -> float:
        """k = y - (x1 + x2) when negative (external pairs with tip shortening), else 0."""
        return 0.0 if self.is_rack else float(self._geometry.tip_alteration)

    @cached_property
    def mounted(self) -> tuple[Gear, Gear | Rack]:
        """The gears as mounted in this pair: ``g1`` and ``g2`` (the gears as given) with the
        pair's tip shortening k added to each gear's own ``tip_alteration``. Every quantity of
        the pair (tip diameters, contact ratio, :meth:`check`) is of these; measure a gear as
        mounted with ``pair.mounted[0].chordal_thickness()``, as given with ``pair.g1``."""
        k = self.tip_alteration
        if k == 0.0:
            return self.g1, self.g2
        g1, g2 = self.g1, self.g2
        return (
            g1.with_(tip_alteration=g1.tip_alteration + k),
            g2.with_(tip_alteration=g2.tip_alteration + k),
        )

    @property
    def tip_diameters(self) -> tuple[float, float]:
        """Tip diameters of the gears as mounted (after tip shortening and each gear's own tip
        alteration); a rack's is ``inf``."""
        m1, m2 = self.mounted
        if self.is_rack:
            return m1.tip_diameter, math.inf
        return m1.tip_diameter, m2.tip_diameter

    @property
    def working_diameters(self) -> tuple[float, float]:
        """Working pitch diameters d_w = d_b / cos alpha_wt."""
        if self.is_rack:
            return self.g1.reference_diameter, math.inf
        return float(self._geometry.working_diameter_1), float(self._geometry.working_diameter_2)

    @property
    def ratio(self) -> float:
        """Gear ratio u = z2 / z1 (speed ratio ``|w1 / w2|``); ``inf`` for a rack."""
        return math.inf if self.is_rack else self.g2.teeth / self.g1.teeth

    # --- contact ---------------------------------------------------------------------------------
    @cached_property
    def path_of_contact(self) -> PathOfContact:
        """Start, end, pitch point and N2 on the line of action (mm from N1)."""
        g1 = self.g1
        rb1 = g1.base_diameter / 2
        ra1 = self.tip_diameters[0] / 2
        self._require_tip_above_base(1, ra1, rb1)
        at = math.radians(self.working_pressure_angle)
        tw = math.tan(at)
        pb = g1.base_pitch
        if self.is_rack:
            # The rack's tip line (h_a - x1 m above the pitch line... measured from the
            # pinion's reference line) cuts the line of action at (h_a - x1) m / sin(alpha_t)
            # before the pitch point (ISO 21771, the rack's contact ratio).
            h = (self.g2.addendum - g1.profile_shift) * g1.module
            u_c = rb1 * tw
            start = u_c - h / math.sin(at)
            end = math.sqrt(ra1 * ra1 - rb1 * rb1)
            return PathOfContact(start, end, u_c, math.inf, pb)
        rb2 = self.g2.base_diameter / 2
        ra2 = self.tip_diameters[1] / 2
        self._require_tip_above_base(2, ra2, rb2)
        u_a, u_e, u_n2 = line_positions(ra1, ra2, rb1, rb2, tw, self._sigma)
        return PathOfContact(float(u_a), float(u_e), rb1 * tw, float(u_n2), pb)

    def _require_tip_above_base(self, which: int, ra: float, rb: float) -> None:
        if ra < rb:
            raise GearError(
                f"gear {which}'s tip circle (d_a = {2 * ra:.4f} mm) lies inside its base circle "
                f"(d_b = {2 * rb:.4f} mm): there is no involute to mesh; raise the tip "
                f"(internal gears: a negative shift or more teeth)"
            )

    @property
    def contact_ratio(self) -> float:
        """Transverse contact ratio epsilon_alpha (Ozols 21.12; ISO 21771)."""
        p = self.path_of_contact
        return max(p.length, 0.0) / p.base_pitch  # tips too short to meet: no contact

    @property
    def overlap_ratio(self) -> float:
        """epsilon_beta = ``b sin(abs(beta)) / (pi m_n)`` (Ozols 21.31); b = the smaller face width.

        Raises :class:`GearError` when neither gear has a face width.
        """
        widths = [w for w in (self.g1.face_width, getattr(self.g2, "face_width", None)) if w]
        if not widths:
            raise GearError("overlap_ratio needs a face_width on g1 or g2")
        b = min(widths)
        return b * abs(math.sin(math.radians(self.g1.helix_angle))) / (math.pi * self.g1.module)

    @property
    def total_contact_ratio(self) -> float:
        """epsilon_gamma = epsilon_alpha + epsilon_beta (epsilon_beta = 0 for spur gears)."""
        if self.g1.helix_angle == 0:
            return self.contact_ratio
        return self.contact_ratio + self.overlap_ratio

    def specific_sliding(
        self, u: ArrayLike | None = None, n: int = 101
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Specific sliding ``(u, zeta_1, zeta_2)`` along the path of contact.

        ``u`` are positions in mm from N1 (default: ``n`` points from start to end).
        """
        p = self.path_of_contact
        u = np.linspace(p.start, p.end, n) if u is None else np.asarray(u, float)
        if self.is_rack:
            # rack flank: straight (rho_2 = inf); the limit of the gear formula as z2 -> inf
            u_c = p.pitch_point
            with np.errstate(divide="ignore"):
                return u, 1.0 - u_c / u, 1.0 - u / u_c
        rb1 = self.g1.base_diameter / 2
        rb2 = self.g2.base_diameter / 2
        tw = math.tan(math.radians(self.working_pressure_angle))
        z1_, z2_ = specific_sliding(u, rb1, rb2, tw, self.ratio, self.internal)
        return u, z1_, z2_

    @property
    def max_specific_sliding(self) -> tuple[float, float]:
        """Largest ``|specific sliding|`` of each flank: gear 1 at the contact start (its root),
        gear 2 at the contact end (its root)."""
        p = self.path_of_contact
        _, a1, _ = self.specific_sliding([p.start])
        _, _, e2 = self.specific_sliding([p.end])
        return float(abs(a1[0])), float(abs(e2[0]))

    def mesh_efficiency(self, friction: float = 0.1) -> float:
        """Ozols (14.25): 1 - (pi f eps_alpha / 2)(1/z1 +- 1/z2) (rack: 1/z2 = 0)."""
        z2 = math.inf if self.is_rack else self.g2.teeth
        return float(
            mesh_efficiency(self.g1.teeth, z2, self.contact_ratio, friction, self.internal)
        )

    # --- forces ----------------------------------------------------------------------------------
    def forces(self, torque: float, friction: float = 0.0) -> PairForces:
        """The mesh forces under ``torque`` N m on gear 1, signed about its axis
        (:func:`gears.forces.pair_forces`; ``friction``: Ozols (21.17), spur pairs).

        >>> f = GearPair(Gear(20, 5), Gear(40, 5)).forces(100)    # Ozols section 11-2
        >>> round(f.normal[0], 2), round(f.torque_2, 6)     # R = M1 / (r1 cos alpha), M2
        (2128.36, 200.0)
        """
        return pair_forces(self, torque, friction)

    def efficiency(
        self, torque: float, speed: float, *, face_width: float | None = None,
        roughness: float | tuple[float, float] = 1.0, viscosity: float = 30.0,
        lubricant: str | float = "mineral",
    ) -> MeshLosses:  # fmt: skip
        """The load-dependent mesh loss and efficiency, ISO/TR 14179-2 (docs/rating.md).

        eta_z = 1 - mu_mz H_V: the loss factor H_V of this pair's path of contact and the mean
        coefficient of friction mu_mz from the load, the speed, the roughness and the oil
        (:mod:`gears.rating.losses`). Churning, windage and bearing losses are not counted.

        Parameters
        ----------
        torque : float
            Torque on gear 1, N m (> 0).
        speed : float
            Speed of gear 1 relative to the carrier, rpm (> 0).
        face_width : float, optional
            b in mm (default: the smaller of the gears' face widths).
        roughness : float or pair
            Flank roughness Ra of the gears, um (their mean is used).
        viscosity : float
            Dynamic viscosity of the oil at its working temperature, mPa s (an ISO VG 220
            mineral oil near 80 deg C has roughly 25 mPa s).
        lubricant : str or float
            Base oil (:data:`gears.rating.losses.LUBRICANT_FACTORS`) or the factor X_L.

        Returns
        -------
        MeshLosses
            ``efficiency``, ``loss_factor`` (H_V), ``friction`` (mu_mz), ``power_loss`` (W).

        Examples
        --------
        >>> p = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))
        >>> m = p.efficiency(torque=200, speed=1500)
        >>> round(float(m.efficiency), 4), round(float(m.loss_factor), 4)
        (0.9898, 0.1583)
        """
        from gears.rating.losses import pair_efficiency  # the rating family: when asked

        return pair_efficiency(self, torque, speed, self._face_width(face_width), roughness,
                               viscosity, lubricant)  # fmt: skip

    def _face_width(self, face_width: float | None) -> float:
        """b in mm: the given one, else the smaller of the gears' own."""
        if face_width is not None:
            return check_positive("face_width", face_width, "mm")
        widths = [w for w in (self.g1.face_width, getattr(self.g2, "face_width", None)) if w]
        if not widths:
            raise GearError("face_width: give one, or give the gears a face_width")
        return float(min(widths))

    # --- load capacity (ISO 6336) -----------------------------------------------------------------
    def rating(
        self, torque: float | None = None, speed: float | None = None,
        material: str | Material | tuple[str | Material, str | Material] = "case-carburized", *,
        spectrum: Sequence[tuple[float, float, float]] | None = None,
        life: float = 20000.0,
        application_factor: float = 1.0, quality: int = 6, roughness: float = 1.0,
        oil_viscosity: float = 220.0, tip_relief: float | None = None,
        sigma_Hlim: float | tuple[float, float] | None = None,
        sigma_Flim: float | tuple[float, float] | None = None, face_width: float | None = None,
        contacts: tuple[int, int] = (1, 1), idler: tuple[bool, bool] = (False, False),
        misalignment: float | None = None, root: str = "auto",
        root_roughness: float | None = None, scuffing: Oil | None = None,
        welding_factor: float = 1.0, edition: int = 2019, **factors,
    ) -> Rating | SpectrumRating:  # fmt: skip
        """ISO 6336 method B rating against pitting and tooth-root breakage (docs/rating.md).

        Parameters
        ----------
        torque : float
            Torque on gear 1, N m (> 0).
        speed : float
            Speed of gear 1, rpm (> 0).
        material : str, Material or pair
            ISO 6336-5 material (:data:`gears.rating.materials.MATERIALS`) of both gears, or a pair.
        life : float
            Required life, hours.
        application_factor : float
            K_A >= 1.
        quality : int
            ISO 1328 accuracy grade 1 ... 12.
        roughness : float
            Flank roughness Ra, um (0.01 ... 100).
        oil_viscosity : float
            nu_40 of the oil, mm^2/s.
        tip_relief : float, optional
            Tip relief C_a in mm, at most 0.1 m_n (default: the larger of the gears'
            ``modification.tip_relief``, else the running-in amount of ISO 6336-1).
        sigma_Hlim, sigma_Flim : float or pair, optional
            Allowable stress numbers replacing the material's, MPa.
        face_width : float, optional
            b in mm (default: the smaller of the gears' face widths).
        contacts, idler
            Meshes per turn of each gear and idler gears (planets): see
            :func:`gears.rating.iso6336.rate_pairs`.
        misalignment : float, optional
            F_betax in um, replacing the method C estimate of K_Hbeta.
        spectrum : list of (torque, speed, hours), optional
            A load spectrum (ISO 6336-6) instead of ``torque``, ``speed`` and ``life``: each bin
            rated on its own, then Miner's sum per gear and failure mode, the equivalent safety
            and the life (:mod:`gears.rating.spectrum`); returns a
            :class:`gears.rating.spectrum.SpectrumRating`.
        root : str
            How Y_F and Y_S find the root (:data:`gears.rating.capacity.ROOT_ROUTES`; by default
            measured on the real tooth of internal and shaper-cut gears).
        root_roughness : float, optional
            Roughness Ra of the root fillets, um, for Y_RrelT (default ``roughness``: give it
            for a ground flank with a hobbed root).
        scuffing : Oil, optional
            The oil (:class:`gears.rating.scuffing.Oil`: FZG load stage, temperature,
            viscosities): the rating adds the safety against scuffing by the flash temperature
            method (ISO/TS 6336-20) and the integral temperature method (ISO/TS 6336-21),
            ``safety_scuffing``, ``temperatures`` and the findings ``scuffing_flash``,
            ``scuffing_integral`` of ``check()``.
        welding_factor : float
            X_W of the flanks for the scuffing temperatures (1: case-carburized, as the FZG
            test gears).
        edition : {2019, 2006}
            ISO 6336-1/-2/-3's edition (:data:`gears.rating.bending.EDITIONS`: Y_F and Y_beta
            differ); 2006 is the one of ISO/TR 6336-30:2017's worked examples.
        **factors
            Any factor by its ISO symbol (``K_v=1.0``, ``K_Hbeta=1.16``, ``Y_F=(2.1, 2.2)``)
            replaces the computed one (:data:`gears.rating.iso6336.FACTORS`); ``K_Hbeta`` and
            ``K_Halpha`` may be ``"contact"``: from the loaded contact analysis
            (:meth:`contact`) at the torque times K_A, with ``misalignment`` as F_betax.

        Returns
        -------
        Rating
            ``safety_pitting``, ``safety_bending``, ``stresses``, ``factors``, ``check()``.

        Raises
        ------
        GearError
            For bad input, naming it, or where a method does not apply (e.g. a pointed tip).

        Examples
        --------
        >>> p = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))
        >>> r = p.rating(torque=200, speed=1500)
        >>> [round(s, 3) for s in r.safety_pitting], [round(s, 3) for s in r.safety_bending]
        ([1.053, 1.161], [3.287, 3.563])
        """
        from gears.rating.capacity import rate_pair, rate_pair_spectrum  # loaded when rated

        if tip_relief is None:  # the gears' own tip relief, the larger (ISO 6336-1 C_a)
            reliefs = [m.tip_relief for g in (self.g1, self.g2)
                       if (m := getattr(g, "modification", None)) is not None]  # fmt: skip
            tip_relief = max(reliefs) if any(reliefs) else None
        options = dict(application_factor=application_factor, quality=quality,
                       roughness=roughness, oil_viscosity=oil_viscosity, tip_relief=tip_relief,
                       sigma_Hlim=sigma_Hlim, sigma_Flim=sigma_Flim, face_width=face_width,
                       contacts=contacts, idler=idler, misalignment=misalignment, root=root,
                       root_roughness=root_roughness, scuffing=scuffing,
                       welding_factor=welding_factor, edition=edition, **factors)  # fmt: skip
        if spectrum is not None:
            if torque is not None or speed is not None:
                raise GearError("give either torque and speed or spectrum=, not both")
            return rate_pair_spectrum(self, spectrum, material, **options)
        if torque is None or speed is None:
            raise GearError("rating needs torque (N m) and speed (rpm), or spectrum=")
        if "contact" in (factors.get("K_Hbeta"), factors.get("K_Halpha")):
            from gears.contact.result import rating_factors

            options.update(rating_factors(self, torque * application_factor, misalignment,
                                          factors))  # fmt: skip
        return rate_pair(self, torque, speed, material, life=life, **options)

    # --- loaded tooth contact analysis ---------------------------------------------------------
    def contact(
        self, torque: float, *, misalignment: float = 0.0, f_ma: float = 0.0, f_sh: float = 0.0,
        positions: int = 64, slices: int = 30, center_distance_error: float = 0.0,
        modulus: float = 206000.0, poisson: float = 0.3,
    ) -> Contact:  # fmt: skip
        """The loaded tooth contact analysis under ``torque`` (N m on gear 1) over one mesh
        cycle: transmission error, mesh stiffness, load sharing, contact pattern, K_Hbeta and
        K_Halpha (:func:`gears.contact.result.contact`; the gears' ``modification`` apply;
        external and internal pairs; ``misalignment`` or its parts ``f_ma`` and ``f_sh``, mm
        over the face in the plane of action).

        >>> p = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))
        >>> c = p.contact(300)
        >>> round(c.mean_mesh_stiffness, 2), round(c.peak_to_peak, 2)   # N/(mm um), um
        (17.75, 12.7)
        """
        from gears.contact.result import contact

        return contact(self, torque, misalignment=misalignment, f_ma=f_ma, f_sh=f_sh,
                       positions=positions, slices=slices, modulus=modulus, poisson=poisson,
                       center_distance_error=center_distance_error)  # fmt: skip

    def harris(
        self, torques: ArrayLike, reliefs: ArrayLike, *, relief_length: float | None = None,
        kind: str = "linear", positions: int = 64, slices: int | None = None,
    ) -> HarrisMap:  # fmt: skip
        """The Harris map: transmission error peak to peak over tip ``reliefs`` (mm, both
        gears) and ``torques`` (N m on gear 1) (:func:`gears.contact.result.harris`)."""
        from gears.contact.result import harris

        return harris(self, torques, reliefs, relief_length=relief_length, kind=kind,
                      positions=positions, slices=slices)  # fmt: skip

    def best_modification(self, torque: float, **options) -> ModificationSearch:
        """The tip relief (both gears) and crowning (gear 1) of the least transmission error
        peak to peak at the design ``torque``, N m on gear 1 (``options``: the grids, tilt
        and limits of :func:`gears.contact.result.best_modification`)."""
        from gears.contact.result import best_modification

        return best_modification(self, torque, **options)

    # --- checks ----------------------------------------------------------------------------------
    def outlines(
        self, angle: float = 0.0, tolerance: float = 0.001, method: str = "analytic",
        backlash: float = 0.0, cutter: ShaperCutter | tuple | None = None,
        progress: Callable[[int, int], object] | None = None,
    ) -> tuple[shapely.Polygon, shapely.Polygon]:  # fmt: skip
        """Both outlines in mesh: gear 1 at the origin turned by ``angle`` degrees, gear 2 at the
        working centre distance (see :func:`gears.cutting.outline.pair_outlines`; ``cutter`` is a
        shaper cutter for both gears or a pair of them; ``progress(done, total)`` follows a
        simulation of both)."""
        from gears.cutting.outline import pair_outlines  # the cutting family: when drawn

        return pair_outlines(self, angle, tolerance, method, backlash, cutter, progress)

    def scene(
        self, angle: float = 0.0, face_width: float | None = None, tolerance: float = 0.01,
        method: str = "analytic", backlash: float = 0.0, herringbone: bool = False,
        cutter: ShaperCutter | tuple | None = None,
        progress: Callable[[int, int], object] | None = None,
    ) -> trimesh.Scene:  # fmt: skip
        """Both gears as a ``trimesh.Scene`` in mesh (nodes ``gear1``, ``gear2``, coloured).

        Gear 1 sits at the origin turned by ``angle`` degrees, gear 2 at the working centre
        distance turned as :meth:`outlines` turns it (:func:`gears.cutting.outline.pair_placement`);
        each solid is :meth:`Gear.mesh` of the mounted gear, so a helical pair's hands
        (opposite for external, the same for internal) carry into the twist. ``face_width``
        defaults to each gear's own, else 10 modules; ``progress(done, total)`` follows a
        simulated outline. Every argument is checked and the scene's size (both solids)
        estimated before any work: over the mesh budget it is refused with the tolerance that
        fits (:data:`gears.budget.BUDGETS`).

        Examples
        --------
        >>> p = GearPair(Gear(12, 2, helix_angle=15), Gear(30, 2, helix_angle=-15))
        >>> sorted(p.scene(tolerance=0.05).graph.nodes_geometry)
        ['gear1', 'gear2']
        """
        from gears.pair_drawing import pair_scene  # drawn: the solids load here

        return pair_scene(
            self, angle, face_width, tolerance, method, backlash, herringbone, cutter, progress
        )

    def animate(
        self, path: str | os.PathLike[str], frames: int = 48, fps: float = 20.0,
        turn: float | None = None, tolerance: float = 0.02, method: str = "analytic",
        backlash: float = 0.0, cutter: ShaperCutter | tuple | None = None,
        progress: Callable[[int, int], object] | None = None,
    ) -> pathlib.Path:  # fmt: skip
        """Write a GIF (or MP4 with ffmpeg) of both outlines in mesh while gear 1 turns by
        ``turn`` degrees (default one mesh cycle, ``360 / z1``), gear 2 placed as
        :meth:`outlines` places it; ``progress(i, n)`` after each frame
        (:func:`gears.solid.animate.write_animation`). Every argument (the file's folder too) is
        checked and the drawing's size (frames times outline vertices) estimated before any
        work: over the animation budget it is refused with the tolerance that fits."""
        from gears.pair_drawing import pair_animation  # drawn: the solids load here

        return pair_animation(
            self, path, frames, fps, turn, tolerance, method, backlash, cutter, progress
        )

    def check(self, min_contact_ratio: float = 1.1, min_tip_land: float = 0.2) -> Report:
        """Both gears' findings (prefixed ``g1.``/``g2.``) plus ``contact_ratio``,
        ``tip_interference`` and, for internal pairs, ``involute_interference``,
        ``trochoid_interference``, ``radial_interference`` and ``ring_tip_above_base``.
        ``min_contact_ratio`` and ``min_tip_land`` are finite and >= 0."""
        min_contact_ratio = check_real("min_contact_ratio", min_contact_ratio, 0.0, low_open=False)
        min_tip_land = check_real("min_tip_land", min_tip_land, 0.0, low_open=False)
        m1, m2 = self.mounted
        findings = list(m1.check(min_tip_land).prefixed("g1").values())
        if not self.is_rack:
            findings += list(m2.check(min_tip_land).prefixed("g2").values())
        try:
            eps = self.contact_ratio
        except GearError as exc:
            findings.append(Finding("contact_ratio", -min_contact_ratio, str(exc), unit=""))
            return Report(findings)
        findings.append(
            Finding(
                "contact_ratio", eps - min_contact_ratio,
                f"transverse contact ratio {eps:.4f} vs required {min_contact_ratio:g}", unit="",
            )
        )  # fmt: skip
        findings.extend(interference_findings(self))
        return Report(findings)

    @cached_property
    def _form_lengths(self) -> tuple[float, float]:
        """Distances along the line of action from N1 to gear 1's form circle and from N2 to
        gear 2's (0 for a rack): sqrt(r_Ff^2 - r_b^2) (:func:`gears.checks.form_lengths`)."""
        lengths = []
        for g in self.mounted:
            if isinstance(g, Rack):
                lengths.append(0.0)
                continue
            lengths.append(float(form_lengths(g._form, g.base_diameter, g.tip_diameter)))
        return lengths[0], lengths[1]

    @cached_property
    def tip_diameter_limits(self) -> tuple[float, float]:
        """Tip diameters at which each gear's tip meets its mate's flank exactly at the mate's
        form circle: ``(largest d_a1, limit of d_a2)``. The limit of d_a2 is a largest diameter
        for an external gear 2 and a smallest one for a ring (a ring tip reaches deeper than a
        rack's tip line and is relieved by enlarging d_a2); for a rack it is the largest rack
        addendum in mm. A tip beyond its limit reaches the mate's fillet (``tip_interference``).
        """
        p = self.path_of_contact
        g1, g2 = self.mounted
        u_f1, l2 = self._form_lengths
        if self.is_rack:
            # the rack's tip line cuts the line of action (u_C - u) sin(alpha) above the pitch line
            angle = math.radians(self.working_pressure_angle)
            return math.inf, (p.pitch_point - u_f1) * math.sin(angle)
        rb1, rb2 = g1.base_diameter / 2, g2.base_diameter / 2
        limit1, limit2 = tip_diameter_limits(rb1, rb2, p.n2, u_f1, l2, self.internal)
        return float(limit1), float(limit2)

    def _repr_svg_(self) -> str:
        """Both gears in mesh with the line of action as an SVG picture, what a notebook shows
        (:func:`gears.figures.drawing.pair_svg`; a text instead when it cannot be drawn)."""
        from gears.figures.drawing import pair_svg  # drawn in a notebook only

        return pair_svg(self, (COLOURS["gear1"], COLOURS["gear2"]))
