"""Layer 1, command line: the rating options the sub-commands share (``rate``, ``planetary``,
``bevel``, ``differential``): the operating conditions of an ISO 6336 rating, what ISO 10300 adds
for bevel gears, and the oil of a scuffing rating (ISO/TS 6336-20/-21), each with its defaults
and the map from the library's names in error messages to the options.
"""

from __future__ import annotations

import argparse

from trains.cli._types import bounded, integer, non_negative, positive

#: the library's names in rating errors -> the options of rating_arguments
RATING_NAMES = {
    "torque": "--torque",
    "speed": "--speed",
    "life": "--life",
    "quality": "--quality",
    "roughness": "--roughness",
    "root_roughness": "--root-roughness",
    "oil_viscosity": "--oil-viscosity",
    "tip_relief": "--tip-relief",
    "application_factor": "--application-factor",
    "material": "--material",
    "min_pitting": "--min-pitting",
    "min_bending": "--min-bending",
    "edition": "--edition",
}


RATING_DEFAULTS = {
    "material": "case-carburized",
    "life": 20000.0,
    "quality": 6,
    "roughness": 1.0,
    "root_roughness": None,
    "oil_viscosity": 220.0,
    "tip_relief": None,
    "application_factor": 1.0,
    "min_pitting": 1.0,
    "min_bending": 1.4,
}


def rating_arguments(parser: argparse.ArgumentParser, required: bool = True, *,
                     torque: bool = True, speed: bool = True) -> None:  # fmt: skip
    """The operating conditions of an ISO 6336 rating (``rate``, ``planetary``; the ISO 10300
    rating of ``bevel`` and ``differential``): ``--torque`` and ``--speed`` (unless the
    command has its own: ``torque=False``, ``speed=False``), ``--material``, ``--life``,
    ``--quality``, ``--roughness``, ``--root-roughness``, ``--oil-viscosity``,
    ``--tip-relief``, ``--application-factor``, ``--min-pitting`` and ``--min-bending``. Their
    defaults (:data:`RATING_DEFAULTS`) are filled in by :func:`rating_options`, so a command
    can tell which were given (:func:`rating_given`)."""
    need = "" if required else " (with --speed: rate every mesh)"
    d = RATING_DEFAULTS
    if torque:
        parser.add_argument(
            "--torque", type=positive("--torque", "N m"), required=required, default=None,
            metavar="T", help=f"input torque in N m{need}",
        )  # fmt: skip
    if speed:
        parser.add_argument(
            "--speed", type=positive("--speed", "rpm"), required=required, default=None,
            metavar="N", help="input speed in rpm",
        )  # fmt: skip
    parser.add_argument(
        "--material", default=None,
        help="ISO 6336-5 material of the gears: case-carburized, nitrided, induction-hardened, "
        f"flame-hardened, through-hardened, nodular-cast-iron or grey-cast-iron (default "
        f"{d['material']})",
    )  # fmt: skip
    parser.add_argument(
        "--life", type=positive("--life", "hours"), default=None,
        help=f"required life, hours (default {d['life']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--quality", type=integer("--quality", 1, 12), default=None,
        help=f"ISO 1328 accuracy grade (default {d['quality']})",
    )  # fmt: skip
    parser.add_argument(
        "--roughness", type=positive("--roughness", "um"), default=None,
        help=f"flank roughness Ra, um (default {d['roughness']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--root-roughness", type=positive("--root-roughness", "um"), default=None,
        metavar="RA", help="root fillet roughness Ra, um (default: --roughness; a ground flank "
        "with a hobbed root has a rougher root)",
    )  # fmt: skip
    parser.add_argument(
        "--oil-viscosity", type=positive("--oil-viscosity", "mm^2/s"), default=None,
        help=f"oil viscosity nu_40 at 40 deg C, mm^2/s (default {d['oil_viscosity']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--tip-relief", type=non_negative("--tip-relief", "mm"), default=None, metavar="C_A",
        help="tip relief in mm (default: the running-in amount of ISO 6336-1)",
    )  # fmt: skip
    parser.add_argument(
        "--application-factor", type=bounded("--application-factor", 1, 10), default=None,
        metavar="K_A", help=f"application factor K_A (default {d['application_factor']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--min-pitting", type=non_negative("--min-pitting"), default=None,
        help=f"required safety against pitting S_Hmin (default {d['min_pitting']:g})",
    )  # fmt: skip
    parser.add_argument(
        "--min-bending", type=non_negative("--min-bending"), default=None,
        help=f"required safety against tooth-root breakage S_Fmin (default {d['min_bending']:g})",
    )  # fmt: skip


