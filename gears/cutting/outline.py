"""Layer 6, outlines: a gear's outline by any method, and both outlines of a pair in mesh.

Dispatches to the analytic envelope (:func:`gears.cutting.profile.outline`) or a simulated cutter
(:mod:`gears.cutting.generate`), takes the gear's flank modification off
(:mod:`gears.contact.flank`), and places a pair's gears at their working centre distance (a
pair's reliefs default to its own short relief, as in the contact analysis).
"""

from __future__ import annotations

import shapely

from gears.arguments import check_angle, check_callback, check_choice, check_point
from gears.contact.flank import relieved_outline
from gears.cutting.cutter import ShaperCutter
from gears.cutting.generate import rack_outline, shaper_outline
from gears.cutting.profile import outline
from gears.cutting.profile import outline_vertices as analytic_vertices
from gears.cutting.sampling import check_blank
from gears.errors import GearError

__all__ = ["METHODS", "gear_outline", "outline_vertices", "pair_outlines", "pair_placement"]

#: The ways to draw an outline: the exact envelope, or a simulated rack or shaper cutter.
METHODS = ("analytic", "rack", "shaper")

#: Vertices of a simulated outline per vertex of the analytic one at the same tolerance (the
#: scallops of the tool positions; measured 3.9 ... 7.2 for racks and shapers at 0.01 and 0.001
#: mm): the estimate a mesh of a simulated outline is budgeted on before the simulation runs.
SIMULATED_VERTICES = 8.0


def outline_vertices(
    gear, tolerance: float, method: str = "analytic", backlash: float = 0.0,
    bore: float | None = None, rim: float | None = None, cutter=None,
) -> float:  # fmt: skip
    """Estimated vertices of :func:`gear_outline` at ``tolerance``, before it is drawn: one
    tooth of the exact envelope sampled, times z, plus the rim or bore circle
    (:func:`gears.cutting.profile.outline_vertices`); :data:`SIMULATED_VERTICES` times that for a
    simulated cutter."""
    method = check_choice("method", method, METHODS)
    if method == "shaper" and cutter is None and getattr(gear, "cutter", None) is None:
        cutter = ShaperCutter.default_for(gear)
    n = analytic_vertices(gear, tolerance, backlash, bore, rim, cutter)
    return n if method == "analytic" else SIMULATED_VERTICES * n


def gear_outline(
    gear, tolerance: float = 0.001, method: str = "analytic", backlash: float = 0.0,
    bore: float | None = None, rim: float | None = None, angle: float = 0.0, center=(0.0, 0.0),
    cutter=None, progress=None, short_relief: float | None = None,
) -> shapely.Polygon:  # fmt: skip
    """Dispatch :meth:`Gear.outline` to the analytic outline or a simulated cutter
    (``progress(done, total)`` reports a simulation's progress), then take the gear's
    ``modification`` tip and root relief off its flanks
    (:func:`gears.contact.flank.relieved_outline`; a relief length left None is
    ``short_relief``, mm of roll, else the gear's own against its basic rack).

    ``cutter`` (a :class:`gears.cutting.cutter.ShaperCutter`) selects the shaper for
    ``method='analytic'`` (its exact envelope) and ``method='shaper'`` (default: the cutter of
    :meth:`ShaperCutter.default_for`).

    Raises
    ------
    GearError
        For an unknown ``method``, or a cutter given with ``method='rack'``.
    """
    angle = check_angle("angle", angle)
    center = check_point("center", center)
    method = check_choice("method", method, METHODS)
    check_callback("progress", progress)
    poly = _unmodified(gear, tolerance, method, backlash, bore, rim, angle, center, cutter,
                       progress)  # fmt: skip
    return relieved_outline(gear, poly, center, short_relief)


def _unmodified(gear, tolerance, method, backlash, bore, rim, angle, center, cutter, progress):
    if method == "analytic":
        return outline(gear, tolerance, backlash, bore, rim, angle, center, cutter)
    if method == "rack":
        if cutter is not None or getattr(gear, "cutter", None) is not None:
            raise GearError(
                "this gear is cut by a shaper cutter; use method='shaper' or 'analytic', not 'rack'"
            )
        check_blank(gear, None, rim, 0.0)  # the rack cuts external gears: rim= means nothing
        return rack_outline(gear, tolerance, backlash, bore, angle, center, progress)
    return shaper_outline(
        gear, tolerance, backlash, bore=bore, rim=rim, angle=angle, center=center,
        cutter=cutter, progress=progress,
    )  # fmt: skip


