"""Layer 6, design and files: reading a :class:`~trains.willis.Train` from a TOML file.

The format (documented with examples in ``docs/trains.md`` and ``examples/*.toml``)::

    name = "simple planetary 20/30/80"

    [[mesh]]                      # one table per mesh
    gears = ["sun", "planet"]     # members a, b
    teeth = [20, 30]              # z_a, z_b (positive integers)
    carrier = "arm"               # optional; default the frame (fixed axes)
    internal = false              # optional; with real gears the one with more teeth is the ring
    name = "sun-planet"           # optional relation name
    module = 2                    # optional: real gears (normal module, mm); then also:
    shift = [0.3, -0.3]           #   profile shifts x_a, x_b (or one number for both; a
                                  #   ring's in the sign of DIN 3960 / ISO 21771)
    helix = 15                    #   gear a's helix angle (deg); b gets the matching hand
    face_width = [20, 18]         #   mm (or one number for both)
    pressure_angle = 20           #   deg (default: ISO 53, 20)

    [[link]]                      # (w_a - w_c) = ratio (w_b - w_c)
    members = ["a", "b"]
    ratio = "-13/3"               # a number, or a string fraction for exact arithmetic
    carrier = "h"                 # optional

    [[couple]]                    # w_a = w_b
    members = ["planet", "output"]

    coaxial = [["sun", "ring"]]   # optional: groups of members on one axis (Train.coaxial)

    [planets]                     # optional: identical planet copies (structure count)
    planet = 3

    [run]                         # optional defaults for `geartrain train`
    fixed = ["ring"]
    input = {sun = 1500}
    output = "arm"
    mesh_efficiency = 0.98        # a number, or a table {mesh name = efficiency}
    friction = 0.06               # meshes of real gears: efficiency from their geometry

Every error is a :class:`~trains.errors.TrainError` naming the file, the line where it is known
and the field (``train.toml, line 7: mesh #2, 'module': ...``).
"""

from __future__ import annotations

import math
import numbers
import re
import tomllib
from pathlib import Path
from typing import Any

from gears import Gear, GearError
from trains.errors import TrainError
from trains.willis import Train

_GEAR_KEYS = {"module", "shift", "helix", "face_width", "pressure_angle"}
_KEYS = {
    "mesh": {"gears", "teeth", "carrier", "internal", "name", *_GEAR_KEYS},
    "link": {"members", "ratio", "carrier", "name"},
    "couple": {"members", "name"},
}
_TOP = {"name", "mesh", "link", "couple", "planets", "run", "members", "coaxial"}
_RUN = {"fixed", "input", "output", "mesh_efficiency", "friction"}


class _Where:
    """Error messages with the file and, when the text is known, the line of a table or key."""

    def __init__(self, source: str, text: str | None) -> None:
        self.source = source
        self.lines = text.splitlines() if text is not None else None

    def _header(self, kind: str, index: int | None) -> int | None:
        """0-based line of the ``index``-th (1-based) ``[[kind]]`` header, or of ``[kind]``."""
        if self.lines is None:
            return None
        pat = (
            re.compile(rf"^\s*\[\[\s*{kind}\s*\]\]")
            if index
            else re.compile(rf"^\s*\[\s*{kind}\s*\]")
        )
        n = 0
        for i, line in enumerate(self.lines):
            if pat.match(line):
                n += 1
                if not index or n == index:
                    return i
        return None

    def line(
        self, kind: str | None, index: int | None = None, key: str | None = None
    ) -> int | None:
        """1-based line of ``key`` in the table (or at the top level), else of the table."""
        if self.lines is None:
            return None
        start = 0
        if kind is not None:
            h = self._header(kind, index)
            if h is None:
                return None
            start = h + 1  # the header's 1-based line; its keys follow it
        if key is not None:
            kp = re.compile(rf"^\s*\"?{re.escape(key)}\"?\s*=")
            for i in range(start, len(self.lines)):
                if re.match(r"^\s*\[", self.lines[i]):
                    break
                if kp.match(self.lines[i]):
                    return i + 1
        return start if kind is not None else None

    def error(
        self, msg: str, kind: str | None = None, index: int | None = None, key: str | None = None
    ) -> TrainError:
        line = self.line(kind, index, key)
        head = self.source if line is None else f"{self.source}, line {line}"
        what = ""
        if kind is not None:
            what = f"{kind} #{index}" if index else f"[{kind}]"
        if key is not None:
            what = f"{what}, '{key}'" if what else f"'{key}'"
        return TrainError(f"{head}: {what}: {msg}" if what else f"{head}: {msg}")


