"""Notebook displays (gears/display.py, gears/drawing.py): the SVG of a gear and a pair, the HTML
tables of a Report and a SearchResult (issue 21).

The SVGs are parsed with xml.etree and read back as geometry: the drawn points are checked
against the gears' own circles (an independent route: the definitions of the tip circles and of
the path of contact), so a picture that looks right but is placed wrong fails. The HTML is parsed
with html.parser. Hypothesis sweeps gears and pairs: a display never raises, and what cannot be
drawn shows the library's own message (never "a bug").
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from html.parser import HTMLParser

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from gears import Gear, GearError, GearPair, Rack, search
from gears.display import html_table, message_svg, svg
from gears.figures.drawing import WIDTH, display_tolerance, gear_svg, shown
from gears.report import Finding, Report

NS = "{http://www.w3.org/2000/svg}"


def parse(text: str) -> ET.Element:
    root = ET.fromstring(text)
    assert root.tag == f"{NS}svg"
    return root


def view_box(root: ET.Element) -> tuple[float, float, float, float]:
    x0, y0, w, h = map(float, root.get("viewBox").split())
    assert w > 0 and h > 0
    return x0, y0, w, h


def paths(root: ET.Element) -> list[list[np.ndarray]]:
    """Each <path> as its rings in drawing coordinates (the y flip of gears.display undone)."""
    _, y0, _, h = view_box(root)
    out = []
    for el in root.iter(f"{NS}path"):
        rings = []
        for part in el.get("d").split("M")[1:]:
            xy = np.array([p.split(",") for p in part.rstrip(" Z").split(" L")], float)
            rings.append(np.column_stack([xy[:, 0], 2 * y0 + h - xy[:, 1]]))
        out.append(rings)
    return out


def is_message(root: ET.Element) -> str:
    return " ".join(t.text or "" for t in root.iter(f"{NS}tspan"))


def test_gear_svg_is_its_outline():
    # source: the outline itself (gears.cutting.outline at the display tolerance): the drawn
    # polygon has
    # its area to the written digits (2 decimals at this size), the view box holds the tip
    # circle with a 2 % margin, the dashed circle is the reference circle d = z m
    g = Gear(12, 3, profile_shift=0.6)
    root = parse(g._repr_svg_())
    assert root.get("width") == str(WIDTH)
    (rings,) = paths(root)
    assert len(rings) == 1
    drawn = shapely.Polygon(rings[0])
    exact = g.outline(display_tolerance(g.tip_diameter))
    assert drawn.area == pytest.approx(exact.area, rel=1e-3)
    x0, _, w, _ = view_box(root)
    assert w == pytest.approx(1.04 * g.tip_diameter, rel=1e-3)
    assert x0 == pytest.approx(-0.52 * g.tip_diameter, rel=1e-3)
    (circle,) = root.iter(f"{NS}circle")
    assert float(circle.get("r")) == pytest.approx(g.reference_diameter / 2, abs=0.01)
    assert "teeth=12" in root.find(f"{NS}title").text


def test_ring_gear_svg_keeps_its_hole():
    # an internal gear is a rim with a toothed hole: one path of two rings (evenodd)
    root = parse(Gear(60, 2, internal=True)._repr_svg_())
    (rings,) = paths(root)
    assert len(rings) == 2
    assert next(root.iter(f"{NS}path")).get("fill-rule") == "evenodd"


@pytest.mark.parametrize(
    "pair",
    [
        GearPair(Gear(12, 3, profile_shift=0.6), Gear(24, 3, profile_shift=0.36)),
        GearPair(Gear(20, 2, profile_shift=0.3), Gear(80, 2, internal=True, profile_shift=-0.5)),
    ],
    ids=["external", "internal"],
)
def test_pair_svg_draws_the_path_of_contact_between_the_tip_circles(pair):
    # source: the definition of the path of contact (ISO 21771 §5.4): it starts at A on gear
    # 2's tip circle and ends at E on gear 1's tip circle (gear 1 at the origin, gear 2 at
    # (+-a_w, 0)); the line of action touches both base circles
    root = parse(pair._repr_svg_())
    drawn = paths(root)
    assert len(drawn) == 4  # gear 1, gear 2, line of action, path of contact
    assert len(list(root.iter(f"{NS}circle"))) == 2  # the working circles
    (contact,) = drawn[3]
    g1, g2 = pair.mounted
    centre2 = np.array([-pair.center_distance if pair.internal else pair.center_distance, 0.0])
    a, e = contact
    resolution = 0.02  # mm: two decimals written at this size
    assert np.hypot(*e) == pytest.approx(g1.tip_diameter / 2, abs=resolution)
    assert np.hypot(*(a - centre2)) == pytest.approx(g2.tip_diameter / 2, abs=resolution)
    (line,) = drawn[2]
    along = (line[1] - line[0]) / np.hypot(*(line[1] - line[0]))

    def distance(point):  # from the drawn line of action
        dx, dy = point - line[0]
        return abs(along[0] * dy - along[1] * dx)

    assert distance(np.zeros(2)) == pytest.approx(g1.base_diameter / 2, abs=resolution)
    assert distance(centre2) == pytest.approx(g2.base_diameter / 2, abs=resolution)
    # the two outlines do not overlap (placed in mesh at zero backlash)
    p1, p2 = (shapely.Polygon(r[0], r[1:]) for r in drawn[:2])
    assert p1.intersection(p2).area < 0.01 * p1.area


def test_what_cannot_be_drawn_says_why():
    # z = 4, x = -0.5: the fillets cut the teeth away; the outline is refused by
    # gears.cutting.profile
    root = parse(Gear(4, 1, profile_shift=-0.5)._repr_svg_())
    text = is_message(root)
    assert text.startswith("this gear is not drawn") and "undercut" in text
    root = parse(GearPair(Gear(20, 2), Rack(2))._repr_svg_())
    assert "pinion-and-rack" in is_message(root)


def test_a_failure_that_is_not_the_librarys_own_says_it_is_a_bug():
    def broken() -> str:
        return str(1 / 0)

    text = is_message(parse(shown("this gear", broken)))
    assert "ZeroDivisionError" in text and "bug" in text


def test_svg_writes_lines_circles_and_escapes():
    text = svg(
        [(shapely.LineString([(0, 0), (4, 2)]), {"stroke": "a<b"})],
        margin=0, digits=1, title="x & y",
    )  # fmt: skip
    root = parse(text)
    assert view_box(root) == pytest.approx((0, 0, 4, 2))
    assert root.find(f"{NS}title").text == "x & y"
    (line,) = paths(root)
    np.testing.assert_allclose(line[0], [[0, 0], [4, 2]])  # open: no Z, flip undone
    assert "Z" not in next(root.iter(f"{NS}path")).get("d")
    assert parse(message_svg("a < b")).find(f".//{NS}tspan").text == "a < b"


class _Table(HTMLParser):
    """Rows of an HTML table as lists of cell texts, with each row's class."""

    def __init__(self, text: str) -> None:
        super().__init__()
        self.rows: list[tuple[str | None, list[str]]] = []
        self.caption = ""
        self._in: str | None = None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self.rows.append((dict(attrs).get("class"), []))
        elif tag in ("td", "th", "caption"):
            self._in = tag
            if tag != "caption":
                self.rows[-1][1].append("")

    def handle_endtag(self, tag):
        self._in = None

    def handle_data(self, data):
        if self._in == "caption":
            self.caption += data
        elif self._in:
            self.rows[-1][1][-1] += data


