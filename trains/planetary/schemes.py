"""Layer 2, planetary: the stage schemes and their exact tooth-count arithmetic.

The five mesh topologies of a planetary (2K-H) stage, their basic ratio, the ratio with any member
held, the assembly number, the mesh phasing class and the coaxial ring, as integer functions
vectorised over numpy arrays (no floats anywhere), and the mesh tables a
:class:`~trains.planetary.stage.Planetary` builds its gears from.

A stage has two central gears, called ``sun`` (central gear *a*, lectures' link 1) and ``ring``
(central gear *b*, link 3) whatever their kind, a carrier, and ``n_planets`` identical planets
(or planet pairs). The mesh topology is the ``scheme`` (lectures §4.2 / Arnaudov & Karaivanov; the
letters differ between authors, so the code names schemes by topology and keeps the letters as
aliases):

==================  ===================================  =========================  ==========
scheme              meshes                               basic ratio i0 = i_13^(H)  alias
==================  ===================================  =========================  ==========
``simple``          sun-planet ext, planet-ring int      -z3/z1                     A, james
``stepped``         sun-planet ext, planet'-ring int     -z2 z3 / (z1 z2')          B
``external``        sun-planet ext, planet'-ring ext     +z2 z3 / (z1 z2')          C, david
``internal``        sun(ring)-planet int, planet'-ring   +z2 z3 / (z1 z2')          D
``double-planet``   sun-planet ext, planet-planet2 ext,  +z3/z1
                    planet2-ring int
==================  ===================================  =========================  ==========

Ratios follow from the Willis relation ``w_sun - i0 w_ring - (1 - i0) w_carrier = 0``
(Ozols (7.6), (7.7)) and are exact :class:`fractions.Fraction`\\ s.
"""

from __future__ import annotations

import math
from fractions import Fraction
from typing import Any

import numpy as np

from trains.conditions import assembly_number
from trains.errors import TrainError

__all__ = [
    "SCHEMES",
    "assembly_ticks",
    "basic_ratio",
    "canonical_scheme",
    "coaxial_ring_teeth",
    "phasing_class",
    "stage_ratio",
    "textbook_assembly",
]

#: The stage schemes a :class:`Planetary` takes (``scheme=``).
SCHEMES = ("simple", "stepped", "external", "internal", "double-planet")
_ALIASES = {
    "a": "simple", "james": "simple", "sun-planet-ring": "simple",
    "b": "stepped", "compound": "stepped", "ext-int": "stepped",
    "c": "external", "david": "external", "ext-ext": "external",
    "d": "internal", "int-int": "internal",
    "double": "double-planet", "double_planet": "double-planet",
}  # fmt: skip
_MEMBERS = ("sun", "ring", "carrier")


def canonical_scheme(scheme: Any) -> str:
    """The scheme name for ``scheme`` or one of its aliases (``"A"`` ... ``"D"``, ``"james"``).

    Raises
    ------
    TrainError
        For an unknown scheme.
    """
    if isinstance(scheme, str):
        s = scheme.strip().lower()
        if s in SCHEMES:
            return s
        if s in _ALIASES:
            return _ALIASES[s]
    raise TrainError(
        f"scheme = {scheme!r}; valid are {', '.join(SCHEMES)} (aliases A, B, C, D, james, david)"
    )


# --------------------------------------------------------------------------------- integer core
# Vectorised over numpy integer arrays (or Python ints); exact: no floats anywhere.


def basic_ratio(scheme: str, z1, z2, z2p, z3):
    """Basic (carrier-fixed) ratio i0 = i_13^(H) as an integer pair ``(numerator, denominator)``.

    ``z1`` sun (central gear a), ``z2`` the planet gear meshing it, ``z2p`` the planet gear meshing
    the ring (``z2p = z2`` for one row; the outer planet of a double-planet stage), ``z3`` ring
    (lectures §4.2 table). Arrays broadcast.

    Examples
    --------
    >>> basic_ratio("stepped", 20, 40, 20, 80)   # Willis: -(40 80)/(20 20)
    (-3200, 400)
    """
    scheme = canonical_scheme(scheme)
    if scheme == "double-planet":
        return z3, z1
    sign = -1 if scheme in ("simple", "stepped") else 1
    return sign * z2 * z3, z1 * z2p


