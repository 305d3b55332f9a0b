"""Layer 5, stages and catalog.

Ready-made trains: each one a :class:`~trains.willis.Train` built from mesh, link, couple.

Nothing here is special-cased in the solver: every function only writes the Willis relations of
its scheme, so a user can copy one and change it. Member names follow the textbook figures cited
in each docstring; the ``examples/train_*.py`` scripts use every one of them.
"""

from __future__ import annotations

from collections.abc import Sequence

from trains.errors import TrainError
from trains.willis import Train

_MESH_KINDS = ("external", "internal")


def simple_planetary(sun: int, planet: int, ring: int, n_planets: int = 1) -> Train:
    """Sun - planet - ring on a carrier (James / 2K-H type A; Ozols (7.7), lectures §4.2 A).

    Members ``"sun"``, ``"planet"``, ``"ring"``, ``"carrier"``. Basic ratio
    ``i_sun,ring^(carrier) = -ring/sun``.

    Examples
    --------
    >>> t = simple_planetary(20, 30, 80)
    >>> t.ratio("sun", "carrier", fixed=["ring"])
    Fraction(5, 1)
    """
    t = Train()
    t.name = f"simple planetary {sun}/{planet}/{ring}"
    t.mesh("sun", "planet", teeth=(sun, planet), carrier="carrier")
    t.mesh("planet", "ring", teeth=(planet, ring), carrier="carrier", internal=True)
    t.set_planets("planet", n_planets)
    return t


def stepped_planetary(
    z1: int,
    z2: int,
    z2b: int,
    z3: int,
    meshes: Sequence[str] = ("external", "internal"),
    n_planets: int = 1,
) -> Train:
    """2K-H train with a stepped (compound) planet 2-2' (Ozols Fig 7-7, 7-8; lectures §4.2 B-D).

    Members ``"1"`` (first central gear), ``"2"`` (the planet block: ``z2`` meshes 1, ``z2b``
    = z2' meshes 3), ``"3"`` (second central gear) and ``"H"`` (carrier), numbered as in the
    books. ``meshes`` gives the kind of mesh 1-2 and of mesh 2'-3:

    * ``("external", "internal")``: scheme B, sun and ring;
    * ``("external", "external")``: scheme C, two external meshes (Ozols' David mechanism,
      example 7-4; the thread-tapping differential, example 7-5);
    * ``("internal", "internal")``: scheme D, two rings.

    Examples
    --------
    >>> t = stepped_planetary(100, 101, 100, 99, meshes=("external", "external"))
    >>> t.ratio("H", "1", fixed=["3"])
    Fraction(10000, 1)
    """
    kinds = tuple(meshes)
    if len(kinds) != 2 or any(k not in _MESH_KINDS for k in kinds):
        raise TrainError(f"meshes must be two of {_MESH_KINDS}, got {meshes!r}")
    t = Train()
    t.name = f"stepped-planet 2K-H {z1}/{z2}-{z2b}/{z3} ({kinds[0]}, {kinds[1]})"
    t.mesh("1", "2", teeth=(z1, z2), carrier="H", internal=kinds[0] == "internal")
    t.mesh("2", "3", teeth=(z2b, z3), carrier="H", internal=kinds[1] == "internal")
    t.set_planets("2", n_planets)
    return t


def double_planet(sun: int, planet1: int, planet2: int, ring: int, n_planets: int = 1) -> Train:
    """Sun - planet - planet - ring (double-planet, "plus" train; Willis sign rule, - per external
    mesh).

    Members ``"sun"``, ``"planet1"`` (meshes the sun), ``"planet2"`` (meshes planet1 and the
    ring), ``"ring"``, ``"carrier"``. Basic ratio ``+ring/sun``, so with the ring fixed
    ``i_sun,carrier = 1 - ring/sun`` (negative) and with the sun fixed the carrier turns with the
    ring.

    Examples
    --------
    >>> double_planet(30, 15, 15, 90).ratio("ring", "carrier", fixed=["sun"])
    Fraction(2, 3)
    """
    t = Train()
    t.name = f"double-planet {sun}/{planet1}/{planet2}/{ring}"
    t.mesh("sun", "planet1", teeth=(sun, planet1), carrier="carrier")
    t.mesh("planet1", "planet2", teeth=(planet1, planet2), carrier="carrier")
    t.mesh("planet2", "ring", teeth=(planet2, ring), carrier="carrier", internal=True)
    t.set_planets("planet1", n_planets)
    t.set_planets("planet2", n_planets)
    return t