def _is_number(x: Any) -> bool:
    return isinstance(x, numbers.Real) and not isinstance(x, bool) and math.isfinite(float(x))


def _pair(entry: dict, key: str, where: _Where, kind: str, i: int) -> tuple[str, str]:
    value = entry.get(key)
    if (
        not isinstance(value, list)
        or len(value) != 2
        or not all(isinstance(v, str) and v for v in value)
    ):
        raise where.error(f"must be a list of two member names, got {value!r}", kind, i, key)
    return value[0], value[1]


def _two_numbers(entry: dict, key: str, where: _Where, i: int) -> tuple[Any, Any]:
    value = entry.get(key)
    if value is None:
        return None, None
    if _is_number(value):
        return value, value
    if isinstance(value, list) and len(value) == 2 and all(_is_number(v) for v in value):
        return value[0], value[1]
    raise where.error(f"must be a number or a list of two numbers, got {value!r}", "mesh", i, key)


def _mesh_gears(e: dict, teeth: tuple, internal: bool, where: _Where, i: int) -> tuple | None:
    """The two Gears of a mesh table that gives a module (None for a kinematic-only mesh)."""
    given = sorted(k for k in _GEAR_KEYS if k in e)
    if "module" not in e:
        if given:
            raise where.error(
                f"gear fields {given} need 'module' (a mesh with real gears)", "mesh", i, given[0]
            )
        return None
    module = e["module"]
    if not _is_number(module) or module <= 0:
        raise where.error(f"must be a number > 0 (mm), got {module!r}", "mesh", i, "module")
    x = _two_numbers(e, "shift", where, i)
    b = _two_numbers(e, "face_width", where, i)
    helix = e.get("helix", 0.0)
    if not _is_number(helix):
        raise where.error(f"must be a number (degrees), got {helix!r}", "mesh", i, "helix")
    pa = e.get("pressure_angle")
    if pa is not None and not _is_number(pa):
        raise where.error(f"must be a number (degrees), got {pa!r}", "mesh", i, "pressure_angle")
    za, zb = teeth
    ring = None
    if internal:
        if za == zb:
            raise where.error(
                f"an internal mesh needs a ring with more teeth than its pinion, got {teeth}",
                "mesh", i, "teeth",
            )  # fmt: skip
        ring = 0 if za > zb else 1
    gears = []
    for j, z in enumerate(teeth):
        hand = helix if j == 0 or internal else -helix
        kw = {"profile_shift": 0.0 if x[j] is None else x[j], "face_width": b[j]}
        try:
            gears.append(Gear(z, module, pa, hand, internal=ring == j, **kw))
        except GearError as exc:
            field = "shift" if "profile_shift" in str(exc) else "face_width"
            field = next((k for k in ("helix", "module", "pressure_angle") if k in str(exc)), field)
            raise where.error(str(exc), "mesh", i, field) from None
    return tuple(gears)


def _coaxial(t: Train, data: dict, where: _Where) -> None:
    groups = data.get("coaxial", [])
    if not isinstance(groups, list):
        raise where.error(f"must be a list of member lists, got {groups!r}", key="coaxial")
    for g in groups:
        if not isinstance(g, list) or not all(isinstance(m, str) for m in g):
            raise where.error(f"each group must be a list of member names, got {g!r}",
                              key="coaxial")  # fmt: skip
        try:
            t.coaxial(*g)
        except TrainError as exc:
            raise where.error(str(exc), key="coaxial") from None


