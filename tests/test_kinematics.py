"""Tests of bearinglab.kinematics: the published CWRU multipliers, an independent derivation from the
contact velocities, invariants (hypothesis), the frequency shift and the spectral mask, bad input."""

import csv
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import catalog, kinematics
from bearinglab.errors import InputError

DATA = Path(__file__).parent / "data" / "cwru_6205_multipliers.csv"
CWRU = {
    r["name"]: r for r in csv.DictReader(line for line in DATA.open() if not line.startswith("#"))
}
SETTINGS = settings(max_examples=40, deadline=None)


def _cwru_orders():
    b = catalog.get("6205-2RS")
    return kinematics.characteristic_orders(
        b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle
    )


# ----------------------------------------------------------------------------------------- validation
@pytest.mark.parametrize("name", ["bpfi", "bpfo", "two_bsf"])
def test_cwru_6205_multipliers_to_the_printed_digits(name):
    row = CWRU[name]
    got = getattr(_cwru_orders(), name)
    # tolerance: half a unit of the last printed digit (the value must round to the print)
    assert abs(got - float(row["published"])) <= 0.5 * 10.0 ** -int(row["digits"]), (name, got)
    assert f"{got:.{row['digits']}f}" == row["published"]


def test_cwru_6205_ftf_as_close_as_the_published_numbers_allow():
    # The published FTF 0.39828 is not consistent with the published BPFO: for any geometry
    # FTF = BPFO / Z exactly (fixed outer ring), and BPFO = 3.5848 (+-5e-5) puts FTF in
    # [0.3983056, 0.3983167]; 0.39828 (+-5e-6) lies outside it (BPFI gives the same interval through
    # FTF = 1 - BPFI / Z). The published FTF corresponds to D = 7.9423 mm instead of 7.94 mm. So FTF
    # cannot be matched to its printed digits by any model that matches BPFO; the tightest tolerance
    # the published numbers allow is the largest distance from 0.39828 to that interval, 3.67e-5.
    orders = _cwru_orders()
    z = 9
    bpfo, ftf = float(CWRU["bpfo"]["published"]), float(CWRU["ftf"]["published"])
    lo, hi = (bpfo - 5e-5) / z, (bpfo + 5e-5) / z
    assert not (lo <= ftf + 5e-6 and ftf - 5e-6 <= hi)  # the evidence: the two prints disagree
    assert orders.ftf == pytest.approx(orders.bpfo / z, rel=1e-15)
    assert (
        abs(orders.ftf - ftf) <= hi - ftf
    )  # 3.67e-5; the library's value is 2.94e-5 from the print
    assert lo <= orders.ftf <= hi


def test_cwru_bsf_and_shaft_order():
    o = _cwru_orders()
    assert o.shaft == 1.0
    assert o.two_bsf == pytest.approx(2 * o.bsf, rel=1e-15)
    # BSF written out from the catalog numbers, D = 7.94 mm, d_m = 39.04 mm, alpha = 0 (Harris eq. 7.18)
    assert o.bsf == pytest.approx(39.04 / (2 * 7.94) * (1 - (7.94 / 39.04) ** 2), rel=1e-14)


def test_frequencies_at_cwru_speed_in_hz():
    # 1797 rpm, the CWRU 0 hp speed: BPFI = 5.4152 x 29.95 Hz = 162.19 Hz
    f = kinematics.characteristic_frequencies(1797 * 2 * math.pi / 60, 7.94e-3, 39.04e-3, 9, 0.0)
    assert f.bpfi / (2 * math.pi) == pytest.approx(5.4152 * 29.95, abs=0.5 * 0.0001 * 29.95)
    assert f.bpfo / (2 * math.pi) == pytest.approx(3.5848 * 29.95, abs=0.5 * 0.0001 * 29.95)


# ---------------------------------------------------------------- independent derivation (velocities)
def _from_contact_velocities(wi, wo, d, dm, alpha):
    """Pure rolling written from the surface speeds at the two contacts (no shared code path)."""
    r_i = (dm - d * math.cos(alpha)) / 2  # radius of the inner contact point about the bearing axis
    r_o = (dm + d * math.cos(alpha)) / 2
    v_i, v_o = wi * r_i, wo * r_o  # raceway surface speeds
    v_c = (v_i + v_o) / 2  # ball centre: mean of the two contact speeds (no slip)
    wc = v_c / (dm / 2)
    # ball spin relative to the cage: the inner raceway moves past the ball at (wi - wc) r_i, and the
    # ball's surface point at the contact is at D/2 from its centre
    spin = abs(wi - wc) * r_i / (d / 2)
    return wc, abs(wc - wo), abs(wi - wc), spin


