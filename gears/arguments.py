"""Layer 1, arguments: the one checker of every number, flag and choice a caller passes.

Every entry point (a gear's fields, outlines, meshes, scenes, animations, checks, the search)
passes its arguments through these functions before any work (an output file's path through
:func:`gears.files.check_output`). Each returns the value in its
canonical type or raises :class:`gears.errors.GearError` naming the argument, the value given
and the valid range. Numbers must be real numbers (``int``, ``float``, numpy scalars,
``Fraction``): strings, ``bool``, ``None``, NaN and infinities are refused, so a value never
turns into a foreign exception (TypeError, a GEOS or scipy error) or a NaN deep inside the work.

Lengths that shape a solid or a drawing (face width, bore, rim, tip radius) are held to a range
relative to the size of what they shape (:func:`check_length`): a face width of 5e-324 mm is a
positive number but no solid, and a float32 file could not tell its faces apart. Tolerances
have a floor (:data:`MIN_TOLERANCE`, relative to the module below 1 mm, :func:`min_tolerance`).

Examples
--------
>>> check_positive("face_width", 10)
10.0
>>> check_positive("face_width", "10")
Traceback (most recent call last):
...
gears.errors.GearError: face_width = '10'; valid is a finite number > 0 (mm)
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable, Iterable
from decimal import Decimal

import numpy as np

from gears.errors import GearError

__all__ = [
    "LENGTH_RANGE",
    "MAX_FPS",
    "MAX_FRAMES",
    "MAX_TEETH",
    "MIN_FPS",
    "MIN_TOLERANCE",
    "MODULE_RANGE",
    "PRESSURE_ANGLES",
    "check_angle",
    "check_callback",
    "check_choice",
    "check_flag",
    "check_fps",
    "check_frames",
    "check_integer",
    "check_length",
    "check_module",
    "check_point",
    "check_positive",
    "check_pressure_angle",
    "check_real",
    "check_teeth",
    "check_tolerance",
    "min_tolerance",
]

#: The finest tolerance honoured, mm, for modules of 1 mm and more (below, 1e-6 modules:
#: :func:`min_tolerance`). Double precision would allow less, but shapely's robustness on
#: polygons of 10^6 vertices and the work of the simulations set the floor; a micrometre
#: grinder needs 1e-4 mm (docs/profiles.md, "Bounded work").
MIN_TOLERANCE = 1e-6

#: A length that shapes a solid (face width, bore, rim) lies within these multiples of the
#: size it is measured against (a module or an outline's radius): below, a float32 file cannot
#: tell its faces apart; above, volumes lose every digit.
LENGTH_RANGE = (1e-6, 1e6)

#: The normal pressure angles a gear may have, degrees (1 <= alpha_n < 45): below a degree the
#: involute formulas divide by sin(alpha) of nearly nothing; 45 is the rack's own limit.
PRESSURE_ANGLES = (1.0, 45.0)

#: The most teeth a gear may have (its diameter is then 10^7 modules: far past any rack limit).
MAX_TEETH = 10_000_000

#: The modules a gear may have, mm: below, areas and volumes underflow; above, they overflow.
MODULE_RANGE = (1e-6, 1e6)

#: Most frames one animation writes (matplotlib renders 30 to 200 ms a frame).
MAX_FRAMES = 2000

#: Frame rates an animation file can hold: a GIF stores each frame's delay in 1/100 s, at most
#: 655.35 s; faster than 1000 frames/s no player shows.
MIN_FPS, MAX_FPS = 0.01, 1000.0


def _is_real(value) -> bool:
    return isinstance(value, numbers.Real) and not isinstance(value, bool | np.bool_)


def _float(value) -> float:
    """``float(value)``, or an infinity of its sign for an int or Fraction beyond the float
    range (``float(10**400)`` raises OverflowError)."""
    try:
        return float(value)
    except OverflowError:
        return math.inf if value > 0 else -math.inf


def _show(value) -> str:
    """``value`` for a message: its repr, or ``1.000e+400`` for a number too long to print
    (an int of 10**400 overflows a float; one of 10**5000 cannot even be printed)."""
    if isinstance(value, numbers.Rational) and not isinstance(value, bool | np.bool_):
        big = abs(value.numerator) > 10**16 * abs(value.denominator)
        if big:
            return format(Decimal(value.numerator) / Decimal(value.denominator), ".3e")
    try:
        return repr(value)
    except ValueError:  # a container holding such a number
        return f"a {type(value).__name__} holding a number too long to print"


def _whole(value) -> int | None:
    """``value`` as an int when it is a whole real number (int-valued floats and Fractions too,
    of any size), else None."""
    if isinstance(value, numbers.Rational):
        return int(value) if value.denominator == 1 else None
    v = float(value)
    return int(v) if math.isfinite(v) and v == int(v) else None


def check_real(name: str, value, low=None, high=None, low_open=True, high_open=True) -> float:
    """``value`` as a finite float within ``(low, high)`` (ends open unless told), or a
    :class:`GearError` naming it and the valid range.

    >>> check_real("helix_angle", 30, -60, 60)
    30.0
    >>> check_real("helix_angle", 60, -60, 60)
    Traceback (most recent call last):
    ...
    gears.errors.GearError: helix_angle = 60; valid is helix_angle < 60
    """
    if not _is_real(value):
        raise GearError(f"{name} must be a real number; got {_show(value)}")
    v = _float(value)
    shown = f"{v:g}" if math.isfinite(v) else _show(value)
    if math.isnan(v) or (math.isinf(v) and isinstance(value, float | np.floating)):
        raise GearError(f"{name} = {v} is not finite; valid is a finite number")
    if low is not None and (v <= low if low_open else v < low):
        rel = ">" if low_open else ">="
        top = "" if high is None else f" and {'<' if high_open else '<='} {high:g}"
        raise GearError(f"{name} = {shown}; valid is {name} {rel} {low:g}{top}")
    if high is not None and (v >= high if high_open else v > high):
        rel = "<" if high_open else "<="
        raise GearError(f"{name} = {shown}; valid is {name} {rel} {high:g}")
    if not math.isfinite(v):
        raise GearError(f"{name} = {shown}; valid is a finite number (at most 1.8e308 in size)")
    return v


def check_integer(name: str, value, low: int = 1, high: int | None = None) -> int:
    """``value`` as an int in ``low ... high`` (int-valued floats are accepted)."""
    span = f"an integer {low} ... {high}" if high is not None else f"an integer >= {low}"
    if not _is_real(value):
        raise GearError(f"{name} = {_show(value)}; valid is {span}")
    v = _whole(value)
    if v is None:
        raise GearError(f"{name} = {_show(value)} is not a whole number; valid is {span}")
    if v < low or (high is not None and v > high):
        raise GearError(f"{name} = {_show(v)}; valid is {span}")
    return v


def check_teeth(name: str, z) -> int:
    """Validate a tooth count: an integer 1 ... :data:`MAX_TEETH` (int-valued floats are
    accepted)."""
    if not _is_real(z):
        raise GearError(f"{name} must be an integer >= 1; got {_show(z)}")
    v = _whole(z)
    if v is None:
        raise GearError(
            f"{name} = {_show(z)} is not a whole number of teeth; valid is an integer 1 ... "
            f"{MAX_TEETH}"
        )
    if not 1 <= v <= MAX_TEETH:
        raise GearError(f"{name} = {_show(v)}; valid is an integer 1 ... {MAX_TEETH}")
    return v


def check_positive(name: str, value, unit: str = "mm") -> float:
    """``value`` as a finite float > 0, or a :class:`GearError` naming it."""
    if not _is_real(value) or not (math.isfinite(_float(value)) and _float(value) > 0.0):
        raise GearError(f"{name} = {_show(value)}; valid is a finite number > 0 ({unit})")
    return float(value)


def check_module(value, name: str = "module") -> float:
    """A module in mm within :data:`MODULE_RANGE`.

    >>> check_module(0.0024)
    0.0024
    """
    lo, hi = MODULE_RANGE
    return check_real(name, value, lo, hi, low_open=False, high_open=False)


def check_pressure_angle(value, name: str = "pressure_angle") -> float:
    """A normal pressure angle in degrees within :data:`PRESSURE_ANGLES` (1 <= alpha < 45)."""
    lo, hi = PRESSURE_ANGLES
    return check_real(name, value, lo, hi, low_open=False)


def check_length(name: str, value, scale: float, of: str = "the module") -> float:
    """A length in mm that shapes a solid or a drawing, within :data:`LENGTH_RANGE` times
    ``scale`` (``of`` says what ``scale`` is, for the message).

    >>> check_length("face_width", 5e-324, 10.0, "the outline's radius")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    gears.errors.GearError: face_width = 5e-324 mm; valid is 1e-05 ... 1e+07 mm (1e-06 ...
    """
    v = check_positive(name, value)
    lo, hi = (f * scale for f in LENGTH_RANGE)
    if not lo <= v <= hi:
        raise GearError(
            f"{name} = {_show(value)} mm; valid is {lo:.3g} ... {hi:.3g} mm "
            f"({LENGTH_RANGE[0]:g} ... {LENGTH_RANGE[1]:g} times {of}, {scale:.6g} mm)"
        )
    return v


def check_angle(name: str, value) -> float:
    """An angle in degrees: any finite real number."""
    if not _is_real(value) or not math.isfinite(_float(value)):
        raise GearError(f"{name} = {_show(value)}; valid is a finite number of degrees")
    return float(value)


def min_tolerance(module: float | None = None) -> float:
    """The finest tolerance honoured, mm: :data:`MIN_TOLERANCE`, or 1e-6 modules for a module
    below 1 mm (the work follows the tolerance relative to the module, so a watch gear may be
    drawn as finely as a gear of module 1).

    >>> min_tolerance(), min_tolerance(0.05)
    (1e-06, 5e-08)
    """
    if module is None:
        return MIN_TOLERANCE
    return MIN_TOLERANCE * min(1.0, float(module))


def check_tolerance(
    tolerance,
    name: str = "tolerance",
    module: float | None = None,
    floor: float | None = None,
    why: str = "the finest this library honours; 1e-4 mm already exceeds any grinder",
) -> float:
    """``tolerance`` as a float in mm, or a :class:`GearError` naming the valid range
    (finite and ``>= min_tolerance(module)``, or ``>= floor`` when given: a solid built from an
    outline takes its floor from the outline's size, and ``why`` says so)."""
    floor = min_tolerance(module) if floor is None else floor
    if not _is_real(tolerance):
        raise GearError(f"{name} = {_show(tolerance)}; valid is a number of mm >= {floor:g}")
    t = _float(tolerance)
    if not (math.isfinite(t) and t >= floor):
        raise GearError(
            f"{name} = {_show(tolerance)} mm; valid is a finite tolerance >= {floor:g} mm ({why})"
        )
    return t


def check_frames(frames, name: str = "frames") -> int:
    """``frames`` as an int in ``1 ... MAX_FRAMES``, or a :class:`GearError` naming the range."""
    if not _is_real(frames):
        raise GearError(f"{name} = {_show(frames)}; valid is an integer 1 ... {MAX_FRAMES}")
    n = _whole(frames)
    if n is None or not 1 <= n <= MAX_FRAMES:
        raise GearError(
            f"{name} = {_show(frames)}; valid is an integer 1 ... {MAX_FRAMES} (a longer animation "
            "takes minutes to render; lower the count)"
        )
    return n


def check_fps(fps, name: str = "fps") -> float:
    """Frames per second within :data:`MIN_FPS` ... :data:`MAX_FPS`."""
    if not _is_real(fps) or not MIN_FPS <= _float(fps) <= MAX_FPS:  # NaN fails too
        raise GearError(f"{name} = {_show(fps)}; valid is a number {MIN_FPS:g} ... {MAX_FPS:g}")
    return float(fps)


def check_flag(name: str, value) -> bool:
    """``True`` or ``False`` (numpy booleans too); anything else is refused, so that a string
    such as ``"no"`` never counts as true."""
    if not isinstance(value, bool | np.bool_):
        raise GearError(f"{name} = {_show(value)}; valid is True or False")
    return bool(value)


def check_choice(name: str, value, options: Iterable[str]) -> str:
    """One of ``options`` (strings)."""
    options = tuple(options)
    if not isinstance(value, str) or value not in options:
        raise GearError(f"{name} = {_show(value)}; valid are {', '.join(map(repr, options))}")
    return value


def check_callback(name: str, value) -> Callable | None:
    """None or a callable (a ``progress`` callback)."""
    if value is not None and not callable(value):
        raise GearError(
            f"{name} = {_show(value)}; valid is None or a callable such as f(done, total)"
        )
    return value


def check_point(name: str, value) -> tuple[float, float]:
    """A pair of finite coordinates in mm."""
    try:
        ok = len(value) == 2 and all(_is_real(v) and math.isfinite(_float(v)) for v in value)
    except TypeError:
        ok = False
    if not ok:
        raise GearError(f"{name} = {_show(value)}; valid is a pair of finite coordinates (mm)")
    return float(value[0]), float(value[1])


def common_shape(shapes: dict[str, tuple[int, ...]]) -> tuple[int, ...]:
    """The shape the arrays of an array entry point broadcast to (numpy's rules), or a
    :class:`GearError` naming two arguments whose shapes do not broadcast together.

    >>> common_shape({"z1": (2, 1), "z2": (3,)})
    (2, 3)
    >>> common_shape({"z1": (2,), "z2": (3,)})
    Traceback (most recent call last):
    ...
    gears.errors.GearError: z1 has shape (2,) and z2 shape (3,): they do not broadcast \
together; valid are arrays of one shape, or shapes numpy broadcasts (lengths equal or 1, \
aligned at the end)
    """
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        pass
    seen: dict[str, tuple[int, ...]] = {}
    for name, shape in shapes.items():
        for other, before in seen.items():
            try:
                np.broadcast_shapes(before, shape)
            except ValueError:
                raise GearError(
                    f"{other} has shape {before} and {name} shape {shape}: they do not broadcast "
                    "together; valid are arrays of one shape, or shapes numpy broadcasts (lengths "
                    "equal or 1, aligned at the end)"
                ) from None
        seen[name] = shape
    raise GearError(  # every pair broadcasts but not all together: cannot happen (numpy's rule)
        f"the shapes {shapes} do not broadcast together; valid are arrays of one shape"
    )
