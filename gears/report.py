"""Layer 1, base.

Design findings: a named condition, whether it holds, its signed margin and a sentence.

Checks never raise for a design that is merely bad; they return a :class:`Report`, an
ordered, read-only mapping from finding name to :class:`Finding`.

Examples
--------
>>> r = Report([Finding("contact_ratio", 0.12, "contact ratio 1.22 >= 1.10", unit="")])
>>> r.ok, r["contact_ratio"].margin
(True, 0.12)
>>> Report([Finding("undercut", -0.05, "x = 0.25 < x_min = 0.30", unit="module")]).failed()
['undercut']
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Iterator, Mapping
from dataclasses import dataclass, field

from gears.display import html_table


@dataclass(frozen=True)
class Finding:
    """One checked condition.

    Parameters
    ----------
    name : str
        Identifier, e.g. ``"undercut"`` or ``"sun-planet.contact_ratio"``.
    margin : float
        Signed distance to the limit; positive (or zero) means satisfied.
    message : str
        A sentence a designer understands, with the numbers compared.
    unit : str
        Unit of the margin (``"mm"``, ``"module"``, ``"teeth"``, ``""`` for a ratio).
    ok : bool, optional
        Defaults to ``margin >= 0``; give it explicitly for a condition whose margin is
        informative only (e.g. a note).
    """

    name: str
    margin: float
    message: str
    unit: str = "mm"
    ok: bool | None = field(default=None)

    def __post_init__(self) -> None:
        margin = float(self.margin)
        if math.isnan(margin):
            raise ValueError(f"finding {self.name!r} has a NaN margin; a check must decide")
        object.__setattr__(self, "margin", margin)
        if self.ok is None:
            object.__setattr__(self, "ok", margin >= 0.0)

    def renamed(self, prefix: str) -> Finding:
        """The same finding with ``prefix + "."`` before its name."""
        return Finding(f"{prefix}.{self.name}", self.margin, self.message, self.unit, self.ok)

    def __str__(self) -> str:
        flag = "ok  " if self.ok else "FAIL"
        unit = f" {self.unit}" if self.unit else ""
        return f"[{flag}] {self.name:<34s} margin {self.margin:+.4g}{unit}: {self.message}"


class Report(Mapping[str, Finding]):
    """Ordered, read-only mapping of findings by name.

    ``report.ok`` is true when every finding holds; ``report.failed()`` lists the names of the
    ones that do not. ``str(report)`` is a readable table.
    """

    def __init__(self, findings: Iterable[Finding] = ()) -> None:
        self._findings: dict[str, Finding] = {}
        for f in findings:
            if f.name in self._findings:
                raise ValueError(f"duplicate finding name {f.name!r}")
            self._findings[f.name] = f

    def __getitem__(self, name: str) -> Finding:
        try:
            return self._findings[name]
        except KeyError:
            raise KeyError(f"no finding {name!r}; findings are {list(self._findings)}") from None

    def __iter__(self) -> Iterator[str]:
        return iter(self._findings)

    def __len__(self) -> int:
        return len(self._findings)

    @property
    def ok(self) -> bool:
        """True when every finding holds."""
        return all(f.ok for f in self._findings.values())

    def failed(self) -> list[str]:
        """Names of the findings that do not hold."""
        return [n for n, f in self._findings.items() if not f.ok]

    def prefixed(self, prefix: str) -> Report:
        """The same findings, each renamed ``prefix.name``."""
        return Report(f.renamed(prefix) for f in self._findings.values())

    def __add__(self, other: Report) -> Report:
        return Report([*self.values(), *other.values()])

    def __str__(self) -> str:
        head = "all conditions hold" if self.ok else f"FAILED: {', '.join(self.failed())}"
        return "\n".join([head, *(str(f) for f in self._findings.values())])

    def __repr__(self) -> str:
        return f"Report(ok={self.ok}, findings={list(self._findings)})"

    def _repr_html_(self) -> str:
        """The findings as an HTML table, failing ones marked: what a notebook shows."""
        head = "all conditions hold" if self.ok else f"FAILED: {', '.join(self.failed())}"
        rows = [
            ("ok" if f.ok else "FAIL", f.name, f"{f.margin:+.4g} {f.unit}".rstrip(), f.message)
            for f in self._findings.values()
        ]
        failing = [not f.ok for f in self._findings.values()]
        return html_table(["", "finding", "margin", "message"], rows, failing=failing,
                          caption=head)  # fmt: skip


def format_duration(seconds: float) -> str:
    """A duration as a person reads it: ``"45 s"``, ``"12 min"``, ``"3.5 h"``, ``"9 days"``,
    ``"2.1e+03 years"`` (for the size and time of refused searches).

    >>> format_duration(45), format_duration(720), format_duration(12600), format_duration(1e6)
    ('45 s', '12 min', '3.5 h', '12 days')
    """
    if seconds < 120:
        return f"{seconds:.0f} s"
    if seconds < 7200:
        return f"{seconds / 60:.0f} min"
    if seconds < 2 * 86400:
        return f"{seconds / 3600:.1f} h"
    if seconds < 2 * 3.15e7:
        return f"{seconds / 86400:.0f} days"
    return f"{seconds / 3.15e7:.3g} years"