def wolfrom(
    sun: int, planet: int, ring1: int, planet2: int, ring2: int, n_planets: int = 1
) -> Train:
    """Wolfrom / 3K train: a stepped planet between two rings (Ozols Fig 7-9a, "relieved carrier").

    Members ``"sun"``, ``"planet"`` (``planet`` teeth mesh the sun and ``ring1``, ``planet2``
    teeth mesh ``ring2``), ``"ring1"`` (usually fixed), ``"ring2"`` (usually the output),
    ``"carrier"`` (runs idle). Ozols: ``i_14 = (1 + z3/z1) / (1 - z2' z3 / (z4 z2))``.

    Examples
    --------
    >>> t = wolfrom(20, 30, 80, 29, 77)
    >>> t.ratio("sun", "ring2", fixed=["ring1"]) == (1 + 80 / 20) / (1 - 29 * 80 / (77 * 30))
    False
    >>> from fractions import Fraction as F
    >>> t.ratio("sun", "ring2", fixed=["ring1"]) == (1 + F(80, 20)) / (1 - F(29 * 80, 77 * 30))
    True
    """
    t = Train()
    t.name = f"Wolfrom 3K {sun}/{planet}/{ring1} + {planet2}/{ring2}"
    t.mesh("sun", "planet", teeth=(sun, planet), carrier="carrier")
    t.mesh("planet", "ring1", teeth=(planet, ring1), carrier="carrier", internal=True)
    t.mesh("planet", "ring2", teeth=(planet2, ring2), carrier="carrier", internal=True)
    t.set_planets("planet", n_planets)
    return t


def bevel_differential(
    side: int = 16, pinion: int = 10, drive: tuple[int, int] | None = None
) -> Train:
    """The bevel (car) differential (Ozols Fig 7-11, (7.9): ``w_1 + w_2 = 2 w_H``).

    Members ``"left"``, ``"right"`` (side gears, ``side`` teeth), ``"pinion"`` (the planet
    pinions, ``pinion`` teeth) and ``"carrier"`` (the case). The bevel meshes are links by the
    arrow rule: in the case's frame the side gears turn opposite ways; the pinion's speed is its
    spin about its own axis (its absolute "speed" is only meaningful through
    ``Motion.relative("pinion", "carrier")``, the bearing speed). ``drive=(z_pinion, z_crown)``
    adds the final drive: member ``"input"`` turning ``z_crown/z_pinion`` times the case speed
    (crossed axes: the sign is a convention, positive here).

    Examples
    --------
    >>> t = bevel_differential()
    >>> m = t.solve(carrier=100, left=80)
    >>> m["right"], m.relative("pinion", "carrier")
    (Fraction(120, 1), Fraction(-32, 1))
    """
    t = Train()
    t.name = f"bevel differential {side}/{pinion}"
    from fractions import Fraction

    t.link("pinion", "left", ratio=Fraction(side, pinion), carrier="carrier", name="left-pinion")
    t.link("right", "pinion", ratio=-Fraction(pinion, side), carrier="carrier",
           name="pinion-right")  # fmt: skip
    if drive is not None:
        zp, zc = drive
        t.link("input", "carrier", ratio=Fraction(zc, zp), name="final-drive")
    return t


