"""Layer 1, base: gear materials for the load-capacity rating (ISO 6336-5) and their groups.

A :class:`Material` carries what ISO 6336 needs of a gear's material: the allowable stress
numbers ``sigma_Hlim`` (contact) and ``sigma_Flim`` (bending), Young's modulus, Poisson's ratio,
density, hardness and its ISO 6336 material group (``kind``), which selects the life curves
(ISO 6336-2 Table 2 for Z_NT, ISO 6336-3 Table 3 for Y_NT: :mod:`gears.rating.life`), the
running-in allowances of ISO 6336-1, the notch sensitivity (slip-layer thickness rho',
ISO 6336-3 Table 4), the root surface factor and the size factor (the group tables below, indexed
by :func:`kind_code`).

The named materials (:data:`MATERIALS`) are each one point of ISO 6336-5; its ``source`` says
which. ``Material(...)`` makes your own; an unknown name is refused with the known names.

ISO 6336 material groups (``kind``): ``"St"`` normalized structural steel, ``"V"``
through-hardened (quenched and tempered) steel, ``"GGG"`` nodular (pearlitic/bainitic) cast iron,
``"GG"`` grey cast iron, ``"Eh"`` case-hardened (carburized) steel, ``"IF"`` induction- or
flame-hardened steel, ``"NT"`` nitrided steel, ``"NV"`` nitrocarburized steel.

Examples
--------
>>> m = material("case-carburized")
>>> m.sigma_Hlim, m.sigma_Flim, m.kind
(1500.0, 500.0, 'Eh')
>>> material("brass")                                   # doctest: +ELLIPSIS
Traceback (most recent call last):
...
gears.errors.GearError: material = 'brass' is not known; the known materials are ...
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, replace

import numpy as np

from gears.errors import GearError

__all__ = [
    "KINDS",
    "MATERIALS",
    "Material",
    "kind_code",
    "material",
]

#: ISO 6336 material groups, in the order of their integer codes (:func:`kind_code`).
KINDS = ("St", "V", "GGG", "GG", "Eh", "IF", "NT", "NV")


def _by_kind(mapping):
    return np.array([mapping[k] for k in KINDS])


# What the rating's formulas ask of a material group, indexed by its code: surface-hardened
# (running-in of ISO 6336-1 §8.3.3, Z_W of ISO 6336-2 §12), grey cast iron (running-in), the
# class of Y_RrelT (ISO 6336-3 §14: 0 V, GGG, Eh, IF; 1 St; 2 GG, NT, NV) and of Y_X
# (ISO 6336-3 §15: 0 St, V, GGG; 1 Eh, IF, NT, NV; 2 GG).
HARDENED = _by_kind({"St": 0, "V": 0, "GGG": 0, "GG": 0, "Eh": 1, "IF": 1, "NT": 1, "NV": 1})
GREY_IRON = _by_kind({"St": 0, "V": 0, "GGG": 0, "GG": 1, "Eh": 0, "IF": 0, "NT": 0, "NV": 0})
ROOT_SURFACE_CLASS = _by_kind({"St": 1, "V": 0, "GGG": 0, "GG": 2, "Eh": 0, "IF": 0, "NT": 2,
                               "NV": 2})  # fmt: skip
SIZE_CLASS = _by_kind({"St": 0, "V": 0, "GGG": 0, "GG": 2, "Eh": 1, "IF": 1, "NT": 1, "NV": 1})


@dataclass(frozen=True)
class Material:
    """A gear material (lengths in mm, stresses in N/mm^2 = MPa).

    Parameters
    ----------
    name : str
        Label shown in reports.
    kind : str
        The ISO 6336 material group, one of :data:`KINDS` (see the module docstring).
    sigma_Hlim : float
        Allowable contact stress number, MPa (ISO 6336-5), > 0.
    sigma_Flim : float
        Nominal stress number for bending, MPa (ISO 6336-5; sigma_FE = 2 sigma_Flim), > 0.
    youngs_modulus : float
        E, MPa (206 000 for steel).
    poisson : float
        nu, 0 < nu < 0.5.
    density : float
        kg/mm^3 (7.83e-6 for steel), for the reduced mass of the dynamic factor K_v.
    hardness : float
        Surface hardness HB (for Z_W of a soft gear against a hardened one), > 0.
    slip_layer : float or None
        rho', the slip-layer thickness in mm for the relative notch sensitivity Y_deltarelT
        (ISO 6336-3 Table 4); None takes the group's value.
    source : str
        Where the numbers come from.
    """

    name: str
    kind: str
    sigma_Hlim: float
    sigma_Flim: float
    youngs_modulus: float = 206000.0
    poisson: float = 0.3
    density: float = 7.83e-6
    hardness: float = 600.0
    slip_layer: float | None = None
    source: str = "user"

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise GearError(f"material kind = {self.kind!r}; valid are {', '.join(KINDS)}")
        checks = (
            ("sigma_Hlim", 0.0, 1e5),
            ("sigma_Flim", 0.0, 1e5),
            ("youngs_modulus", 0.0, 1e7),
            ("poisson", 0.0, 0.5),
            ("density", 0.0, 1e-4),
            ("hardness", 0.0, 1e4),
        )
        for name, low, high in checks:
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, numbers.Real):
                raise GearError(f"material {name} = {value!r}; valid is a number")
            v = float(value)
            if not (math.isfinite(v) and low < v < high):
                raise GearError(
                    f"material {name} = {value!r}; valid is {low:g} < {name} < {high:g}"
                )
            object.__setattr__(self, name, v)
        if self.slip_layer is None:
            object.__setattr__(self, "slip_layer", _SLIP_LAYER[self.kind])
        else:
            v = float(self.slip_layer) if isinstance(self.slip_layer, numbers.Real) else math.nan
            if not (math.isfinite(v) and 0.0 <= v < 10.0):
                raise GearError(
                    f"material slip_layer = {self.slip_layer!r}; valid is 0 <= rho' < 10 mm"
                )
            object.__setattr__(self, "slip_layer", v)

    @property
    def code(self) -> int:
        """The integer code of :attr:`kind` (its index in :data:`KINDS`)."""
        return KINDS.index(self.kind)

    def with_limits(
        self, sigma_Hlim: float | None = None, sigma_Flim: float | None = None
    ) -> Material:
        """The same material with other allowable stress numbers (None keeps a value)."""
        return replace(
            self,
            sigma_Hlim=self.sigma_Hlim if sigma_Hlim is None else sigma_Hlim,
            sigma_Flim=self.sigma_Flim if sigma_Flim is None else sigma_Flim,
        )


# rho' of ISO 6336-3 Table 4 (slip-layer thickness, mm), per group at a typical strength:
# Eh/IF 0.0030; NT/NV 0.1005; V/GGG at sigma_0.2 = 800 MPa 0.0064; St at sigma_S = 300 MPa 0.0833;
# GG at sigma_B = 300 MPa 0.3095.
_SLIP_LAYER = {
    "St": 0.0833, "V": 0.0064, "GGG": 0.0064, "GG": 0.3095,
    "Eh": 0.0030, "IF": 0.0030, "NT": 0.1005, "NV": 0.1005,
}  # fmt: skip

_STEEL = {"youngs_modulus": 206000.0, "poisson": 0.3, "density": 7.83e-6}

_INDUCTION = Material(
    "induction-hardened",
    "IF",
    1200.0,
    370.0,
    hardness=560.0,
    **_STEEL,
    source="ISO 6336-5 induction- or flame-hardened steel, MQ at 560 HV: sigma_Hlim "
    "1200, sigma_Flim 370",
)

#: The named materials: one point of ISO 6336-5 each (quality MQ), its ``source`` says which.
MATERIALS: dict[str, Material] = {
    m.name: m
    for m in (
        Material(
            "case-carburized",
            "Eh",
            1500.0,
            500.0,
            hardness=700.0,
            **_STEEL,
            source="ISO 6336-5 case-hardened wrought steel, MQ (core >= 30 HRC): sigma_Hlim "
            "1500, sigma_Flim 500; E, nu and sigma_Hlim as in ISO/TR 6336-30 Ex. 1 (16MnCr5)",
        ),
        Material(
            "nitrided",
            "NT",
            1250.0,
            420.0,
            hardness=650.0,
            **_STEEL,
            source="ISO 6336-5 nitriding steel, gas-nitrided, MQ: sigma_Hlim 1250, sigma_Flim 420",
        ),
        _INDUCTION,
        replace(_INDUCTION, name="flame-hardened"),  # one ISO 6336-5 point for both
        Material(
            "through-hardened",
            "V",
            767.0,
            315.0,
            hardness=285.0,
            **_STEEL,
            source="ISO 6336-5 through-hardened alloy steel, MQ lines sigma_Hlim = 1.313 HV + 373 "
            "and sigma_Flim = 0.425 HV + 187 at 300 HV",
        ),
        Material(
            "nodular-cast-iron",
            "GGG",
            600.0,
            300.0,
            youngs_modulus=173000.0,
            poisson=0.3,
            density=7.1e-6,
            hardness=250.0,
            source="ISO 6336-5 nodular (pearlitic) cast iron, MQ near 250 HB: sigma_Hlim 600, "
            "sigma_Flim 300; E 173 000",
        ),
        Material(
            "grey-cast-iron",
            "GG",
            370.0,
            100.0,
            youngs_modulus=118000.0,
            poisson=0.3,
            density=7.2e-6,
            hardness=220.0,
            source="ISO 6336-5 grey cast iron, MQ near 220 HB: sigma_Hlim 370, sigma_Flim 100; "
            "E 118 000",
        ),
    )
}


def material(value) -> Material:
    """A :class:`Material` from a name of :data:`MATERIALS` or a Material (returned as is).

    Raises
    ------
    GearError
        For an unknown name, listing the known names.
    """
    if isinstance(value, Material):
        return value
    if isinstance(value, str) and value in MATERIALS:
        return MATERIALS[value]
    raise GearError(
        f"material = {value!r} is not known; the known materials are {', '.join(MATERIALS)} "
        "(or pass gears.rating.materials.Material(...))"
    )


def kind_code(kind) -> np.ndarray:
    """Integer codes (indices into :data:`KINDS`) of material group names (array in, out)."""
    names = np.asarray(kind)
    out = np.empty(names.shape, int)
    for i, name in enumerate(KINDS):
        out[names == name] = i
    known = np.isin(names, KINDS)
    if not np.all(known):
        bad = np.ravel(names)[np.argmax(~np.ravel(known))]
        raise GearError(f"material kind = {bad!r}; valid are {', '.join(KINDS)}")
    return out
