"""The oil-bath drag moment of the SKF model (bearinglab.friction.skf.drag_moment), by hand in the
catalogue's units, and through skf() and the command line."""

import json
import math

import pytest

from bearinglab import friction
from bearinglab.cli import main
from bearinglab.errors import InputError

RPM = 2 * math.pi / 60


def _by_hand(n, nu, d, big, h, vm, kz=3.1):
    """SKF catalogue 2018, drag losses in an oil bath, in N, mm, rpm, mm^2/s (N mm)."""
    dm = (d + big) / 2
    k_ball = kz * (d + big) / (big - d) * 1e-12
    t = 2 * math.acos((0.6 * dm - h) / (0.6 * dm))
    f_t = math.sin(t / 2)
    f_a = 0.05 * kz * (big + d) / (big - d)
    r_s = 0.36 * dm**2 * (t - math.sin(t)) * f_a
    return 0.4 * vm * k_ball * dm**5 * n**2 + 1.093e-7 * n**2 * dm**3 * (n * dm**2 * f_t / nu) ** -1.379 * r_s


@pytest.mark.parametrize("n, nu, h, vm", [(3000, 20.0, 5.0, 2e-4), (800, 100.0, 12.0, 5e-4), (6000, 8.0, 1.0, 1e-4)])
def test_drag_moment_by_hand(n, nu, h, vm):
    got = friction.drag_moment(n * RPM, nu * 1e-6, 25e-3, 52e-3, h * 1e-3, vm)
    assert got * 1e3 == pytest.approx(_by_hand(n, nu, 25.0, 52.0, h, vm), rel=1e-12)
    angular = friction.drag_moment(n * RPM, nu * 1e-6, 25e-3, 52e-3, h * 1e-3, vm, bearing_type="angular")
    assert angular * 1e3 == pytest.approx(_by_hand(n, nu, 25.0, 52.0, h, vm, kz=4.4), rel=1e-12)


def test_no_oil_no_speed_no_drag_and_level_above_centre_refused():
    assert friction.drag_moment(3000 * RPM, 20e-6, 25e-3, 52e-3, 0.0, 0.0) == 0.0
    assert friction.drag_moment(0.0, 20e-6, 25e-3, 52e-3, 5e-3, 2e-4) == 0.0
    with pytest.raises(InputError, match="oil_level must be <= d_m/2"):
        friction.drag_moment(3000 * RPM, 20e-6, 25e-3, 52e-3, 20e-3, 2e-4)


def test_skf_adds_the_drag_in_an_oil_bath_only():
    kw = {"series": "62"}
    jet = friction.skf(1000.0, 0.0, 3000 * RPM, 20e-6, 25e-3, 52e-3, lubrication="oil-jet", **kw)
    bath = friction.skf(1000.0, 0.0, 3000 * RPM, 20e-6, 25e-3, 52e-3, lubrication="oil-bath", oil_level=5e-3,
                        drag_loss_factor=2e-4, **kw)
    assert jet.drag_moment == 0.0
    assert bath.drag_moment * 1e3 == pytest.approx(_by_hand(3000, 20.0, 25.0, 52.0, 5.0, 2e-4), rel=1e-12)
    assert bath.total_moment == pytest.approx(jet.total_moment + bath.drag_moment, rel=1e-12)  # same K_rs
    with pytest.raises(InputError, match="oil bath needs the oil level"):
        friction.skf(1000.0, 0.0, 3000 * RPM, 20e-6, 25e-3, 52e-3, lubrication="oil-bath", **kw)
    with pytest.raises(InputError, match="belong to lubrication='oil-bath'"):
        friction.skf(1000.0, 0.0, 3000 * RPM, 20e-6, 25e-3, 52e-3, oil_level=5e-3, drag_loss_factor=1e-4, **kw)


BASE = ["friction", "torque", "-m", "skf", "-b", "6205-2RS", "-R", "1 kN", "-n", "3000 rpm"]


def test_cli_oil_bath_with_the_oil_by_grade(capsys):
    assert main([*BASE, "--oil", "VG68", "--temperature", "60 degC", "--lubrication", "oil-bath", "--oil-level",
                 "5 mm", "--drag-loss-factor", "0.0002", "--json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    nu = doc["viscosity_cSt"]
    assert doc["drag_moment_Nmm"] == pytest.approx(_by_hand(3000, nu, 25.0, 52.0, 5.0, 2e-4), rel=1e-9)


@pytest.mark.parametrize("extra, message", [
    (["--viscosity", "20 cSt", "--lubrication", "oil-bath", "--oil-level", "30 mm", "--drag-loss-factor", "1e-4"],
     "oil-level must be <= d_m/2"),
    (["--viscosity", "20 cSt", "--lubrication", "oil-bath"], "oil-level: --lubrication oil-bath needs"),
    (["--viscosity", "20 cSt", "--oil-level", "5 mm"], "go with --lubrication oil-bath"),
    (["--viscosity", "20 cSt", "--lubrication", "oil-bath", "--oil-level", "5 mm", "--drag-loss-factor", "-1"],
     "drag-loss-factor must be in"),
    (["--oil", "VG70", "--temperature", "60 degC"], "oil must be an ISO VG grade"),
])
def test_cli_bad_input(capsys, extra, message):
    assert main([*BASE, *extra]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and message in err, err
