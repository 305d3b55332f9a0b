"""gears.rack: ISO 53 basic racks, the stub tooth, the generating tool and its limits."""

import math

import pytest

from gears import BasicRack, Gear
from gears.errors import GearError
from gears.geometry import min_profile_shift

SIN20 = math.sin(math.radians(20.0))


@pytest.mark.parametrize(
    ("profile", "dedendum", "radius", "depth", "z_min"),
    [
        # standards.md §1.1 (h*_eff) and §1.6 (z_min with the tool tip radius)
        ("A", 1.25, 0.38, 1.0000, 17.10),
        ("B", 1.25, 0.30, 1.0526, 18.00),
        ("C", 1.25, 0.25, 1.0855, 18.56),
        ("D", 1.40, 0.39, 1.1434, 19.55),
    ],
)
def test_iso53_profiles(profile, dedendum, radius, depth, z_min):
    rack = BasicRack.iso53(profile)
    assert (rack.pressure_angle, rack.addendum, rack.dedendum, rack.root_radius) == (
        20.0,
        1.0,
        dedendum,
        radius,
    )
    assert rack.bottom_clearance == pytest.approx(dedendum - 1.0)
    assert rack.tool_addendum == dedendum and rack.tool_tip_radius == radius
    assert rack.straight_flank_depth == pytest.approx(depth, abs=5e-5)
    # z_min is where the minimum profile shift crosses zero: h*_eff - z sin^2(alpha) / 2 = 0
    z0 = 2 * rack.straight_flank_depth / SIN20**2
    assert z0 == pytest.approx(z_min, abs=0.005)
    assert float(min_profile_shift(z0, 20.0, 0.0, rack.straight_flank_depth)) == pytest.approx(
        0.0, abs=1e-12
    )
    # and through a Gear: undercut just below z_min, not just above
    below, above = math.floor(z0), math.ceil(z0)
    assert Gear(below, 1, rack=rack).undercut
    assert not Gear(above, 1, rack=rack).undercut


def test_profile_a_tip_radius_fits_constant_clearance():
    # standards.md §1.1: c / (1 - sin alpha) = 0.3799 m, why profile A uses 0.38 m
    assert 0.25 / (1 - SIN20) == pytest.approx(0.3799, abs=1e-4)
    assert BasicRack.iso53("a").name == "ISO 53 A"


def test_stub_tooth_undercut_limit():
    # Ozols §2.13/2.15 and in-text statement: kappa = 0.8 gives z_min^inf = 13.68 ("14");
    # Joldasbekov E2 derived: f0 = 0.8 -> 13.68. The tool's tip rounding only forms the
    # clearance and must not cut the involute (Joldasbekov §2.8), so the straight flank of the
    # stub tool reaches exactly h_a* = 0.8.
    stub = BasicRack.stub()
    assert stub.addendum == 0.8
    assert stub.straight_flank_depth == pytest.approx(0.8, abs=1e-12)
    assert 2 * stub.straight_flank_depth / SIN20**2 == pytest.approx(13.68, abs=0.005)
    assert Gear(13, 1, rack=stub).undercut
    assert not Gear(14, 1, rack=stub).undercut
    assert stub.root_radius <= stub.max_root_radius
    # at another pressure angle the same rule holds (15 deg: 2 * 0.8 / sin^2 15 = 23.88)
    stub15 = BasicRack.stub(15.0)
    assert stub15.straight_flank_depth == pytest.approx(0.8, abs=1e-12)


def test_custom_rack_and_reangle():
    rack = BasicRack(pressure_angle=25.0, addendum=1.0, dedendum=1.25, root_radius=0.2)
    # independent derivation: depth = h_fP - rho (1 - sin alpha)
    assert rack.straight_flank_depth == pytest.approx(1.25 - 0.2 * (1 - math.sin(math.radians(25))))
    # the 14.5 deg rack (standards.md §1.6: z_min = 31.90 with h* = 1)
    r145 = BasicRack.iso53("A").with_pressure_angle(14.5)
    assert r145.pressure_angle == 14.5 and r145.root_radius <= r145.max_root_radius
    assert 2 * 1.0 / math.sin(math.radians(14.5)) ** 2 == pytest.approx(31.90, abs=0.005)
    # a Gear given another pressure angle re-angles its rack
    assert Gear(20, 1, pressure_angle=25).rack.pressure_angle == 25.0


def test_max_root_radius_independent():
    # independent derivation: half tool tooth at its tip line = pi/4 - h_fP tan(alpha); a round
    # of radius rho tangent to the flank and the tip line eats rho (1 - sin a)/cos a of it
    a = math.radians(20)
    half = math.pi / 4 - 1.25 * math.tan(a)
    rho = BasicRack.iso53("A").max_root_radius
    assert rho * (1 - math.sin(a)) / math.cos(a) == pytest.approx(half, rel=1e-14)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"pressure_angle": 0.0}, "pressure_angle"),
        ({"pressure_angle": 45.0}, "pressure_angle"),
        ({"pressure_angle": -5.0}, "pressure_angle"),
        ({"addendum": 0.0}, "addendum"),
        ({"addendum": float("nan")}, "addendum"),
        ({"dedendum": 0.9}, "dedendum"),
        ({"root_radius": -0.1}, "root_radius"),
        ({"root_radius": 0.6}, "root_radius"),
        ({"protuberance": -0.01}, "protuberance"),
        ({"dedendum": "1.25"}, "dedendum"),
        ({"pressure_angle": 40.0, "dedendum": 2.0, "root_radius": 0.0}, "dedendum"),
    ],
)
def test_invalid_rack_raises_naming_the_value(kwargs, name):
    with pytest.raises(GearError, match=name):
        BasicRack(**kwargs)


def test_unknown_iso53_profile():
    with pytest.raises(GearError, match="'E'"):
        BasicRack.iso53("E")
