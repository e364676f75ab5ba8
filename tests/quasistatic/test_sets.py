"""Issue 11 section 4: preloaded bearing sets on a rigid shaft (quasistatic.sets)."""

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose

from bearinglab import catalog
from bearinglab.bearing import BallBearing
from bearinglab.errors import InputError
from bearinglab.quasistatic import combined, sets
from bearinglab.quasistatic.contact import contact_stiffness
from bearinglab.units import RPM

B218 = catalog.get("B218")
SPINDLE = BallBearing(n_balls=15, ball_diameter=7.938e-3, pitch_diameter=52.5e-3, inner_conformity=0.52,
                      outer_conformity=0.53, contact_angle=math.radians(15), type="angular")


@pytest.mark.parametrize("kind", ["DB", "DF"])
def test_force_preload_is_carried_by_each_bearing_without_load(kind):
    s = sets.set_analysis(SPINDLE, np.zeros(5), arrangement_kind=kind, spacing=0.06, preload=500.0)
    assert s.converged
    assert_allclose(np.abs(s.bearing_loads[:, 2]), 500.0, rtol=1e-9)
    assert_allclose(s.bearing_loads.sum(axis=0), 0.0, atol=1e-7)
    # each bearing alone under its preload: the same ball loads
    single = combined.combined_analysis(SPINDLE, [0, 0, 500.0, 0, 0])
    assert_allclose(s.bearings[0]["ball_load_inner"], single.ball_load_inner, rtol=1e-9)


def test_db_pair_is_stiffer_in_tilt_than_df_at_the_same_preload():
    k = {kind: sets.set_analysis(SPINDLE, np.zeros(5), arrangement_kind=kind, spacing=0.03, preload=500.0).stiffness
         for kind in ("DB", "DF")}
    assert k["DB"][3, 3] > 1.5 * k["DF"][3, 3] and k["DB"][4, 4] > 1.5 * k["DF"][4, 4]
    assert_allclose(k["DB"][[0, 1, 2], [0, 1, 2]], k["DF"][[0, 1, 2], [0, 1, 2]], rtol=1e-9)  # same at the centre


@pytest.mark.parametrize(("bearing", "kind", "n"), [(SPINDLE, "DB", 2), (SPINDLE, "DF", 2), (B218, "DB", 2),
                                                   (SPINDLE, "DB", 4)])
