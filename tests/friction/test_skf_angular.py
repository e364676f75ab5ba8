"""SKF friction model of angular-contact ball bearings: the published constants, the model written out
by hand in the catalogue's units, the refusal of what the catalogue does not cover, and the parts of the
catalogue's worked example that a ball-bearing model shares.

Source: SKF General Catalogue 6000/I RU (2006), section "Friction": table 3, p. 92 (geometry constants),
table 4, p. 96 (seal constants), table 5, p. 98 (K_Z), worked example pp. 104-105; section "Single row
angular contact ball bearings", p. 410 (the single-row range: 72 B and 73 B, 40 deg).
"""

import dataclasses
import json
import math

import numpy as np
import pytest

from bearinglab import catalog, friction
from bearinglab.cli import main
from bearinglab.errors import InputError

RPM = 2 * math.pi / 60

# Table 3, p. 92, as printed: (R1, R2, R3, S1, S2, S3) by type.
PRINTED = {
    "single row": (5.03e-7, 1.97, 1.90e-12, 1.30e-2, 0.68, 1.91e-12),
    "double row": (6.34e-7, 1.41, 7.83e-13, 7.56e-3, 1.21, 7.83e-13),
    "four-point": (4.78e-7, 2.42, 1.40e-12, 1.20e-2, 0.9, 1.40e-12),
}


@pytest.mark.parametrize("kind", list(PRINTED))
def test_constants_are_the_catalogues(kind):
    c = friction.ANGULAR_CONTACT_CONSTANTS[kind]
    assert (c.r1, c.r2, c.r3, c.s1, c.s2, c.s3) == PRINTED[kind]


def test_angular_seal_constants_are_the_catalogues():
    # table 4, p. 96: RS1 seals of angular contact ball bearings, 30 < D <= 120 mm: beta 2, K_S1 0.014, K_S2 10
    assert friction.seal_constants("RS1", 80e-3, bearing_type="angular") == friction.SealConstants(0.014, 2.0, 10.0)
    for outside in (30e-3, 121e-3):
        with pytest.raises(InputError, match="outside the tabulated rows"):
            friction.seal_constants("RS1", outside, bearing_type="angular")
    with pytest.raises(InputError, match="seal must be one of"):
        friction.seal_constants("RSH", 80e-3, bearing_type="angular")


def _by_hand(fr, fa, rpm, nu, d, big, printed, *, krs, kz):
    """Table 2a's angular-contact forms and the reduction factors, in N, mm, rpm, mm^2/s -> N mm."""
    r1, r2, r3, s1, s2, s3 = printed
    dm = (d + big) / 2
    grr = r1 * dm**1.97 * (fr + r3 * dm**4 * rpm**2 + r2 * fa) ** 0.54
    gsl = s1 * dm**0.26 * ((fr + s3 * dm**4 * rpm**2) ** (4 / 3) + s2 * fa ** (4 / 3))
    ish = 1 / (1 + 1.84e-9 * (rpm * dm) ** 1.28 * nu**0.64)
    rs = math.exp(-krs * nu * rpm * (d + big) * math.sqrt(kz / (2 * (big - d))))
    phi_bl = math.exp(-2.6e-8 * (rpm * nu) ** 1.4 * dm)
    mu = phi_bl * 0.15 + (1 - phi_bl) * 0.05
    return ish * rs * grr * (nu * rpm) ** 0.6 + gsl * mu


@pytest.mark.parametrize("fr, fa, rpm, nu", [(1000.0, 2000.0, 3000.0, 30.0), (0.0, 500.0, 12000.0, 10.0),
                                             (4000.0, 0.0, 500.0, 100.0)])
def test_7208_be_without_constants_is_the_catalogue_model(fr, fa, rpm, nu):
    # 7208 BE: d 40, D 80 mm, 40 deg (SKF 72 B series): SKF's single-row constants, K_Z 4.4, grease K_rs 6e-8
    b = catalog.get("7208 BE")
    got = friction.skf_for_bearing(b, fr, fa, rpm * RPM, nu * 1e-6)
    want = _by_hand(fr, fa, rpm, nu, 40.0, 80.0, PRINTED["single row"], krs=6e-8, kz=4.4)
    assert got.total_moment * 1e3 == pytest.approx(want, rel=1e-12)


def test_four_point_and_double_row_take_their_rows_and_kz():
    for kind, name in (("four-point", "four-point"), ("double row", "double-row-angular")):
        got = friction.skf(2000.0, 3000.0, 4000 * RPM, 20e-6, 50e-3, 110e-3, bearing_type=name,
                           lubrication="oil-jet")
        want = _by_hand(2000.0, 3000.0, 4000.0, 20.0, 50.0, 110.0, PRINTED[kind], krs=3e-8, kz=3.1)
        assert got.total_moment * 1e3 == pytest.approx(want, rel=1e-12)