def _coefficients(num, den):
    """Willis coefficients of (sun, ring, carrier): den w_s - num w_r + (num - den) w_H = 0."""
    return {"sun": den, "ring": -num, "carrier": num - den}


def stage_ratio(scheme: str, z1, z2, z2p, z3, fixed="ring", input="sun", output="carrier"):
    """Exact ratio ``w_input / w_output`` with ``fixed`` held, as ``(numerator, denominator)``.

    From ``w_s - i0 w_r - (1 - i0) w_H = 0`` (Ozols (7.6)): with one member fixed the ratio is
    ``-c_output / c_input`` of the Willis coefficients, reduced, with a positive denominator. A
    zero denominator means the input is locked, a zero numerator that the output stands still.

    Examples
    --------
    >>> stage_ratio("simple", 20, 30, 30, 80)   # Ozols derived case: i_1H = 5
    (5, 1)
    >>> stage_ratio("simple", 20, 30, 30, 80, fixed="sun", input="ring")   # 1 - 1/i0 = 5/4
    (5, 4)
    """
    fixed, input, output = _roles(fixed, input, output)
    c = _coefficients(*basic_ratio(scheme, z1, z2, z2p, z3))
    num, den = -c[output], c[input]
    g = np.gcd(num, den)
    g = np.where(g == 0, 1, g) * np.where(den < 0, -1, 1)
    num, den = num // g, den // g
    if np.ndim(num) == 0:
        return int(num), int(den)
    return num, den


def _roles(fixed: Any, input: Any, output: Any) -> tuple[str, str, str]:
    names = []
    for what, v in (("fixed", fixed), ("input", input), ("output", output)):
        if v not in _MEMBERS:
            raise TrainError(f"{what} = {v!r}; valid are 'sun', 'ring', 'carrier'")
        names.append(v)
    if len(set(names)) != 3:
        raise TrainError(
            f"fixed = {fixed!r}, input = {input!r}, output = {output!r} must be three different"
            " members of 'sun', 'ring', 'carrier'"
        )
    return names[0], names[1], names[2]


def _default_roles(fixed: str, input: str | None, output: str | None) -> tuple[str, str, str]:
    if fixed not in _MEMBERS:
        raise TrainError(f"fixed = {fixed!r}; valid are 'sun', 'ring', 'carrier'")
    free = [m for m in _MEMBERS if m != fixed]
    if input is None:
        input = free[0] if output != free[0] else free[1]
    if output is None:
        output = next(m for m in free if m != input)
    return _roles(fixed, input, output)


def assembly_ticks(scheme: str, z1, z2, z2p, z3):
    """Assembly number T = N / gcd(z_c, z_d): planet positions per turn (tick 2 pi / T).

    ``N = |z_b z_c - s_a s_b z_a z_d|`` (lectures §4.3; KHK); for one row this is
    ``z_s + z_r`` (Ozols §21-13). Identical planets assemble equally spaced iff ``T % k == 0``.
    For the double-planet scheme the rigid cluster behaves as one planet with the sun-side tooth
    count on both sides and a sign reversal, giving ``T = |z_r - z_s|``. Integer arithmetic.

    Examples
    --------
    >>> int(assembly_ticks("simple", 18, 45, 45, 108))   # 126 = 3 x 42: three planets fit
    126
    >>> int(assembly_ticks("stepped", 26, 70, 21, 117))  # (26 21 + 117 70) / 7 = 1248
    1248
    """
    scheme = canonical_scheme(scheme)
    if scheme == "double-planet":
        return np.abs(np.asarray(z3) - np.asarray(z1))
    internal_a = scheme == "internal"  # the sun of scheme D is a ring
    internal_b = scheme != "external"
    return assembly_number(z1, z2, z2p, z3, internal_a, internal_b)