def edition_argument(parser: argparse.ArgumentParser) -> None:
    """``--edition``: the edition of ISO 6336-1/-2/-3 an ISO 6336 rating follows (``rate``,
    ``planetary``; :data:`gears.rating.bending.EDITIONS`), read by :func:`edition_option`."""
    parser.add_argument(
        "--edition", type=int, choices=(2019, 2006), default=None,
        help="edition of ISO 6336-1/-2/-3 (default 2019; 2006 is the edition of ISO/TR "
        "6336-30:2017's examples): they differ in the root's Y_F and Y_beta",
    )  # fmt: skip


def edition_option(args: argparse.Namespace) -> dict:
    """``{"edition": ...}`` of :func:`edition_argument`'s option, the default (2019) filled in."""
    return {"edition": 2019 if args.edition is None else args.edition}


def rating_given(args: argparse.Namespace) -> list[str]:
    """The rating options given on the command line (other than --torque and --speed)."""
    return [f"--{k.replace('_', '-')}" for k in RATING_DEFAULTS if getattr(args, k) is not None]


def rating_options(args: argparse.Namespace) -> dict:
    """The keyword arguments of ``GearPair.rating`` / ``Planetary.rating`` the options of
    :func:`rating_arguments` give (torque, speed and the minimums aside), defaults filled in."""
    keys = ("material", "life", "quality", "roughness", "root_roughness", "oil_viscosity",
            "tip_relief", "application_factor")  # fmt: skip
    return {k: RATING_DEFAULTS[k] if getattr(args, k) is None else getattr(args, k) for k in keys}


def rating_minimums(args: argparse.Namespace) -> tuple[float, float]:
    """``(min_pitting, min_bending)`` of the options, defaults filled in."""
    return tuple(
        RATING_DEFAULTS[k] if getattr(args, k) is None else getattr(args, k)
        for k in ("min_pitting", "min_bending")
    )


#: the library's names in ISO 10300 errors -> the options of :func:`bevel_rating_arguments`
BEVEL_RATING_NAMES = {
    "mounting": "--mounting",
    "pattern": "--pattern",
    "effective_width": "--effective-width",
}


def bevel_rating_arguments(parser: argparse.ArgumentParser) -> None:
    """What ISO 10300 adds to :func:`rating_arguments` (``bevel``, ``differential``):
    ``--mounting`` and ``--pattern`` (the mounting factor K_Hbeta-be) and
    ``--effective-width`` (b_eff / b)."""
    parser.add_argument(
        "--mounting", choices=("both-straddle", "one-straddle", "neither-straddle"),
        default=None, help="how pinion and wheel are mounted (ISO 10300-1 mounting factor; "
        "default both-straddle)",
    )  # fmt: skip
    parser.add_argument(
        "--pattern", choices=("full-load", "light-load", "estimated"), default=None,
        help="how the contact pattern was checked: each set under full load, under a light "
        "test load (default), or on a sample set and estimated",
    )  # fmt: skip
    parser.add_argument(
        "--effective-width", type=bounded("--effective-width", 0, 1, low_open=True),
        default=None, metavar="B_EFF",
        help="share of the face the loaded contact pattern covers, b_eff / b (default 0.85)",
    )  # fmt: skip


#: the defaults of :func:`bevel_rating_arguments`
BEVEL_RATING_DEFAULTS = {"mounting": "both-straddle", "pattern": "light-load",
                         "effective_width": 0.85}  # fmt: skip


def bevel_rating_given(args: argparse.Namespace) -> list[str]:
    """The rating options of an ISO 10300 rating given on the command line (other than
    --torque and --speed)."""
    own = [f"--{k.replace('_', '-')}" for k in BEVEL_RATING_DEFAULTS
           if getattr(args, k) is not None]  # fmt: skip
    return rating_given(args) + own


def bevel_rating_options(args: argparse.Namespace) -> dict:
    """The keyword arguments of ``BevelPair.rating`` / ``Differential.rating`` of the options of
    :func:`rating_arguments` and :func:`bevel_rating_arguments` (torque, speed and the minimums
    aside), defaults filled in."""
    own = {k: d if getattr(args, k) is None else getattr(args, k)
           for k, d in BEVEL_RATING_DEFAULTS.items()}  # fmt: skip
    return {**rating_options(args), **own}