def test_report_html_marks_the_failing_findings():
    # the internal pair of the README: the ring's tip reaches the pinion's fillet
    ring = Gear(80, 2, internal=True, profile_shift=-0.3)
    report = GearPair(Gear(20, 2, profile_shift=0.3), ring).check()
    table = _Table(report._repr_html_())
    head, *body = table.rows
    assert head[1] == ["", "finding", "margin", "message"]
    assert [cells[1] for _, cells in body] == list(report)
    assert [cells[1] for cls, cells in body if cls == "fail"] == report.failed()
    assert all(cells[0] == ("FAIL" if cls == "fail" else "ok") for cls, cells in body)
    assert table.caption == f"FAILED: {', '.join(report.failed())}"
    margin = report["tip_interference"].margin
    (row,) = [cells for _, cells in body if cells[1] == "tip_interference"]
    assert float(row[2].split()[0]) == pytest.approx(margin, rel=1e-3)  # 4 significant digits


def test_html_table_escapes_its_cells():
    table = _Table(html_table(["a"], [["<b>&"]], failing=[True], caption="c<"))
    assert table.rows == [(None, ["a"]), ("fail", ["<b>&"])]
    assert table.caption == "c<"
    report = Report([Finding("x<y", -1.0, "a & b", unit="")])
    assert _Table(report._repr_html_()).rows[1] == ("fail", ["FAIL", "x<y", "-1", "a & b"])