@SETTINGS
@given(
    wi=st.floats(-2000, 2000),
    wo=st.floats(-2000, 2000),
    d=st.floats(1e-3, 0.05),
    ratio=st.floats(1.05, 20),
    alpha=st.floats(0, 1.5),
    z=st.integers(3, 40),
)
def test_agrees_with_contact_velocity_derivation(wi, wo, d, ratio, alpha, z):
    dm = d * ratio
    wc, rel_o, rel_i, spin = _from_contact_velocities(wi, wo, d, dm, alpha)
    f = kinematics.characteristic_frequencies(wi, d, dm, z, alpha, outer_speed=wo)
    scale = abs(wi) + abs(wo) + 1e-300
    assert kinematics.cage_speed(wi, d, dm, alpha, outer_speed=wo) == pytest.approx(
        wc, rel=1e-12, abs=1e-12 * scale
    )
    assert f.ftf == pytest.approx(abs(wc), rel=1e-12, abs=1e-12 * scale)
    assert f.bpfo == pytest.approx(z * rel_o, rel=1e-12, abs=1e-12 * z * scale)
    assert f.bpfi == pytest.approx(z * rel_i, rel=1e-12, abs=1e-12 * z * scale)
    assert f.bsf == pytest.approx(spin, rel=1e-12, abs=1e-12 * ratio * scale)


# ------------------------------------------------------------------------------------------ properties
@SETTINGS
@given(speed=st.floats(1e-3, 1e4), angle=st.floats(0.0, 0.8))
def test_ball_pass_frequencies_sum_to_ball_count(speed, angle):
    bpfo, bpfi = kinematics.ball_pass_frequencies(
        speed, 0.0127, 0.0635, 9, angle
    )  # STYLE.md section 7
    assert bpfo + bpfi == pytest.approx(9 * speed, rel=1e-12)


@SETTINGS
@given(
    wi=st.floats(-1e4, 1e4),
    wo=st.floats(-1e4, 1e4),
    common=st.floats(-1e4, 1e4),
    alpha=st.floats(0, 1.5),
)
def test_common_rotation_changes_only_the_cage_speed(wi, wo, common, alpha):
    # adding the same rotation to both rings (a rotating frame) leaves every relative frequency alone
    args = (0.01, 0.05, 8, alpha)
    f1 = kinematics.characteristic_frequencies(wi, *args, outer_speed=wo)
    f2 = kinematics.characteristic_frequencies(wi + common, *args, outer_speed=wo + common)
    scale = 1e-9 * (abs(wi) + abs(wo) + abs(common) + 1)
    for name in ("bpfo", "bpfi", "bsf", "two_bsf"):
        assert getattr(f2, name) == pytest.approx(getattr(f1, name), abs=8 * scale)
    c1 = kinematics.cage_speed(wi, 0.01, 0.05, alpha, outer_speed=wo)
    c2 = kinematics.cage_speed(wi + common, 0.01, 0.05, alpha, outer_speed=wo + common)
    assert c2 - c1 == pytest.approx(common, abs=scale)


@SETTINGS
@given(speed=st.floats(1.0, 1e4), a1=st.floats(0.0, 1.5), a2=st.floats(0.0, 1.5))
def test_trends_with_contact_angle(speed, a1, a2):
    lo, hi = sorted((a1, a2))
    if hi - lo < 1e-6:
        return
    f_lo = kinematics.characteristic_frequencies(speed, 0.01, 0.05, 9, lo)
    f_hi = kinematics.characteristic_frequencies(speed, 0.01, 0.05, 9, hi)
    # a larger angle lowers gamma: BPFI falls, BPFO, FTF and BSF rise
    assert f_hi.bpfi < f_lo.bpfi
    assert f_hi.bpfo > f_lo.bpfo and f_hi.ftf > f_lo.ftf and f_hi.bsf > f_lo.bsf


