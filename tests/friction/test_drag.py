"""SKF's drag loss factor V_M of an oil bath (issue 30): the digitised diagram, its checks against the printed
values, and both friction models reading it."""

import csv
from importlib import resources

import numpy as np
import pytest

from bearinglab import friction
from bearinglab.errors import InputError
from bearinglab.friction.drag import MAX_LEVEL_RATIO, drag_loss_factor, drag_loss_table

N = 3000 * 2 * np.pi / 60


def test_every_row_of_the_data_file_has_its_source():
    ref = resources.files("bearinglab") / "data" / "skf_drag_loss_factor.csv"
    with ref.open(encoding="utf-8") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    assert {r["bearing"] for r in rows} == {"ball", "roller"}
    assert all(r["source"].startswith("SKF GC diagram V_M") for r in rows)


@pytest.mark.parametrize("kind", ["ball", "roller"])
def test_the_curves_start_at_the_origin_rise_and_end_at_the_diagram(kind):
    h, v, sources = drag_loss_table(kind)
    assert h[0] == 0.0 and v[0] == 0.0 and len(sources) == len(h)
    assert np.all(np.diff(h) > 0) and np.all(np.diff(v) >= 0)
    assert h[-1] == pytest.approx(MAX_LEVEL_RATIO, abs=0.01)


def test_skfs_worked_example_reads_its_printed_value():
    # GC 6000/I RU (2006), p. 105: 22208 E, H = 2.5 mm, d_m = 60 mm, H/d_m = 0.041: "V_M is about 0.3e-4"
    # (roller bearings); one printed digit, so within half a unit of it
    assert 0.25e-4 <= drag_loss_factor(0.041 * 60e-3, 60e-3, "roller") <= 0.35e-4


def test_the_plateaus_read_by_eye_on_the_diagrams_grid():
    # above H/d_m ~ 1.2 both curves are flat: the ball curve above the 0.0012 grid line, the roller curve above
    # the 0.0014 line, each below half way to the next line (the labelled lines are 0.0002 apart)
    assert 0.0012 <= drag_loss_factor(1.3, 1.0, "ball") <= 0.0013
    assert 0.0014 <= drag_loss_factor(1.3, 1.0, "roller") <= 0.0015
    # and the roller curve lies above the ball curve over the whole diagram
    hs = np.linspace(0.02, 1.4, 50)
    assert np.all(drag_loss_factor(hs, 1.0, "roller") > drag_loss_factor(hs, 1.0, "ball"))


def test_beyond_the_diagram_and_bad_inputs_are_refused():
    with pytest.raises(InputError, match="^oil_level must be <= 1.4 d_m"):
        drag_loss_factor(0.1, 0.05)
    with pytest.raises(InputError, match="^oil_level must be >= 0"):
        drag_loss_factor(-1e-3, 0.05)
    with pytest.raises(InputError, match="^rolling_element must be one of"):
        drag_loss_factor(1e-3, 0.05, "needle")


def test_both_models_read_the_same_function_and_a_given_v_m_overrides_it():
    h = 5e-3
    m = friction.skf(1000.0, 0.0, N, 20e-6, 25e-3, 52e-3, series="62", lubrication="oil-bath", oil_level=h)
    assert m.drag_loss_factor == drag_loss_factor(h, 38.5e-3, "ball")
    assert m.drag_moment == friction.drag_moment(N, 20e-6, 25e-3, 52e-3, h, m.drag_loss_factor)
    given = friction.skf(1000.0, 0.0, N, 20e-6, 25e-3, 52e-3, series="62", lubrication="oil-bath", oil_level=h,
                         drag_loss_factor=2e-4)
    assert given.drag_loss_factor == 2e-4 and given.drag_moment != m.drag_moment
    r = friction.skf_roller(3000.0, 0.0, N, 20e-6, 40e-3, 80e-3, series="2", lubrication="oil-bath", width=18e-3,
                            oil_level=h)
    assert r.drag_loss_factor == drag_loss_factor(h, 60e-3, "roller")
    assert r.drag_moment == friction.roller_drag_moment(N, 40e-3, 80e-3, 18e-3, r.drag_loss_factor)
    assert friction.skf(1000.0, 0.0, N, 20e-6, 25e-3, 52e-3, series="62").drag_loss_factor is None


def test_the_worked_example_with_the_diagrams_v_m():
    # 22208 E in an oil bath, H = 2.5 mm: SKF prints M_drag = 14.5 N mm with its V_M = 0.3e-4 read by eye;
    # the digitised V_M (3.09e-5 at H/d_m = 2.5/60) gives 3 % more
    m = friction.skf_roller(2990.0, 100.0, 3500 * 2 * np.pi / 60, 68e-6, 40e-3, 80e-3, bearing_type="spherical",
                            series="222 E", lubrication="oil-bath", width=23e-3, oil_level=2.5e-3)
    assert m.drag_moment * 1e3 == pytest.approx(14.5, rel=0.05)