@pytest.mark.parametrize("degrees", [15.0, 25.0, 30.0, 38.9, 41.1])
def test_single_row_outside_the_published_range_is_refused(degrees):
    with pytest.raises(InputError, match=f"contact_angle {degrees:g} deg is not covered"):
        friction.angular_contact_constants(math.radians(degrees))
    with pytest.raises(InputError, match="is not covered"):
        friction.skf(100.0, 100.0, 1000 * RPM, 20e-6, 40e-3, 68e-3, bearing_type="angular",
                     contact_angle=math.radians(degrees))


def test_single_row_needs_its_angle_and_given_constants_override():
    with pytest.raises(InputError, match="contact_angle is needed"):
        friction.skf(100.0, 100.0, 1000 * RPM, 20e-6, 40e-3, 68e-3, bearing_type="angular")
    spindle = catalog.get("7008 C")  # 15 deg: refused without constants, computed with them
    with pytest.raises(InputError, match="15 deg is not covered"):
        friction.skf_for_bearing(spindle, 100.0, 100.0, 1000 * RPM, 20e-6)
    c = friction.SKFConstants(5e-7, 2.0, 1e-2, 0.7, 2e-12, 2e-12)
    got = friction.skf_for_bearing(spindle, 100.0, 100.0, 1000 * RPM, 20e-6, constants=c)
    want = _by_hand(100.0, 100.0, 1000.0, 20.0, 40.0, 68.0, (c.r1, c.r2, c.r3, c.s1, c.s2, c.s3), krs=6e-8, kz=4.4)
    assert got.total_moment * 1e3 == pytest.approx(want, rel=1e-12)


def test_sealed_angular_contact_bearing_takes_the_angular_seal_row():
    b = catalog.get("7208 BE")
    open_ = friction.skf_for_bearing(b, 500.0, 500.0, 3000 * RPM, 30e-6)
    sealed = dataclasses.replace(b, seal="RS1", seals=2, seal_diameter=52e-3)
    got = friction.skf_for_bearing(sealed, 500.0, 500.0, 3000 * RPM, 30e-6)
    assert got.seal_moment * 1e3 == pytest.approx(0.014 * 52.0**2 + 10.0, rel=1e-12)
    assert got.total_moment - got.seal_moment == pytest.approx(open_.total_moment, rel=1e-12)


def test_the_catalogues_worked_example_inlet_shear_factor():
    # pp. 104-105: a 22208 E at 3500 rpm, d_m = 60 mm, nu = 68 mm^2/s; printed Phi_ish ~ 0.85 (two decimals).
    # The example is a spherical roller bearing: its G_rr, G_sl, K_Z = 5.5 and roller drag are outside a
    # ball-bearing model, so only Phi_ish (the same formula for every type) is reproduced.
    got = friction.inlet_shear_heating_factor(68e-6, 3500 * RPM, 60e-3)
    assert got == pytest.approx(0.85, abs=0.005)
    # Phi_ish of skf() is the same factor: its rolling moment scales with it
    ratio = friction.skf(1000.0, 0.0, 3500 * RPM, 68e-6, 40e-3, 80e-3, series="62", lubrication="oil-bath",
                         oil_level=0.0, drag_loss_factor=0.0)
    phi_rs = friction.replenishment_factor(68e-6, 3500 * RPM, 40e-3, 80e-3, lubrication="oil-bath")
    grr = 3.9e-7 * 60.0**1.96 * 1000.0**0.54  # 62 series, table 3a, p. 93
    assert ratio.rolling_moment * 1e3 == pytest.approx(got * phi_rs * grr * (68 * 3500) ** 0.6, rel=1e-12)


def test_end_to_end_friction_torque_of_a_7208_be(capsys):
    code = main(["friction", "torque", "--model", "skf", "-b", "7208 BE", "-R", "1000 N", "-A", "2000 N",
                 "-n", "3000 rpm", "--viscosity", "30 cSt", "--json"])
    out, err = capsys.readouterr()
    assert code == 0, err
    doc = json.loads(out)
    want = _by_hand(1000.0, 2000.0, 3000.0, 30.0, 40.0, 80.0, PRINTED["single row"], krs=6e-8, kz=4.4)
    assert doc["total_moment_Nmm"] == pytest.approx(want, rel=1e-5)  # JSON keeps 6 significant digits
    assert doc["type"] == "angular"


def test_end_to_end_refuses_a_spindle_bearing_in_one_line(capsys):
    code = main(["friction", "torque", "--model", "skf", "-b", "7008 C", "-R", "100 N", "-n", "3000 rpm",
                 "--viscosity", "30 cSt"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "15 deg is not covered" in err
    code = main(["friction", "torque", "--model", "skf", "-b", "7208 BE", "-R", "100 N", "-n", "3000 rpm",
                 "--viscosity", "30 cSt", "--series", "62"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and "--series names SKF's deep-groove series" in err


def test_vectorised_over_cases():
    b = catalog.get("7208 BE")
    fr = np.array([100.0, 1000.0, 5000.0])
    got = friction.skf_for_bearing(b, fr, 1000.0, 3000 * RPM, 30e-6)
    each = [friction.skf_for_bearing(b, x, 1000.0, 3000 * RPM, 30e-6).total_moment for x in fr]
    np.testing.assert_allclose(got.total_moment, each, rtol=1e-14)
    assert np.all(np.diff(got.total_moment) > 0)