@SETTINGS
@given(scale=st.floats(1e-3, 1e3), speed=st.floats(-1e3, 1e3), alpha=st.floats(0, 1.5))
def test_size_scaling_and_linearity_in_speed(scale, speed, alpha):
    f = kinematics.characteristic_frequencies(speed, 0.01, 0.05, 9, alpha)
    g = kinematics.characteristic_frequencies(speed, 0.01 * scale, 0.05 * scale, 9, alpha)
    h = kinematics.characteristic_frequencies(3.0 * speed, 0.01, 0.05, 9, alpha)
    for a, b, c in zip(f, g, h):
        assert b == pytest.approx(a, rel=1e-12, abs=1e-300)
        assert c == pytest.approx(3.0 * a, rel=1e-12, abs=1e-300)


def test_limits():
    # a vanishing ball: the cage runs at half the shaft speed, BPFO = BPFI = Z/2
    f = kinematics.characteristic_orders(1e-12, 1.0, 10, 0.3)
    assert_allclose([f.ftf, f.bpfo, f.bpfi], [0.5, 5.0, 5.0], rtol=1e-11)
    # contact angle -> 90 deg: gamma -> 0 as well
    f = kinematics.characteristic_orders(0.01, 0.05, 10, math.pi / 2 - 1e-12)
    assert_allclose([f.ftf, f.bpfo, f.bpfi, f.bsf], [0.5, 5.0, 5.0, 2.5], rtol=1e-10)
    # outer ring only: the cage follows the outer ring at (1 + gamma)/2 of its speed
    g = 0.01 / 0.05
    assert kinematics.cage_speed(0.0, 0.01, 0.05, 0.0, outer_speed=2.0) == pytest.approx(
        1 + g, rel=1e-15
    )
    # equal ring speeds: no relative motion, every defect frequency vanishes
    f = kinematics.characteristic_frequencies(5.0, 0.01, 0.05, 9, 0.2, outer_speed=5.0)
    assert (f.bpfo, f.bpfi, f.bsf) == (0.0, 0.0, 0.0) and f.ftf == pytest.approx(5.0, rel=1e-15)


def test_scalar_and_array_agree_and_broadcast():
    speeds = np.array([10.0, 100.0, 1000.0])
    angles = np.array([[0.0], [0.2], [0.7]])
    f = kinematics.characteristic_frequencies(speeds, 0.01, 0.05, 9, angles)
    assert f.bpfi.shape == (3, 3) and f.shaft.shape == (3, 3)
    for i in range(3):
        for j in range(3):
            one = kinematics.characteristic_frequencies(speeds[j], 0.01, 0.05, 9, angles[i, 0])
            for name in kinematics.FAMILIES:
                assert getattr(f, name)[i, j] == getattr(one, name)
    scalar = kinematics.characteristic_frequencies(10.0, 0.01, 0.05, 9, 0.2)
    assert all(isinstance(x, float) for x in scalar)
    bp = kinematics.ball_pass_frequencies(speeds, 0.01, 0.05, np.array([7, 9, 11]), 0.1)
    assert_allclose(bp.bpfo + bp.bpfi, np.array([7, 9, 11]) * speeds, rtol=1e-14)


def test_orders_are_frequencies_at_unit_speed():
    o = kinematics.characteristic_orders(0.01, 0.05, 9, 0.3, outer_speed_ratio=-0.5)
    f = kinematics.characteristic_frequencies(250.0, 0.01, 0.05, 9, 0.3, outer_speed=-125.0)
    for a, b in zip(o, f):
        assert b / 250.0 == pytest.approx(a, rel=1e-14)


# ------------------------------------------------------------------------------------------- shift
def test_frequency_shift_of_the_stand_example():
    from bearinglab import static

    b = catalog.get("4-1006095")
    alpha = float(static.stand_analysis(b, 2 * 9.80665).contact_angle)
    s = kinematics.frequency_shift(
        2 * math.pi * 50, b.ball_diameter, b.pitch_diameter, b.n_balls, b.contact_angle, alpha
    )
    g0 = 2.0 * math.cos(math.radians(12)) / 8.7355
    g1 = 2.0 * math.cos(alpha) / 8.7355
    assert s.shift_percent.bpfi == pytest.approx(100 * ((1 + g1) / (1 + g0) - 1), rel=1e-10)
    assert s.shift_percent.bpfo == pytest.approx(100 * ((1 - g1) / (1 - g0) - 1), rel=1e-10)
    assert s.shift_percent.bsf == pytest.approx(100 * ((1 - g1**2) / (1 - g0**2) - 1), rel=1e-10)
    assert s.shift_percent.ftf == pytest.approx(s.shift_percent.bpfo, rel=1e-12)
    assert s.shift.bpfi == pytest.approx(s.operating.bpfi - s.nominal.bpfi, rel=1e-15)
    assert s.shift.bpfo == pytest.approx(-s.shift.bpfi, rel=1e-12)  # BPFO + BPFI = Z n is fixed
    assert s.shift.shaft == 0.0