def pair_outlines(pair, angle: float = 0.0, tolerance: float = 0.001, method: str = "analytic",
                  backlash: float = 0.0, cutter=None, progress=None):  # fmt: skip
    """Outlines of a :class:`GearPair` in mesh, as mounted (tip shortening applied).

    Gear 1 is centred at the origin and turned by ``angle`` degrees (at 0 its tooth 0 points
    along +x, towards gear 2). An external gear 2 sits at ``(a_w, 0)``, a ring at ``(-a_w, 0)``;
    each is turned so the pitch circles roll: at zero backlash both flanks of the tooth in the
    mesh touch (its tooth fills the mating space on the working circle exactly).
    ``backlash`` is the pair's normal backlash; each gear's teeth are thinned by half of it.
    ``method`` applies to both gears; a rack cannot cut a ring, so with ``method='rack'`` the
    ring is cut by its default shaper (simulated). ``cutter`` is a
    :class:`gears.cutting.cutter.ShaperCutter` for both gears or a pair ``(cutter1, cutter2)`` (None
    entries: the gear's default), used with ``method='shaper'`` or ``'analytic'``.
    ``progress(done, 1000)`` reports a simulation of both gears as one run to 1000.

    Returns
    -------
    (shapely.Polygon, shapely.Polygon)
    """
    if pair.is_rack:
        raise GearError("outlines of a pinion-and-rack pair are not drawn; use the gear alone")
    angle = check_angle("angle", angle)
    check_callback("progress", progress)
    g1, g2 = pair.mounted
    c1, c2 = cutter if isinstance(cutter, tuple | list) else (cutter, cutter)
    first = second = None
    if progress is not None:  # one run to 1000: gear 1 fills the first half, gear 2 the second

        def first(done: int, total: int) -> None:
            progress(500 * done // total, 1000)

        def second(done: int, total: int) -> None:
            progress(500 + 500 * done // total, 1000)

    short = _pair_short_relief(pair)
    p1 = gear_outline(g1, tolerance, method, backlash, angle=angle, cutter=c1, progress=first,
                      short_relief=short)  # fmt: skip
    m2 = "shaper" if (g2.internal and method == "rack") else method
    a2, center2 = pair_placement(g1.teeth, g2.teeth, pair.center_distance, g2.internal, angle)
    p2 = gear_outline(g2, tolerance, m2, backlash, angle=a2, center=center2, cutter=c2,
                      progress=second, short_relief=short)  # fmt: skip
    return p1, p2


def _pair_short_relief(pair) -> float | None:
    """The pair's short relief (eps_alpha - 1) p_bt, mm of roll, the default length of a
    relief in mesh (as the contact analysis takes it); None when neither gear is modified."""
    if all(getattr(g, "modification", None) is None for g in (pair.g1, pair.g2)):
        return None
    p = pair.path_of_contact
    return max(p.length - p.base_pitch, 0.0)


def pair_placement(z1: int, z2: int, center_distance: float, internal: bool, angle: float = 0.0):
    """Where gear 2 sits and how far it is turned when gear 1 (at the origin) is turned by
    ``angle`` degrees: ``(angle2 in degrees, (x2, y2) in mm)``.

    At ``angle = 0`` tooth 0 of gear 1 points along +x towards gear 2; an external gear 2 sits at
    ``(a_w, 0)`` with a space facing gear 1 (``180 + 180/z2`` deg), a ring at ``(-a_w, 0)``
    (``180/z2`` deg); the pitch circles roll, so gear 2 turns by ``-+ angle z1/z2``.

    >>> pair_placement(20, 40, 60.0, False, 0.0)
    (184.5, (60.0, 0.0))
    """
    if internal:
        return 180.0 / z2 + angle * z1 / z2, (-center_distance, 0.0)
    return 180.0 + 180.0 / z2 - angle * z1 / z2, (center_distance, 0.0)
