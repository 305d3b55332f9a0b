"""Layer 4, load capacity of trains: every mesh of real gears rated by ISO 6336 from the power flow.

:func:`rating` solves the statics of a :class:`~trains.willis.Train` (:func:`trains.power_flow`),
then rates each mesh built from real gears with :meth:`gears.GearPair.rating`:

* the torque on the mesh's gear 1 is the torque the mesh puts on its member
  (:attr:`trains.power.RelationPower.torques`), shared by the planet copies when one of its
  members is a planet declared with :meth:`Train.set_planets` (``n`` copies: ``T / n`` per mesh);
* the speed is gear 1's speed relative to the mesh's carrier;
* the load cycles per turn count the planets a central gear meets (a sun with three planets:
  three per relative turn), and a gear that two meshes load on opposite flanks (a planet
  meshing sun and ring, an idler) is rated as an idler (Y_M);
* the mesh load factor K_gamma of planet meshes defaults to :func:`load_sharing` of the planet
  count (AGMA 6123 values, as ISO 6336-1 leaves them to the designer), or is given.

:meth:`trains.Planetary.rating` rates one stage this way. A bevel mesh (``pair=``
:class:`gears.BevelPair`) is rated by ISO 10300 method B1 (:meth:`gears.BevelPair.rating`, a
:class:`gears.BevelRating`) at the same torque and speed of its pinion, with the options
``mounting``, ``pattern`` and ``effective_width`` (bevel meshes only; its face width is its
pair's); under a load spectrum bevel meshes are left out.
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Iterable, Mapping
from typing import Any

from gears import BevelPair, GearPair, Rating
from gears.errors import GearError
from trains.errors import TrainError
from trains.power import power_flow
from trains.willis import FRAME, Train

__all__ = ["LOAD_SHARING", "load_sharing", "rating"]

#: K_gamma by planet count: AGMA 6123 (application level 1) as commonly quoted; one or two
#: planets share equally (1.0), more share worse.
LOAD_SHARING = {1: 1.0, 2: 1.0, 3: 1.16, 4: 1.25, 5: 1.35, 6: 1.44, 7: 1.47, 8: 1.50, 9: 1.54}


def load_sharing(n_planets: int) -> float:
    """Default mesh load factor K_gamma for ``n_planets`` planets (:data:`LOAD_SHARING`; 1.54
    beyond nine).

    >>> load_sharing(3), load_sharing(12)
    (1.16, 1.54)
    """
    if isinstance(n_planets, bool) or not isinstance(n_planets, numbers.Integral) or n_planets < 1:
        raise TrainError(f"n_planets = {n_planets!r}; valid is an integer >= 1")
    return LOAD_SHARING.get(int(n_planets), 1.54)


def _per_mesh(value: Any, name: str, what: str) -> Any:
    """A value for every mesh, or a mapping mesh name -> value (missing: None)."""
    if isinstance(value, Mapping):
        return value.get(name)
    return value


def rating(
    train: Train,
    input: str,
    output: str,
    fixed: Iterable[str] = (),
    torque: float = 1.0,
    speed: float = 1.0,
    material: Any = "case-carburized",
    face_width: float | Mapping[str, float] | None = None,
    load_sharing_factor: float | Mapping[str, float] | None = None,
    mesh_efficiency: float | Mapping[str, float] | None = None,
    friction: float | None = None,
    spectrum: Any = None,
    **options: Any,
) -> dict[str, Any]:
    """ISO 6336 rating of every mesh of real gears in ``train`` (see the module docstring).

    Parameters
    ----------
    train : Train
        Meshes built with ``gears=`` or ``pair=`` are rated; kinematic-only relations and meshes
        that carry no torque in this load case are left out.
    input, output, fixed
        As for :func:`trains.power_flow`.
    torque : float
        Torque on the input member, N m (> 0).
    speed : float
        Speed of the input member, rpm (> 0).
    material : name, Material, pair or mapping
        The gears' material (:mod:`gears.rating.materials`), or a mapping mesh name -> material.
    face_width : float or mapping, optional
        Face width of every mesh (mm) or per mesh name; default the gears' own.
    load_sharing_factor : float or mapping, optional
        K_gamma of the planet meshes (default :func:`load_sharing` of the planet count); 1 for
        fixed-axis meshes unless given per mesh.
    mesh_efficiency, friction
        Losses for the power flow (default lossless), as for :func:`trains.power_flow`.
    spectrum : list of (torque, speed, hours), optional
        A load spectrum on the input member (ISO 6336-6) instead of ``torque``, ``speed`` and
        ``life``: every bin is rated as above, then each mesh gets a
        :class:`gears.rating.spectrum.SpectrumRating` (Miner's sums, equivalent safeties, lives).
    **options
        Passed to :meth:`gears.GearPair.rating` (``life``, ``quality``, ``roughness``,
        ``root_roughness``, ``oil_viscosity``, ``application_factor``, ``edition`` (of
        ISO 6336-1/-2/-3, 2019 or 2006; bevel meshes are rated by ISO 10300 whatever it is),
        factors such as ``K_v=1.0``).

    Returns
    -------
    dict
        Mesh name -> :class:`gears.Rating` (gear 1 is the mesh's external gear).

    Raises
    ------
    TrainError
        For bad input, naming it (and the mesh), a train without rated meshes, or a loaded mesh
        that does not turn (a static rating is not ISO 6336's).

    Examples
    --------
    >>> from gears import Gear
    >>> t = Train()
    >>> t.mesh("in", "out", gears=(Gear(19, 3, face_width=30), Gear(61, 3, face_width=30)))
    >>> r = rating(t, "in", "out", fixed=[], torque=250, speed=1450)
    >>> [round(s, 3) for s in r["in-out"].safety_pitting]
    [0.933, 1.053]
    """
    if spectrum is not None:
        return _spectrum_rating(train, input, output, fixed, spectrum, material, face_width,
                                load_sharing_factor, mesh_efficiency, friction,
                                options)  # fmt: skip
    for name, value in (("torque", torque), ("speed", speed)):
        if (
            isinstance(value, bool)
            or not isinstance(value, numbers.Real)
            or not (math.isfinite(float(value)) and float(value) > 0)
        ):
            raise TrainError(f"{name} = {value!r}; valid is a finite number > 0")
    fixed = [fixed] if isinstance(fixed, str) else list(fixed)
    flow = power_flow(train, input, output, fixed=fixed, mesh_efficiency=mesh_efficiency,
                      input_torque=float(torque), input_speed=float(speed),
                      friction=friction)  # fmt: skip
    speeds = flow.speeds
    planets = dict(getattr(train, "_planets", {}))
    bevel = {k: options.pop(k) for k in _BEVEL_ONLY if k in options}  # ISO 10300's options
    kinds = GearPair if options.pop("_no_bevel", False) else GearPair | BevelPair
    relations = [r for r in train.relations if isinstance(r.pair, kinds)]
    if not relations:
        raise TrainError(
            "the train has no mesh of real gears to rate (build meshes with gears= or pair=)"
        )
    scale = max(abs(float(t)) for t in flow.torques.values())
    out: dict[str, Rating] = {}
    for r in relations:
        rp = flow.relations[r.name]
        pair = r.pair
        first_on_b = not isinstance(pair, BevelPair) and r.gears[0].internal  # g1 external
        m1, m2 = (r.b, r.a) if first_on_b else (r.a, r.b)
        g1, g2 = pair.g1, pair.g2
        copies = max(planets.get(m1, 1), planets.get(m2, 1))
        t1 = abs(rp.torques.get(m1, 0.0)) / copies
        if t1 <= 1e-12 * scale:
            continue  # this load case leaves the mesh unloaded
        n1 = abs(float(speeds[m1]) - float(speeds[r.carrier]))
        if n1 <= 1e-12 * max(abs(float(v)) for v in speeds.values()):
            raise TrainError(
                f"mesh {r.name}: it carries {t1:.6g} N m but does not turn (relative speed 0): "
                "a static rating is not covered by ISO 6336"
            )
        contacts = (
            planets.get(m2, 1) if m1 not in planets else 1,
            planets.get(m1, 1) if m2 not in planets else 1,
        )
        idler = (_idler(train, flow, m1, g1), _idler(train, flow, m2, g2))
        k_gamma = _per_mesh(load_sharing_factor, r.name, "load_sharing_factor")
        if k_gamma is None:
            k_gamma = load_sharing(copies) if copies > 1 else 1.0
        else:
            _at_least_one("load_sharing_factor", k_gamma, r.name)
        kw = dict(options)
        kw.setdefault("K_gamma", k_gamma)
        b = _per_mesh(face_width, r.name, "face_width")
        mat = _per_mesh(material, r.name, "material") if isinstance(material, Mapping) else material
        if mat is None:
            raise TrainError(f"material: no entry for mesh {r.name!r}")
        is_bevel = isinstance(pair, BevelPair)
        if is_bevel and isinstance(face_width, Mapping) and b is not None:
            raise TrainError(
                f"face_width: mesh {r.name!r} is a bevel pair, whose face width is its own "
                f"({pair.face_width:g} mm)"
            )
        try:
            if is_bevel:  # ISO 10300 method B1 (the face width is the pair's; no edition=)
                kw.pop("edition", None)
                out[r.name] = pair.rating(t1, n1, mat, contacts=contacts, idler=idler, **kw,
                                          **bevel)  # fmt: skip
            else:
                out[r.name] = pair.rating(t1, n1, mat, face_width=b, contacts=contacts,
                                          idler=idler, **kw)  # fmt: skip
        except GearError as exc:
            raise TrainError(f"mesh {r.name}: {exc}") from None
    return out


#: the options of :func:`rating` that only bevel meshes take (ISO 10300's)
_BEVEL_ONLY = ("mounting", "pattern", "effective_width")


def _at_least_one(name: str, value: Any, mesh: str) -> None:
    """A load factor the caller gives: one finite number >= 1 (ISO 6336-1's K_gamma)."""
    try:
        ok = (
            not isinstance(value, bool)
            and isinstance(value, numbers.Real)
            and math.isfinite(float(value))
            and float(value) >= 1.0
        )
    except OverflowError:
        ok = False
    if not ok:
        raise TrainError(f"{name} = {value!r} (mesh {mesh}); valid is a number >= 1 (K_gamma)")


def _idler(train: Train, flow, member: str, gear) -> bool:
    """True when two meshes load ``gear`` on ``member`` on opposite flanks (their torques on
    the member have opposite signs): an idler, a planet between sun and ring."""
    signs = set()
    for r in train.relations:
        if r.pair is None or r.gears is None or member not in (r.a, r.b) or member == FRAME:
            continue
        mine = r.gears[0] if member == r.a else r.gears[1]
        if mine != gear:
            continue
        t = flow.relations[r.name].torques.get(member, 0.0)
        if t != 0.0:
            signs.add(t > 0)
    return len(signs) == 2


def _spectrum_rating(train, input, output, fixed, spectrum, material, face_width,
                     load_sharing_factor, mesh_efficiency, friction, options) -> dict:  # fmt: skip
    """:func:`rating` under a load spectrum: each bin rated, then Miner's rule per mesh."""
    from gears.rating.spectrum import check_spectrum, spectrum_rating  # when asked

    if "life" in options:
        raise TrainError("life= and spectrum= exclude each other: the spectrum gives the hours")
    for key in _BEVEL_ONLY:
        if key in options:
            raise TrainError(f"{key}= rates bevel meshes, which a spectrum rating leaves out")
    try:
        torques, speeds, hours = check_spectrum(spectrum)
    except GearError as exc:
        raise TrainError(str(exc)) from None
    per_bin = [
        rating(train, input, output, fixed, torque=float(t), speed=float(n), material=material,
               face_width=face_width, load_sharing_factor=load_sharing_factor,
               mesh_efficiency=mesh_efficiency, friction=friction, life=float(h), _no_bevel=True,
               **options)
        for t, n, h in zip(torques, speeds, hours, strict=True)
    ]  # fmt: skip
    out = {}
    for name in per_bin[0]:
        ratings = [bin_[name] for bin_ in per_bin]
        rows = [(r.settings["torque"], r.settings["speed"], float(h))
                for r, h in zip(ratings, hours, strict=True)]  # fmt: skip
        mat = _per_mesh(material, name, "material") if isinstance(material, Mapping) else material
        try:
            out[name] = spectrum_rating(ratings, mat, rows)
        except GearError as exc:
            raise TrainError(f"mesh {name}: {exc}") from None
    return out