@SETTINGS
@given(a0=st.floats(0.0, 1.4), da=st.just(0.0) | st.floats(1e-4, 0.15))
def test_shift_signs_and_zero_shift(a0, da):
    s = kinematics.frequency_shift(100.0, 0.01, 0.05, 9, a0, a0 + da)
    if da == 0.0:
        assert all(x == 0.0 for x in s.shift)
    else:
        assert s.shift.bpfi < 0 < s.shift.bpfo and s.shift.bsf > 0


def test_shift_percent_nan_where_nominal_is_zero():
    s = kinematics.frequency_shift(0.0, 0.01, 0.05, 9, 0.1, 0.2, outer_speed=10.0)
    assert math.isnan(s.shift_percent.shaft)
    assert math.isfinite(s.shift_percent.bpfi)


# -------------------------------------------------------------------------------------------- mask
MASK_ARGS = (100.0, 7.94e-3, 39.04e-3, 9, 0.0)


def test_mask_layout_and_values():
    n, s = 3, 2
    m = kinematics.spectral_mask(*MASK_ARGS, harmonics=n, sidebands=s, band=0.04)
    f = kinematics.characteristic_frequencies(*MASK_ARGS)
    # modulated families: BPFI (FTF and shaft), BSF and 2 BSF (FTF); every carrier has 2S per modulation
    expected = len(kinematics.FAMILIES) * n + n * 2 * s * (2 + 1 + 1)
    assert (
        len(m.name)
        == len(m.harmonic)
        == len(m.sideband)
        == len(m.modulation)
        == m.frequency.shape[-1]
        == expected
    )
    carriers = m.modulation == ""
    assert np.all(m.sideband[carriers] == 0)
    for fam in kinematics.FAMILIES:
        sel = carriers & (m.name == fam)
        assert_allclose(m.frequency[sel], np.arange(1, n + 1) * getattr(f, fam), rtol=1e-15)
    sel = (m.name == "bpfi") & (m.modulation == "shaft") & (m.harmonic == 2)
    assert_allclose(m.frequency[sel], 2 * f.bpfi + np.array([-2, -1, 1, 2]) * f.shaft, rtol=1e-15)
    sel = (m.name == "bsf") & (m.modulation == "ftf") & (m.harmonic == 3)
    assert_allclose(m.frequency[sel], 3 * f.bsf + np.array([-2, -1, 1, 2]) * f.ftf, rtol=1e-15)
    assert not np.any((m.name == "bpfo") & (m.modulation != ""))  # no sidebands around BPFO
    assert_allclose(m.high - m.low, 0.04 * m.frequency, rtol=1e-12)
    assert_allclose((m.high + m.low) / 2, m.frequency, rtol=1e-15)


def test_mask_without_sidebands_and_subset():
    m = kinematics.spectral_mask(*MASK_ARGS, harmonics=4, sidebands=0, families=("bpfo", "bpfi"))
    assert list(m.name) == ["bpfo"] * 4 + ["bpfi"] * 4
    assert list(m.harmonic) == [1, 2, 3, 4] * 2


def test_mask_folds_negative_sidebands():
    # at a large sideband order the lower shaft sideband of BPFI would be negative: folded to |f|
    m = kinematics.spectral_mask(*MASK_ARGS, harmonics=1, sidebands=7, families=("bpfi",))
    f = kinematics.characteristic_frequencies(*MASK_ARGS)
    sel = (m.modulation == "shaft") & (m.sideband == -7)
    assert_allclose(m.frequency[sel], abs(f.bpfi - 7 * f.shaft), rtol=1e-15)
    assert np.all(m.frequency >= 0) and np.all(m.low >= 0)