def test_search_result_html_is_the_ranked_table():
    # the same cells as the text table (SearchResult.format), at most 50 rows in HTML
    res = search.pairs(ratio=2.0, module=2, teeth=(14, 40), top=None, progress=False)
    table = _Table(res._repr_html_())
    head, *body = table.rows
    text = res.format().splitlines()
    assert head[1] == text[0].split()
    assert len(body) == min(len(res), 50)
    assert body[0][1] == text[1].split()
    assert table.caption.startswith(f"{len(res)} pairs of {res.feasible} feasible")


_settings = settings(max_examples=25, deadline=None,
                     suppress_health_check=[HealthCheck.too_slow])  # fmt: skip


def _drawn_or_explained(text: str) -> None:
    root = parse(text)  # always a valid SVG
    message = is_message(root)
    if message:
        assert "bug" not in message, message
        assert re.match(r"this (gear|pair) is not drawn: \S", message)
    else:
        assert paths(root) and all(math.isfinite(v) for v in view_box(root))


@_settings
@given(
    z=st.integers(1, 400), m=st.floats(0.05, 50), x=st.floats(-1.5, 2.5),
    beta=st.sampled_from([0.0, 15.0, -30.0]), internal=st.booleans(),
)  # fmt: skip
def test_gear_display_never_raises(z, m, x, beta, internal):
    try:
        g = Gear(z, m, profile_shift=x, helix_angle=beta, internal=internal)
    except GearError:
        return  # refused at construction: nothing to display
    _drawn_or_explained(g._repr_svg_())
    _drawn_or_explained(gear_svg(g))
    _Table(g.check()._repr_html_())


@_settings
@given(
    z1=st.integers(3, 60), z2=st.integers(3, 200), m=st.floats(0.2, 20),
    x1=st.floats(-1.0, 1.5), x2=st.floats(-1.0, 1.5), internal=st.booleans(),
)  # fmt: skip
def test_pair_display_never_raises(z1, z2, m, x1, x2, internal):
    try:
        pair = GearPair(Gear(z1, m, profile_shift=x1), Gear(z2, m, profile_shift=x2,
                                                             internal=internal))  # fmt: skip
    except GearError:
        return
    _drawn_or_explained(pair._repr_svg_())
    _Table(pair.check()._repr_html_())


def test_rating_html_shows_safeties_factors_and_quantities():
    # the rating's own numbers (gears.rating.capacity.Rating), printed to 4 decimals; the safety
    # rows
    # are marked exactly when check() (S_Hmin = 1, S_Fmin = 1.4) fails them: at 200 N m this
    # pair holds, at 2000 N m every safety fails (the rating's own check)
    from gears.rating.iso6336 import FACTORS, QUANTITIES

    pair = GearPair(Gear(20, 3, face_width=30), Gear(50, 3, face_width=30))
    for torque, failing in ((200, []), (2000, ["safety pitting S_H", "safety bending S_F"])):
        rating = pair.rating(torque, 1500)
        text = rating._repr_html_()
        assert text.count("<table>") == 3
        safeties, factors, quantities = (_Table(t) for t in text.split("</table>")[:3])
        assert safeties.caption.startswith("ISO 6336 method B rating: 20/50 (external)")
        body = {cells[0]: (cls, cells[1:]) for cls, cells in safeties.rows[1:]}
        for name, values in (("safety pitting S_H", rating.safety_pitting),
                             ("safety bending S_F", rating.safety_bending)):  # fmt: skip
            np.testing.assert_allclose([float(v) for v in body[name][1]], values, atol=6e-5)
        assert [n for n, (cls, _) in body.items() if cls == "fail"] == failing
        assert bool(failing) == (not rating.check().ok)
        assert [cells[0] for _, cells in factors.rows[1:]] == [f[0] for f in FACTORS]
        assert [cells[0] for _, cells in quantities.rows[1:]] == [q[0] for q in QUANTITIES]