def khv(planet: int, ring: int, n_planets: int = 1) -> Train:
    """K-H-V train: one planet inside a fixed ring, output through a parallel-link coupling.

    Ozols Fig 7-9b: ``i_1H = 1 - z_ring/z_planet = i_3H``. Members ``"carrier"`` (the eccentric,
    usually the input), ``"planet"``, ``"ring"`` (usually fixed) and ``"output"`` (coupled to
    the planet's absolute rotation by the W/V mechanism).

    Examples
    --------
    >>> khv(49, 50).ratio("carrier", "output", fixed=["ring"])
    Fraction(-49, 1)
    """
    t = Train()
    t.name = f"K-H-V {planet}/{ring}"
    t.mesh("planet", "ring", teeth=(planet, ring), carrier="carrier", internal=True)
    t.couple("planet", "output", name="W-coupling")
    t.set_planets("planet", n_planets)
    return t


def strain_wave(flexspline: int, rigid: int) -> Train:
    """Strain-wave (harmonic) drive as a K-H-V train with the wave generator as carrier.

    Joldasbekov §2.15: with the rigid wheel fixed, ``i_generator,flexspline = -z_1/(z_2 - z_1)``.
    Members ``"generator"``, ``"flexspline"``, ``"rigid"``.

    Examples
    --------
    >>> strain_wave(200, 202).ratio("generator", "flexspline", fixed=["rigid"])
    Fraction(-100, 1)
    """
    t = Train()
    t.name = f"strain wave {flexspline}/{rigid}"
    t.mesh("flexspline", "rigid", teeth=(flexspline, rigid), carrier="generator", internal=True)
    return t


def ferguson(sun: int = 100, idler: int = 20, satellites: Sequence[int] = (99, 100, 101)) -> Train:
    """Ferguson's paradox (Ozols example 7-3): a fixed sun, an idler on the carrier, satellites.

    Members ``"sun"`` (fixed in use), ``"idler"``, ``"carrier"`` and ``"satellite1"``,
    ``"satellite2"``, ... (one per entry of ``satellites``, each meshing the idler). A satellite
    with as many teeth as the sun translates without turning; one with more teeth turns with
    the carrier, one with fewer against it. (Real Ferguson sets mesh one idler with different
    tooth counts by profile shift; the kinematics do not depend on it.)

    Examples
    --------
    >>> m = ferguson().solve(carrier=1, sun=0)
    >>> [m[f"satellite{i}"] for i in (1, 2, 3)]
    [Fraction(-1, 99), Fraction(0, 1), Fraction(1, 101)]
    """
    t = Train()
    t.name = f"Ferguson's paradox, sun {sun}, idler {idler}, satellites {tuple(satellites)}"
    t.mesh("sun", "idler", teeth=(sun, idler), carrier="carrier")
    for i, z in enumerate(satellites, start=1):
        t.mesh("idler", f"satellite{i}", teeth=(idler, z), carrier="carrier")
    return t


def biplanetary(fixed: int, planet: int, inner_sun: int, satellite: int) -> Train:
    """Biplanetary train (Ozols Fig 7-10): a planetary train riding on the planet of another.

    Outer stage: fixed sun ``"3"`` (``fixed`` teeth), carrier ``"H"``, planet ``"2"`` (``planet``
    teeth), external mesh. Inner stage: a gear of ``inner_sun`` teeth fixed to ``H`` and coaxial
    with planet 2; planet 2 is its carrier; satellite ``"1"`` (``satellite`` teeth) meshes it
    externally. Ozols (a): ``i_1H = 1 + (1 + r_H/r_1) r_3/r_2``. With one module the tooth
    counts are proportional to the radii.

    Examples
    --------
    >>> biplanetary(60, 20, 10, 5).ratio("1", "H", fixed=["3"])
    Fraction(10, 1)
    """
    t = Train()
    t.name = f"biplanetary {fixed}/{planet} + {inner_sun}/{satellite}"
    t.mesh("3", "2", teeth=(fixed, planet), carrier="H")
    t.mesh("H", "1", teeth=(inner_sun, satellite), carrier="2")
    return t


__all__ = [
    "bevel_differential",
    "biplanetary",
    "double_planet",
    "ferguson",
    "khv",
    "simple_planetary",
    "stepped_planetary",
    "strain_wave",
    "wolfrom",
]