def test_mask_vectorized_over_speeds():
    speeds = np.linspace(10.0, 1000.0, 50)
    m = kinematics.spectral_mask(speeds, 7.94e-3, 39.04e-3, 9, 0.0, harmonics=2)
    assert m.frequency.shape == (50, len(m.name))
    one = kinematics.spectral_mask(speeds[17], 7.94e-3, 39.04e-3, 9, 0.0, harmonics=2)
    assert_allclose(m.frequency[17], one.frequency, rtol=1e-15)
    assert_allclose(
        m.frequency / speeds[:, None],
        np.broadcast_to(m.frequency[0] / speeds[0], m.frequency.shape),
        rtol=1e-12,
    )


@pytest.mark.parametrize(
    "kw, match",
    [
        ({"harmonics": 0}, r"harmonics must be an integer >= 1"),
        ({"harmonics": 2.5}, r"harmonics must be an integer >= 1"),
        ({"sidebands": -1}, r"sidebands must be an integer >= 0"),
        ({"band": 0.0}, r"band must be a number in \(0, 2\)"),
        ({"band": 2.0}, r"band must be a number in \(0, 2\)"),
        ({"band": [0.01, 0.02]}, r"band must be a number"),
        ({"families": ("bpfo", "cage")}, r"families must be a non-empty subset of .*'ftf'"),
        ({"families": ()}, r"families must be a non-empty subset"),
    ],
)
def test_mask_bad_options(kw, match):
    with pytest.raises(InputError, match=match):
        kinematics.spectral_mask(*MASK_ARGS, **kw)


# ----------------------------------------------------------------------------------------- bad input
@pytest.mark.parametrize(
    "args, kw, match",
    [
        (
            (100.0, 0.01, 0.05, 9, math.radians(90)),
            {},
            r"contact_angle must be in \[0, 90\) \[deg\], got 90",
        ),
        (
            (100.0, 0.01, 0.05, 9, -0.1),
            {},
            r"contact_angle must be in \[0, 90\) \[deg\], got -5.72",
        ),
        ((100.0, 0.01, 0.05, 0, 0.1), {}, r"n_balls must be an integer >= 1 \[-\], got 0.0"),
        ((100.0, 0.01, 0.05, 8.5, 0.1), {}, r"n_balls must be an integer >= 1"),
        ((100.0, 0.0, 0.05, 9, 0.1), {}, r"ball_diameter must be > 0 \[m\], got 0.0"),
        (
            (100.0, 0.01, 0.01, 9, 0.1),
            {},
            r"pitch_diameter must be > ball_diameter \[m\], got 0.01",
        ),
        ((float("nan"), 0.01, 0.05, 9, 0.1), {}, r"shaft_speed must be finite \[rad/s\], got nan"),
        ((100.0, 0.01, 0.05, 9, 0.1), {"outer_speed": float("inf")}, r"outer_speed must be finite"),
    ],
)
def test_bad_input_names_parameter_and_value(args, kw, match):
    with pytest.raises(InputError, match=match):
        kinematics.characteristic_frequencies(*args, **kw)


def test_bad_input_in_every_public_function():
    with pytest.raises(InputError, match="contact_angle"):
        kinematics.cage_speed(1.0, 0.01, 0.05, 2.0)
    with pytest.raises(InputError, match="n_balls"):
        kinematics.ball_pass_frequencies(1.0, 0.01, 0.05, -3, 0.1)
    with pytest.raises(InputError, match="pitch_diameter"):
        kinematics.ball_spin_frequency(1.0, 0.01, 0.005, 0.1)
    with pytest.raises(InputError, match="outer_speed_ratio must be finite"):
        kinematics.characteristic_orders(0.01, 0.05, 9, 0.1, outer_speed_ratio=float("nan"))
    with pytest.raises(InputError, match=r"contact_angle must be in \[0, 90\) \[deg\], got 91.67"):
        kinematics.frequency_shift(1.0, 0.01, 0.05, 9, 0.1, 1.6)
    with pytest.raises(InputError, match=r"free_angle must be in \[0, 90\) \[deg\], got 91.67"):
        kinematics.frequency_shift(1.0, 0.01, 0.05, 9, 1.6, 0.1)
    with pytest.raises(InputError, match=r"ball_diameter must be a number"):
        kinematics.characteristic_frequencies(1.0, "ten", 0.05, 9, 0.1)
