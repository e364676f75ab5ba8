"""Published worked examples of roller bearings (issue 32): printed digits, with the tolerance they support.

- SKF General Catalogue 6000/I RU (2006), pp. 104-105: the frictional moment of a 22208 E in an oil bath.
- SKF General Catalogue 6000/I RU (2006), p. 80, example 5/2: the basic rating lives of a spherical roller bearing
  24026 (C = 540 kN) over a duty cycle (ISO 281 L10 with the roller exponent 10/3).
- NSK Rolling Bearings, CAT. No. E1102e, section 5.7, example 5 (pp. A36-A37): tapered roller bearings HR30305DJ and
  HR30206J back to back, F_r = 5500 N split 1569 / 3931 N, F_ae = 2000 N into HR30305DJ, 600 min^-1, induced axial
  loads 0.6 F_r / Y: printed F_a, P and the lives L_h.
"""

import math

import numpy as np
import pytest

from bearinglab import friction, ratings

RPM = 2 * math.pi / 60


class TestSKF22208E:
    """The 22208 E example: Fr = 2 990 N, Fa = 100 N, 3 500 r/min, 68 mm^2/s, oil bath H = 2.5 mm (V_M ~ 0.3e-4
    read from the diagram by SKF), d 40, D 80, B 23 mm; constants of series 213 E, 222 E (table 3e)."""

    def result(self):
        return friction.skf_roller(2990.0, 100.0, 3500 * RPM, 68e-6, 40e-3, 80e-3, bearing_type="spherical",
                                   series="222 E", lubrication="oil-bath", width=23e-3, drag_loss_factor=0.3e-4)

    def test_the_printed_variables(self):
        c = friction.roller_series_constants("spherical", "222 E")
        dm = 60.0
        g_rr_e = c.r1 * dm**1.85 * (2990 + c.r2 * 100) ** 0.54
        g_rr_l = c.r3 * dm**2.3 * (2990 + c.r4 * 100) ** 0.31
        g_sl_e = c.s1 * dm**0.25 * (2990**4 + c.s2 * 100**4) ** (1 / 3)
        g_sl_l = c.s3 * dm**0.94 * (2990**3 + c.s4 * 100**3) ** (1 / 3)
        assert round(g_rr_e, 2) == 0.26  # printed 0.26
        assert round(g_rr_l, 3) == 0.436  # printed 0.436
        assert round(g_sl_e) == 434  # printed 434
        assert g_sl_l == pytest.approx(1236.6, rel=1e-4)  # printed 1 236.6 (0.1 off: SKF's rounded powers)
        assert round(float(friction.inlet_shear_heating_factor(68e-6, 3500 * RPM, 60e-3)), 2) == 0.85

    def test_the_printed_moments(self):
        m = self.result()
        assert round(m.sliding_moment * 1e3, 1) == 21.7  # printed 21.7 N mm (mu_sl = 0.05, full film)
        assert round(m.drag_moment * 1e3, 1) == 14.5  # printed 14.5 N mm
        # printed M_rr = 437 N mm is 0.26 (G_rr rounded) x (68 x 3500)^0.6; unrounded G_rr = 0.2586 gives 435.0
        assert round(0.26 * (68 * 3500) ** 0.6) == 437
        rolling = m.rolling_moment / (float(friction.inlet_shear_heating_factor(68e-6, 3500 * RPM, 60e-3)) *
                                      math.exp(-3e-8 * 68 * 3500 * 120 * math.sqrt(5.5 / 80)))
        assert rolling * 1e3 == pytest.approx(437, rel=0.005)  # 0.5 %: the rounding of G_rr to 0.26
        # printed M = 0.85 x 0.8 x 437 + 21.7 + 14.5 = 334 N mm; that arithmetic gives 333.4 (the catalogue's own
        # rounding), and the unrounded chain 331.2: within 1 % of the printed total
        assert 0.85 * 0.8 * 437 + 21.7 + 14.5 == pytest.approx(333.36)
        assert m.total_moment * 1e3 == pytest.approx(334, rel=0.01)


def test_skf_24026_duty_cycle_lives():
    # C = 540 kN; steps (P kN, n r/min) -> printed L10h: (200, 50) 9 136; (125, 300) 7 295; (75, 400) 30 030;
    # (50, 200) 232 040. The printed digits are whole hours of a 4-5 digit number: 1e-4 relative.
    for p, n, printed in ((200, 50, 9136), (125, 300, 7295), (75, 400, 30030), (50, 200, 232040)):
        hours = ratings.roller_rating_life(540e3, p * 1e3) / (60 * n)
        assert hours == pytest.approx(printed, rel=2e-4), (p, n)


class TestNSKExample5:
    """HR30305DJ (bearing 1: C_r = 38 000 N, Y = 0.73, e = 0.83) and HR30206J (bearing 2: C_r = 43 000 N,
    Y = 1.60, e = 0.38), back to back; F_r1 = 1 569 N, F_r2 = 3 931 N, F_ae = 2 000 N into bearing 1."""

    def test_axial_and_equivalent_loads(self):
        s2 = ratings.induced_axial_load(3931.0, 1.60, factor=ratings.INDUCED_AXIAL_FACTORS["NSK"])
        assert round(2000 + float(s2)) == 3474  # printed Fae + 0.6/Y2 Fr2 = 3 474 N
        assert round(float(ratings.induced_axial_load(1569.0, 0.73, factor=0.6))) == 1290  # printed 1 290 N
        a = ratings.paired_axial_loads(3931.0, 1569.0, 1.60, 0.73, 2000.0, factor=0.6)
        assert round(float(a.axial_load_b)) == 3474
        p1 = ratings.roller_equivalent_load(1569.0, float(a.axial_load_b), ratio_limit=0.83, axial_factor=0.73)
        assert round(float(p1)) == 3164  # printed P1 = 3 164 N
        # bearing 2: NSK writes F_a2 = 0; this method gives it its own induced load, F_a2/F_r2 = 0.6/1.6 < e:
        # P2 = F_r2 either way (printed 3 931 N)
        p2 = ratings.roller_equivalent_load(3931.0, float(a.axial_load_a), ratio_limit=0.38, axial_factor=1.60)
        assert float(p2) == 3931.0

    def test_lives(self):
        # printed L_h = 500 f_h^(10/3) with f_h = f_n C/P rounded to 5.04 and 4.59 (f_n = 0.42): 109 750 h and
        # 80 400 h. The rounding of f_h to three digits moves a life by up to 0.35 %, NSK's 33.3 (for 100/3)
        # by 0.1 %: 0.6 %.
        for c, p, printed in ((38000.0, 3164.0, 109750), (43000.0, 3931.0, 80400)):
            hours = ratings.roller_rating_life(c, p) / (60 * 600)
            assert hours == pytest.approx(printed, rel=0.006)


def test_the_default_induced_axial_load_is_skfs_half():
    # SKF General Catalogue 6000/I RU (2006), p. 208: F_a = 0.5 F_r / Y
    assert ratings.INDUCED_AXIAL_FACTORS["SKF"] == 0.5
    assert float(ratings.induced_axial_load(1000.0, 1.6)) == pytest.approx(312.5)
    a = ratings.paired_axial_loads(np.array([1000.0, 5000.0]), 2000.0, 1.6, 1.6, 0.0)
    assert a.axial_load_b == pytest.approx([625.0, 1562.5]) and a.axial_load_a == pytest.approx([625.0, 1562.5])