@pytest.mark.parametrize("clearance", ["tapered", "constant"])
def test_bevel_axial_section_meets_the_blank_dimensions(clearance):
    # source: KHK Table 4.10 blank dimensions as gears.bevel.cone.bevel_geometry computes them
    # (outside diameter d_ae, pitch apex to crown X, inner outside diameter
    # d_ai = d_ae - 2 b sin(delta_a) / cos(theta_a)): the section's outer tip is (d_ae/2, X) and
    # its inner tip lies at d_ai/2 from the axis; with tapered clearance every cone meets the
    # pitch apex, so the inner corners are the outer ones scaled by R_i / R_e
    from gears.bevel.cone import axial_section, bevel_geometry

    b = 22.0
    g = bevel_geometry(20, 40, 3.0, b, clearance=clearance)
    s = axial_section(g.pitch_angle, g.face_angle, g.root_angle, g.cone_distance, b,
                      g.addendum, g.dedendum)  # fmt: skip
    assert s.shape == (2, 4, 2)
    np.testing.assert_allclose(s[:, 0, 0], g.tip_diameter / 2, rtol=1e-12)
    np.testing.assert_allclose(s[:, 0, 1], g.crown_to_apex, rtol=1e-12)
    np.testing.assert_allclose(s[:, 3, 0], g.inner_tip_diameter / 2, rtol=1e-12)
    # the root line runs from the outer root through the pitch apex (theta_f = atan(h_fm / R_m))
    np.testing.assert_allclose(s[:, 2] * (g.cone_distance / (g.cone_distance - b)), s[:, 1],
                               rtol=1e-12)  # fmt: skip
    if clearance == "tapered":
        np.testing.assert_allclose(s[:, 3] * (g.cone_distance / (g.cone_distance - b)), s[:, 0],
                                   rtol=1e-12)  # fmt: skip


@pytest.mark.parametrize("shaft_angle", [90.0, 60.0])
def test_bevel_pair_svg_puts_each_tip_where_its_blank_says(shaft_angle):
    # the drawn tooth zones: gear 1's outer tip at (X_1, +-d_ae1/2) about the x axis, gear 2's
    # at X_2 along its axis (at the shaft angle) and d_ae2/2 off it (two decimals written)
    from gears import BevelPair

    pair = BevelPair(20, 30, module=3, face_width=15, shaft_angle=shaft_angle)
    root = parse(pair._repr_svg_())
    corners = np.concatenate([r[0] for r in paths(root) if len(r[0]) == 4])
    sigma = math.radians(shaft_angle)
    axes = [(np.array([1.0, 0.0]), np.array([0.0, 1.0])),
            (np.array([math.cos(sigma), math.sin(sigma)]),
             np.array([math.sin(sigma), -math.cos(sigma)]))]  # fmt: skip
    for gear, (a, p) in zip(pair.gears, axes, strict=True):
        for side in (1, -1):
            tip = gear.crown_to_apex * a + side * gear.tip_diameter / 2 * p
            assert np.min(np.hypot(*(corners - tip).T)) < 0.02
    assert root.find(f"{NS}title").text.startswith("BevelPair(20, 30")


@_settings
@given(
    z1=st.integers(1, 80), z2=st.integers(1, 120), m=st.floats(0.2, 20),
    b=st.floats(0.5, 200), sigma=st.floats(5, 175),
)  # fmt: skip
def test_bevel_display_never_raises(z1, z2, m, b, sigma):
    from gears import BevelPair

    try:
        pair = BevelPair(z1, z2, module=m, face_width=b, shaft_angle=sigma)
    except GearError:
        return
    root = parse(pair._repr_svg_())
    message = is_message(root)
    assert not message or ("bug" not in message and message.startswith("this bevel pair"))
