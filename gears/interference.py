"""Layer 5, interference: the findings of a :class:`gears.GearPair` that its gears' own checks do
not give: tip interference on both flanks and, for an internal pair, the KHK internal-gear checks
(involute, trochoid and radial interference, the ring's tip above its base circle), each a
:class:`gears.report.Finding` with a signed margin and, where it fails, its remedy. The margins are
the vectorised functions of :mod:`gears.checks` and :mod:`gears.meshing`.
"""

from __future__ import annotations

import math

from gears.checks import tip_interference
from gears.meshing import internal_interference
from gears.report import Finding

__all__ = ["interference_findings", "internal_findings"]


def _form_text(gear) -> str:
    form = gear._form
    return "none (the undercut cuts the flank away)" if math.isnan(form) else f"{form:.4f} mm"


def interference_findings(pair) -> list[Finding]:
    """Tip interference on both flanks (``tip_interference``, ``tip_interference_2``) and, for an
    internal pair, :func:`internal_findings`: the findings of ``GearPair.check()`` beyond the
    gears' own and the contact ratio, each with the remedy when it fails."""
    p = pair.path_of_contact
    g1, g2 = pair.mounted
    # gear 2's tip must meet gear 1's flank at or above gear 1's form circle; gear 1's tip
    # (external) at least l2 before N2, (internal) within l2 of N2: gears.checks
    u_f1, l2 = pair._form_lengths
    n2 = 0.0 if pair.is_rack else p.n2
    margin1, margin2 = (
        float(v) for v in tip_interference(p.start, p.end, n2, u_f1, l2, pair.internal)
    )
    clear = pair.tip_diameter_limits[1]
    if pair.is_rack:
        remedy = f"a rack addendum of at most {clear:.4f} mm clears it"
    else:
        bound = "at least" if pair.internal else "at most"
        remedy = f"a mate tip diameter of {bound} {clear:.4f} mm clears it"
    out = [
        Finding(
            "tip_interference", margin1,
            f"mate's tip meets gear 1's flank {margin1:+.4f} mm along the line of action from "
            f"its form circle d_Ff1 = {_form_text(g1)}"
            + ("" if margin1 >= 0 else f" (it reaches the fillet; {remedy})"),
        )
    ]  # fmt: skip
    if pair.is_rack:
        return out
    clear1 = pair.tip_diameter_limits[0]
    out.append(
        Finding(
            "tip_interference_2", margin2,
            f"gear 1's tip meets gear 2's flank {margin2:+.4f} mm along the line of action "
            f"from its form circle d_Ff2 = {_form_text(g2)}"
            + (
                ""
                if margin2 >= 0
                else f" (it reaches the fillet; a tip diameter of at most {clear1:.4f} mm "
                "on gear 1 clears it)"
            ),
        )
    )  # fmt: skip
    if pair.internal:
        out.extend(internal_findings(pair))
    return out


def internal_findings(pair) -> list[Finding]:
    """The internal-gear checks of the KHK Gear Technical Reference for an internal ``pair``,
    each as a signed angle margin."""
    g1, g2 = pair.mounted
    a = pair.center_distance
    ra1, ra2 = g1.tip_diameter / 2, g2.tip_diameter / 2
    rb1, rb2 = g1.base_diameter / 2, g2.base_diameter / 2
    z1, z2 = g1.teeth, g2.teeth
    out = [
        Finding(
            "ring_tip_above_base", ra2 - rb2,
            f"ring tip radius {ra2:.4f} mm vs its base radius {rb2:.4f} mm",
        )
    ]  # fmt: skip
    if ra2 <= rb2 or ra1 <= rb1:
        return out
    m = internal_interference(z1, z2, a, ra1, ra2, rb1, rb2, pair.working_pressure_angle)
    limit = z1 / z2 - float(m.involute)  # 1 - tan(alpha_a2) / tan(alpha_wt)
    out.append(
        Finding(
            "involute_interference", float(m.involute),
            f"z1/z2 = {z1 / z2:.4f} vs 1 - tan(alpha_a2)/tan(alpha_wt) = {limit:.4f} "
            "(ring tip must not pass N1)", unit="",
        )
    )  # fmt: skip
    if ra2 >= a + ra1:
        msg = "tip circles do not cross: no trochoid interference possible"
    elif ra1 >= a + ra2:
        msg = "the ring's tip circle lies inside the pinion's: the tips foul"
    else:
        msg = "tips clear each other while leaving mesh"
    out.append(
        Finding("trochoid_interference", float(m.trochoid), msg + " (margin in rad)", unit="rad")
    )
    msg = (
        "the pinion's tip circle exceeds the ring's: it cannot be moved in radially"
        if ra1 > ra2
        else "pinion can be moved in radially (trimming)"
    )
    out.append(
        Finding("radial_interference", float(m.radial), msg + " (margin in rad)", unit="rad")
    )
    return out
