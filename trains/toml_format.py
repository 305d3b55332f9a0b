"""Layer 5, design and files: reading a :class:`~trains.willis.Train` from a TOML file.

The format (documented with examples in ``docs/trains.md`` and ``examples/*.toml``)::

    name = "simple planetary 20/30/80"

    [[mesh]]                      # one table per mesh
    gears = ["sun", "planet"]     # members a, b
    teeth = [20, 30]              # z_a, z_b (positive integers)
    carrier = "arm"               # optional; default the frame (fixed axes)
    internal = false              # optional
    name = "sun-planet"           # optional relation name

    [[link]]                      # (w_a - w_c) = ratio (w_b - w_c)
    members = ["a", "b"]
    ratio = "-13/3"               # a number, or a string fraction for exact arithmetic
    carrier = "h"                 # optional

    [[couple]]                    # w_a = w_b
    members = ["planet", "output"]

    [planets]                     # optional: identical planet copies (structure count)
    planet = 3

    [run]                         # optional defaults for `geartrain train`
    fixed = ["ring"]
    input = {sun = 1500}
    output = "arm"
    mesh_efficiency = 0.98
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

from trains.errors import TrainError
from trains.willis import Train

_KEYS = {
    "mesh": {"gears", "teeth", "carrier", "internal", "name"},
    "link": {"members", "ratio", "carrier", "name"},
    "couple": {"members", "name"},
}
_TOP = {"name", "mesh", "link", "couple", "planets", "run", "members"}


def _pair(entry: dict, key: str, where: str) -> tuple[str, str]:
    value = entry.get(key)
    if not isinstance(value, list) or len(value) != 2:
        raise TrainError(f"{where}: '{key}' must be a list of two member names, got {value!r}")
    return value[0], value[1]


def train_from_dict(data: dict[str, Any], source: str = "<dict>") -> Train:
    """Build a train from the parsed TOML table (see the module docstring for the keys).

    Examples
    --------
    >>> t = train_from_dict({"mesh": [{"gears": ["a", "b"], "teeth": [10, 30]}]})
    >>> t.ratio("a", "b")
    Fraction(-3, 1)
    """
    unknown = set(data) - _TOP
    if unknown:
        raise TrainError(
            f"{source}: unknown top-level keys {sorted(unknown)}; expected {sorted(_TOP)}"
        )
    t = Train()
    t.name = str(data.get("name", ""))
    for m in data.get("members", []):
        t.add_member(m)
    for kind in ("mesh", "link", "couple"):
        entries = data.get(kind, [])
        if not isinstance(entries, list):
            raise TrainError(f"{source}: '{kind}' must be an array of tables ([[{kind}]])")
        for i, e in enumerate(entries, start=1):
            where = f"{source}: {kind} #{i}"
            if not isinstance(e, dict):
                raise TrainError(f"{where}: must be a table")
            extra = set(e) - _KEYS[kind]
            if extra:
                raise TrainError(
                    f"{where}: unknown keys {sorted(extra)}; expected {sorted(_KEYS[kind])}"
                )
            try:
                if kind == "mesh":
                    a, b = _pair(e, "gears", where)
                    teeth = e.get("teeth")
                    if not isinstance(teeth, list) or len(teeth) != 2:
                        raise TrainError(f"'teeth' must be a list of two integers, got {teeth!r}")
                    t.mesh(a, b, teeth=tuple(teeth), carrier=e.get("carrier"),
                           internal=bool(e.get("internal", False)), name=e.get("name"))  # fmt: skip
                elif kind == "link":
                    a, b = _pair(e, "members", where)
                    if "ratio" not in e:
                        raise TrainError("'ratio' is required")
                    t.link(a, b, ratio=e["ratio"], carrier=e.get("carrier"), name=e.get("name"))
                else:
                    a, b = _pair(e, "members", where)
                    t.couple(a, b, name=e.get("name"))
            except TrainError as exc:
                msg = str(exc)
                raise TrainError(msg if msg.startswith(where) else f"{where}: {msg}") from None
    for member, count in dict(data.get("planets", {})).items():
        t.set_planets(member, count)
    t.run_defaults = dict(data.get("run", {}))
    return t


def read_train(path: Any) -> Train:
    """Read a train from a TOML file (``geartrain train FILE``)."""
    p = Path(path)
    try:
        with p.open("rb") as f:
            data = tomllib.load(f)
    except FileNotFoundError:
        raise TrainError(f"no such train file: {p}") from None
    except tomllib.TOMLDecodeError as exc:
        raise TrainError(f"{p}: not valid TOML: {exc}") from None
    return train_from_dict(data, source=str(p))