def textbook_assembly(z_a: int, ratio_aH: Fraction, k: int) -> bool:
    """Textbook (sufficient) form: ``(z_a i_aH / k)(1 + k p)`` is an integer for some p >= 0.

    Exact: with ``z_a |i_aH| / k = u / v`` in lowest terms, ``v`` must divide ``1 + k p`` for some
    p, that is ``k p = -1 (mod v)``, solvable exactly when ``gcd(k, v) = 1`` (k is then
    invertible modulo v): one gcd instead of a search over ``range(v)``.
    """
    x = Fraction(z_a) * abs(Fraction(ratio_aH)) / k
    return math.gcd(k, x.denominator) == 1


def phasing_class(z_central: int, k: int) -> str:
    """Mesh phasing of k equally spaced planets on a central gear of ``z_central`` teeth.

    ``z mod k`` is 0: in-phase (tooth forces add, radial forces cancel); 1 or k - 1: sequential;
    otherwise counter-phase (drivetrainhub, planetary gear notes).
    """
    r = int(z_central) % int(k)
    if r == 0:
        return "in-phase"
    if r in (1, k - 1):
        return "sequential"
    return "counter-phase"


def coaxial_ring_teeth(scheme: str, z1, z2, z2p):
    """z3 from the zero-shift, one-module coaxiality condition (lectures §4.2 table).

    simple ``z1 + 2 z2``; stepped ``z1 + z2 + z2'``; external ``z1 + z2 - z2'``; internal
    ``z1 - z2 + z2'``. The double-planet scheme has no such equation (its planet triangle closes
    for a range of tooth counts).
    """
    scheme = canonical_scheme(scheme)
    if scheme == "simple":
        return z1 + 2 * z2
    if scheme == "stepped":
        return z1 + z2 + z2p
    if scheme == "external":
        return z1 + z2 - z2p
    if scheme == "internal":
        return z1 - z2 + z2p
    raise TrainError("the double-planet scheme has no tooth-count coaxiality equation")


# mesh table: (name, gear key 1, gear key 2); the GearPair takes the first as g1 (external)
_MESHES = {
    "simple": (("sun-planet", "sun", "planet"), ("planet-ring", "planet", "ring")),
    "stepped": (("sun-planet", "sun", "planet"), ("planet-ring", "planet'", "ring")),
    "external": (("sun-planet", "sun", "planet"), ("planet-ring", "planet'", "ring")),
    "internal": (("sun-planet", "planet", "sun"), ("planet-ring", "planet'", "ring")),
    "double-planet": (
        ("sun-planet", "sun", "planet"),
        ("planet-planet2", "planet", "planet2"),
        ("planet2-ring", "planet2", "ring"),
    ),
}
# (gear key, internal?, helix sign relative to the sun's helix)
_GEARS = {
    "simple": (("sun", False, 1), ("planet", False, -1), ("ring", True, -1)),
    "stepped": (("sun", False, 1), ("planet", False, -1), ("planet'", False, -1),
                ("ring", True, -1)),
    "external": (("sun", False, 1), ("planet", False, -1), ("planet'", False, -1),
                 ("ring", False, 1)),
    "internal": (("sun", True, -1), ("planet", False, -1), ("planet'", False, -1),
                 ("ring", True, -1)),
    "double-planet": (("sun", False, 1), ("planet", False, -1), ("planet2", False, 1),
                      ("ring", True, 1)),
}  # fmt: skip
_TRAIN_MEMBER = {"sun": "sun", "planet": "planet", "planet'": "planet", "planet2": "planet2",
                 "ring": "ring"}  # fmt: skip


#: How far (in modules) a gap between planet tip circles may fall short of the clearance and
#: still pass: the rounding of ``2 a_w sin(pi / k)`` (six planets at clearance 0 touch exactly,