def _planets(t: Train, data: dict, where: _Where) -> None:
    planets = data.get("planets", {})
    if not isinstance(planets, dict):
        raise where.error(
            f"[planets] must be a table of member = count, got {planets!r}", key="planets"
        )
    for member, count in planets.items():
        if isinstance(count, bool) or not isinstance(count, int) or count < 1:
            raise where.error(f"must be a whole number >= 1, got {count!r}", "planets", None,
                              member)  # fmt: skip
        try:
            t.set_planets(member, count)
        except TrainError as exc:
            raise where.error(str(exc), "planets", None, member) from None


def _run(data: dict, where: _Where) -> dict[str, Any]:
    run = data.get("run", {})
    if not isinstance(run, dict):
        raise where.error(f"[run] must be a table, got {run!r}", key="run")
    extra = set(run) - _RUN
    if extra:
        raise where.error(f"unknown keys {sorted(extra)}; expected {sorted(_RUN)}", "run")
    fixed = run.get("fixed", [])
    if isinstance(fixed, str):
        fixed = [fixed]
    if not isinstance(fixed, list) or not all(isinstance(f, str) for f in fixed):
        raise where.error(f"must be a member name or a list of them, got {fixed!r}", "run", None,
                          "fixed")  # fmt: skip
    inp = run.get("input")
    if inp is not None and (
        not isinstance(inp, dict)
        or not all(_is_number(v) or isinstance(v, str) for v in inp.values())
    ):
        raise where.error(f"must be a table {{member = speed}}, got {inp!r}", "run", None, "input")
    out = run.get("output")
    if out is not None and not isinstance(out, str):
        raise where.error(f"must be a member name, got {out!r}", "run", None, "output")
    eta = run.get("mesh_efficiency")
    if eta is not None and not (
        _is_number(eta) or (isinstance(eta, dict) and all(_is_number(v) for v in eta.values()))
    ):
        raise where.error(f"must be a number or a table {{mesh = efficiency}}, got {eta!r}",
                          "run", None, "mesh_efficiency")  # fmt: skip
    f = run.get("friction")
    if f is not None and not (_is_number(f) and 0 <= f < 1):
        raise where.error(f"must be a number 0 <= f < 1, got {f!r}", "run", None, "friction")
    return {**run, "fixed": fixed} if "fixed" in run else dict(run)


def train_from_dict(data: dict[str, Any], source: str = "<dict>", text: str | None = None) -> Train:
    """Build a train from the parsed TOML table (see the module docstring for the keys).

    ``text`` (the TOML source) lets the errors name the line.

    Examples
    --------
    >>> t = train_from_dict({"mesh": [{"gears": ["a", "b"], "teeth": [10, 30]}]})
    >>> t.ratio("a", "b")
    Fraction(-3, 1)
    >>> t = train_from_dict({"mesh": [{"gears": ["a", "b"], "teeth": [17, 40], "module": 2}]})
    >>> round(t.pairs["a-b"].center_distance, 6)
    57.0
    """
    where = _Where(source, text)
    if not isinstance(data, dict):
        raise where.error(f"a train file is a TOML table, got {type(data).__name__}")
    unknown = set(data) - _TOP
    if unknown:
        raise where.error(f"unknown top-level keys {sorted(unknown)}; expected {sorted(_TOP)}",
                          key=sorted(unknown)[0])  # fmt: skip
    t = Train()
    name = data.get("name", "")
    if not isinstance(name, str):
        raise where.error(f"must be a string, got {name!r}", key="name")
    t.name = name
    members = data.get("members", [])
    if not isinstance(members, list) or not all(isinstance(m, str) and m for m in members):
        raise where.error(f"must be a list of member names, got {members!r}", key="members")
    for m in members:
        t.add_member(m)
    for kind in ("mesh", "link", "couple"):
        entries = data.get(kind, [])
        if not isinstance(entries, list):
            raise where.error(f"must be an array of tables ([[{kind}]])", key=kind)
        for i, e in enumerate(entries, start=1):
            if not isinstance(e, dict):
                raise where.error("must be a table", kind, i)
            extra = set(e) - _KEYS[kind]
            if extra:
                raise where.error(
                    f"unknown keys {sorted(extra)}; expected {sorted(_KEYS[kind])}", kind, i,
                    sorted(extra)[0],
                )  # fmt: skip
            for key in ("carrier", "name"):
                if key in e and not (isinstance(e[key], str) and e[key]):
                    raise where.error(f"must be a non-empty string, got {e[key]!r}", kind, i, key)
            _add(t, kind, e, where, i)
    _coaxial(t, data, where)
    _planets(t, data, where)
    t.run_defaults = _run(data, where)
    return t