#: The scuffing options' library names in error messages -> the options (``rate``, ``planetary``).
SCUFFING_NAMES = {
    "fzg_stage": "--fzg-stage", "oil temperature": "--oil-temperature",
    "oil viscosity_100": "--oil-viscosity-100", "oil viscosity_40": "--oil-viscosity",
    "oil base": "--oil", "oil density": "--oil-density", "welding_factor": "--welding-factor",
    "min_scuffing": "--min-scuffing",
}  # fmt: skip


def scuffing_arguments(parser: argparse.ArgumentParser) -> None:
    """The oil of a scuffing rating (ISO/TS 6336-20/-21): ``--fzg-stage``, ``--oil-temperature``,
    ``--oil-viscosity-100`` (``--oil-viscosity`` is its nu_40), ``--oil``, ``--oil-density``,
    ``--spray``, ``--welding-factor`` and ``--min-scuffing`` (:func:`scuffing_options`)."""
    group = parser.add_argument_group(
        "scuffing (ISO/TS 6336-20 flash temperature, ISO/TS 6336-21 integral temperature)"
    )
    group.add_argument(
        "--fzg-stage", type=int, default=None, metavar="STAGE",
        help="the oil's failure load stage in the FZG test A/8.3/90 (ISO 14635-1), 1 ... 12: "
        "rate against scuffing",
    )  # fmt: skip
    group.add_argument(
        "--oil-temperature", type=float, default=None, metavar="C",
        help="oil temperature before the mesh, deg C (needed with --fzg-stage)",
    )  # fmt: skip
    group.add_argument(
        "--oil-viscosity-100", type=float, default=None, metavar="NU100",
        help="the oil's kinematic viscosity at 100 deg C, mm^2/s (needed with --fzg-stage; "
        "--oil-viscosity is its nu_40)",
    )  # fmt: skip
    group.add_argument(
        "--oil", default="mineral", metavar="BASE",
        help="base oil: mineral, polyalphaolefin, polyglycol, polyglycol-water-soluble, "
        "traction, phosphate-ester (default mineral)",
    )  # fmt: skip
    group.add_argument(
        "--oil-density", type=float, default=890.0, metavar="KG_M3",
        help="the oil's density at 15 deg C, kg/m^3 (default 890.0)",
    )  # fmt: skip
    group.add_argument(
        "--spray", action="store_true", help="spray lubrication (default: dip lubrication)"
    )
    group.add_argument(
        "--welding-factor", type=float, default=1.0, metavar="X_W",
        help="welding factor X_W of the flanks (default 1.0, case-carburized)",
    )  # fmt: skip
    group.add_argument(
        "--min-scuffing", type=float, nargs=2, default=None, metavar=("S_B", "S_INTS"),
        help="minimum scuffing safeties, flash and integral (default 2.0 1.8)",
    )  # fmt: skip


def scuffing_options(args: argparse.Namespace, nu40: float) -> dict:
    """``{"scuffing": Oil, "welding_factor": X_W}`` of the scuffing options (the oil's nu_40
    ``nu40``), or ``{}`` without ``--fzg-stage``; an oil option without it, or ``--fzg-stage``
    without the oil's temperature and nu_100, is a GearError naming the option."""
    from gears.errors import GearError
    from gears.rating.scuffing import Oil

    needed = ("oil_temperature", "oil_viscosity_100")
    if args.fzg_stage is None:
        for option in needed:
            if getattr(args, option) is not None:
                raise GearError(f"--{option.replace('_', '-')} needs --fzg-stage STAGE")
        return {}
    for option in needed:
        if getattr(args, option) is None:
            raise GearError(f"--fzg-stage needs --{option.replace('_', '-')}")
    lubrication = "spray" if args.spray else "dip"
    oil = Oil(args.fzg_stage, args.oil_temperature, nu40, args.oil_viscosity_100,
              args.oil_density, args.oil, lubrication)  # fmt: skip
    return {"scuffing": oil, "welding_factor": args.welding_factor}


def scuffing_minimum(args: argparse.Namespace) -> dict:
    """``{"min_scuffing": (S_B, S_intS)}`` when ``--min-scuffing`` was given, else ``{}``
    (``Rating.check``'s defaults)."""
    return {} if args.min_scuffing is None else {"min_scuffing": tuple(args.min_scuffing)}