def test_displacement_preload_equals_the_force_preload_it_produces(bearing, kind, n):
    """Round trip: the interference a force preload produces, fed back as an offset, gives the force back."""
    f = sets.set_analysis([bearing] * n, np.zeros(5), arrangement_kind=kind, spacing=0.05, preload=300.0)
    assert f.preload_displacement > 0
    d = sets.set_analysis([bearing] * n, np.zeros(5), arrangement_kind=kind, spacing=0.05,
                          preload_displacement=f.preload_displacement)
    share = 300.0 / (n // 2)
    assert_allclose(np.abs(d.bearing_loads[:, 2]), share, rtol=1e-12)  # rounding of the offsets only
    assert_allclose(d.displacement, 0.0, atol=1e-15) and not d.warnings


def _thrust_at_offset(bearing, axial):
    """Axial load of one bearing whose groove-curvature centres are offset axially by ``axial`` (all balls at
    one angle), from the exact Hertz constants: Q = K_n (rho - A)^1.5, F_a = Z Q sin(alpha)."""
    big_a = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * bearing.ball_diameter
    radial = big_a * math.cos(bearing.contact_angle)
    rho, alpha = math.hypot(axial, radial), math.atan2(axial, radial)
    k = contact_stiffness(alpha, alpha, bearing.ball_diameter, bearing.pitch_diameter, bearing.inner_conformity,
                          bearing.outer_conformity, bearing.reduced_modulus)
    kn = (k.inner ** (-2 / 3) + k.outer ** (-2 / 3)) ** -1.5
    return bearing.n_balls * kn * max(rho - big_a, 0.0) ** 1.5 * math.sin(alpha)


@pytest.mark.parametrize("bearing", [SPINDLE, B218])
def test_preload_offset_is_measured_from_first_contact(bearing):
    """A spacer offset e of a DB pair is measured from the position where the balls first touch (MESYS,
    MASTA): each bearing is pressed e / 2 beyond its first-contact offset A sin(alpha0). A few um preload
    the set, more preloads it more; each bearing's thrust matches the Hertz thrust at that offset."""
    big_a = (bearing.inner_conformity + bearing.outer_conformity - 1.0) * bearing.ball_diameter
    touch = big_a * math.sin(bearing.contact_angle)
    assert touch > 20e-6  # the clearance that a groove-centred offset of a few um would not take up
    thrusts = []
    for e in (1e-6, 2e-6, 5e-6):
        s = sets.set_analysis(bearing, np.zeros(5), arrangement_kind="DB", spacing=0.1, preload_displacement=e)
        assert s.converged and not s.warnings and s.preload_displacement == e
        fa = s.bearing_loads[:, 2]
        assert fa[0] > 0 and fa[1] == pytest.approx(-fa[0], rel=1e-12)
        assert_allclose(fa[0], _thrust_at_offset(bearing, touch + e / 2), rtol=1e-9)  # interpolant: ~1e-13
        assert np.all(s.bearings[0]["ball_load_inner"] > 0)
        thrusts.append(fa[0])
    assert thrusts[0] < thrusts[1] < thrusts[2]
    zero = sets.set_analysis(bearing, np.zeros(5), spacing=0.1, preload_displacement=0.0)
    assert_allclose(zero.bearing_loads, 0.0, atol=1e-9)  # zero preload: touching, unloaded


def test_a_bearing_without_load_is_warned_about():
    play = sets.set_analysis(SPINDLE, np.zeros(5), spacing=0.05, preload_displacement=-2e-6)
    assert play.converged and np.all(play.bearing_loads == 0.0)
    assert sum("carries no load at all" in m for m in play.warnings) == 2
    loads = [[0.0, 0.0, 50.0, 0.0, 0.0], [0.0, 0.0, 3000.0, 0.0, 0.0]]  # the second lifts bearing 1 off
    s = sets.set_analysis(SPINDLE, loads, spacing=0.05, preload=200.0)
    assert s.converged.all() and np.all(s.bearing_loads[0, :, 2] != 0.0) and s.bearing_loads[1, 1, 2] == 0.0
    idle = [m for m in s.warnings if "no load" in m]
    assert len(idle) == 1 and idle[0].startswith("bearing 1 carries no load at all in 1 case(s) (first: case 1)")


@pytest.mark.parametrize("w", [0.0, 12000 * RPM])
def test_set_equilibrium_and_stiffness_against_finite_differences(w):
    loads = np.array([400.0, -250.0, 300.0, 6.0, -4.0])
    s = sets.set_analysis(SPINDLE, loads, w, spacing=0.05, preload=400.0)
    assert s.converged and s.residual <= 1e-9
    assert_allclose(s.bearing_loads.sum(axis=0), loads, rtol=0, atol=1e-8 * 400)
    fd = np.zeros((5, 5))
    for k in range(5):
        h = np.zeros(5)
        h[k] = 1e-3 * (10.0 if k < 3 else 0.2)
        up = sets.set_analysis(SPINDLE, loads + h, w, spacing=0.05, preload=400.0, tol=1e-14).displacement
        down = sets.set_analysis(SPINDLE, loads - h, w, spacing=0.05, preload=400.0, tol=1e-14).displacement
        fd[:, k] = (up - down) / (2 * h[k])
    compliance = np.linalg.inv(s.stiffness)
    assert_allclose(fd, compliance, rtol=1e-5, atol=1e-6 * np.abs(compliance).max())


def test_single_bearing_equivalence():
    """A 'set' of one bearing at z = 0 without preload is the bearing itself."""
    loads = [[500.0, 100.0, 800.0, 2.0, 1.0]]
    s = sets.set_analysis([SPINDLE], loads, arrangement_kind=[1])
    r = combined.combined_analysis(SPINDLE, loads)
    assert_allclose(s.displacement, r.displacement, rtol=1e-9, atol=1e-15)
    assert_allclose(s.stiffness, r.stiffness, rtol=1e-9)


def test_arrangements_and_inputs():
    o, z = sets.arrangement("DF", 0.1, 4)
    assert o.tolist() == [-1, -1, 1, 1]
    assert_allclose(z, [-0.15, -0.05, 0.05, 0.15])
    with pytest.raises(InputError, match="arrangement must be one of"):
        sets.arrangement("XX", 0.1)
    with pytest.raises(InputError, match="tandem"):
        sets.set_analysis(SPINDLE, np.zeros(5), arrangement_kind="DT", spacing=0.05, preload=100.0)
    with pytest.raises(InputError, match="preload_displacement.*tandem"):
        sets.set_analysis(SPINDLE, np.zeros(5), arrangement_kind="DT", spacing=0.05, preload_displacement=5e-6)



# --------------------------------------------------------------------------- issue 20 item 10: spacing
def test_default_spacing_is_one_ring_width_and_reported():
    """Bearings side by side: centres one width apart (B218: B = 30 mm, catalog), flagged as the default."""
    s = sets.set_analysis(B218, np.zeros(5), arrangement_kind="DB", preload=2000.0)
    assert s.default_spacing is True
    assert_allclose(s.positions, [-0.015, 0.015], rtol=0, atol=1e-15)
    given = sets.set_analysis(B218, np.zeros(5), arrangement_kind="DB", spacing=0.03, preload=2000.0)
    assert given.default_spacing is False
    assert_allclose(given.stiffness, s.stiffness, rtol=1e-12)
    # unequal widths: (B_0 + B_1) / 2 between the centres
    narrow = B218.replace(width=0.020)
    _, z = sets.arrangement("DB", sets.default_spacing([B218, narrow]))
    assert_allclose(np.diff(z), [0.025], rtol=1e-12)


def test_bearing_without_width_needs_a_spacing():
    assert SPINDLE.width is None
    with pytest.raises(InputError, match=r"spacing: bearing 0 .* has no width"):
        sets.set_analysis(SPINDLE, np.zeros(5), arrangement_kind="DB", preload=100.0)
    with pytest.raises(InputError, match="one value or one per gap"):
        sets.arrangement("DB", [0.01, 0.02])


@pytest.mark.parametrize("spacing", [None, 0.03, 0.2])
def test_tilt_stiffness_of_db_and_df_from_one_bearing_and_the_effective_spread(spacing):
    """Hand calculation of the set's tilt stiffness from the single bearing under the preload.

    One bearing under its preload P alone has the tangent stiffness K (k_xx, k_x.theta_y, k_theta_y). A
    radial force through its stiffness centre, c = k_x.theta / k_xx from the bearing centre along its own
    axis, moves it without tilting it. Two such bearings, one mirrored (c -> -c), a distance s apart: the
    stiffness centres are L apart, L = s + 2|c| back-to-back (they lie outside the bearings) and
    |s - 2|c|| face-to-face; the shaft tilting by theta about the middle moves each by theta L / 2, so
    k_theta = 2 (k_xx (L/2)^2 + k_theta - k_x.theta^2 / k_xx). c is close to the pressure-centre distance
    (d_m / 2) tan(alpha) of the loaded balls. The Hertz constants at alpha0 make K exactly symmetric
    (k_x.theta = k_theta.x), which the completed square assumes.
    """
    p = 2000.0
    one = combined.combined_analysis(B218, [0.0, 0.0, p, 0.0, 0.0], stiffness_at="free")
    k = one.stiffness
    kxx, kxt, ktt = k[0, 0], k[0, 4], k[4, 4]
    c = abs(kxt / kxx)
    alpha = one.contact_angle_inner[0]
    assert c == pytest.approx(B218.pitch_diameter / 2 * math.tan(alpha), rel=0.01)
    s_used = B218.width if spacing is None else spacing
    spread = {"DB": s_used + 2 * c, "DF": abs(s_used - 2 * c)}
    got = {kind: sets.set_analysis(B218, np.zeros(5), arrangement_kind=kind, spacing=spacing, preload=p,
                                  stiffness_at="free").stiffness
           for kind in ("DB", "DF")}
    for kind, big_l in spread.items():
        hand = 2.0 * (kxx * (big_l / 2) ** 2 + ktt - kxt**2 / kxx)
        assert got[kind][4, 4] == pytest.approx(hand, rel=1e-9)
        assert got[kind][3, 3] == pytest.approx(hand, rel=1e-9)  # axisymmetric
    assert got["DB"][4, 4] > got["DF"][4, 4]