def _add(t: Train, kind: str, e: dict, where: _Where, i: int) -> None:
    if kind == "mesh":
        a, b = _pair(e, "gears", where, kind, i)
        teeth = e.get("teeth")
        if (
            not isinstance(teeth, list)
            or len(teeth) != 2
            or not all(isinstance(z, int) and not isinstance(z, bool) for z in teeth)
        ):
            raise where.error(f"must be a list of two integers, got {teeth!r}", kind, i, "teeth")
        internal = e.get("internal", False)
        if not isinstance(internal, bool):
            raise where.error(f"must be true or false, got {internal!r}", kind, i, "internal")
        try:
            gears = _mesh_gears(e, tuple(teeth), internal, where, i)
            if gears is None:
                t.mesh(a, b, teeth=tuple(teeth), carrier=e.get("carrier"), internal=internal,
                       name=e.get("name"))  # fmt: skip
            else:
                t.mesh(a, b, gears=gears, carrier=e.get("carrier"), name=e.get("name"))
        except TrainError as exc:
            msg = str(exc)
            if msg.startswith(where.source):
                raise
            field = "teeth" if "tooth count" in msg else "shift" if "x1 + x2" in msg else "gears"
            raise where.error(msg, kind, i, field) from None
        return
    a, b = _pair(e, "members", where, kind, i)
    try:
        if kind == "link":
            if "ratio" not in e:
                raise where.error("'ratio' is required", kind, i)
            t.link(a, b, ratio=e["ratio"], carrier=e.get("carrier"), name=e.get("name"))
        else:
            t.couple(a, b, name=e.get("name"))
    except TrainError as exc:
        msg = str(exc)
        if msg.startswith(where.source):
            raise
        raise where.error(msg, kind, i, "ratio" if "ratio" in msg else "members") from None


def read_train(path: Any) -> Train:
    """Read a train from a TOML file (``geartrain train FILE``).

    Raises
    ------
    TrainError
        For a missing file, a directory, a file that is not UTF-8 text or not valid TOML, or a
        field of the wrong type or value; the message names the file, the line where it is
        known, and the field.
    """
    try:
        p = Path(path)
    except TypeError:
        raise TrainError(f"a train file path must be a string or a Path, got {path!r}") from None
    try:
        if p.is_dir():
            raise TrainError(f"{p}: is a directory, not a train file")
        raw = p.read_bytes()
    except FileNotFoundError:
        raise TrainError(f"no such train file: {p}") from None
    except (OSError, ValueError) as exc:
        raise TrainError(f"{p}: cannot be read ({getattr(exc, 'strerror', None) or exc})") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw[: exc.start].count(b"\n") + 1
        raise TrainError(
            f"{p}, line {line}: not UTF-8 text (byte {exc.start}: {raw[exc.start]:#04x});"
            " save the train file as UTF-8"
        ) from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise TrainError(f"{p}: not valid TOML: {exc}") from None
    except RecursionError:
        raise TrainError(f"{p}: not valid TOML: nested too deeply") from None
    return train_from_dict(data, source=str(p), text=text)
