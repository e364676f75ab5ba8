"""Runout error files (``runout.files``): reading every feature, errors that name the place, writing
with an exact round trip."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from bearinglab import runout as R
from bearinglab.errors import CatalogError, InputError

UM = 1e-6


# ------------------------------------------------------------------------------ error files
def _write(tmp_path, text, name="e.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


GEOM = """
[geometry]
balls = 16
ball_diameter = "7.144 mm"
pitch_diameter = "54 mm"
outer_conformity = 0.53
inner_conformity = 0.52
contact_angle = "15 deg"
"""


def test_error_file_all_features(tmp_path, g):
    (tmp_path / "prof.csv").write_text(
        "# angle deg, deviation um\n"
        + "\n".join(f"{a}, {0.2 * math.cos(math.radians(2 * a))}" for a in range(0, 360, 15)),
        encoding="utf-8",
    )
    p = _write(
        tmp_path,
        GEOM
        + """
first_ball_angle = "10 deg"
[errors.inner.radial]
profile = "prof.csv"
max_order = 4
[errors.inner.axial]
sin = { 1 = "0.3 um" }
[errors.outer.groove]
cos = { 0 = 50 }
unit = "nm"
[errors.outer.normal]
angle = [0, 90, 180, 270]
deviation = [0.1, 0, -0.1, 0]
max_order = 1
[errors.balls]
outer_deficit = [0.1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
inner_deficit = [0, 0.2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]
[tilt]
alpha = 5
beta = "-0.01 mrad"
""",
    )
    geom, e = R.load_error_file(p)
    assert geom.first_ball_angle == pytest.approx(math.radians(10))
    assert_allclose(e.inner.radial.cos, [0, 0, 0.2e-6, 0, 0], atol=1e-18)
    assert e.inner.axial.sin[1] == pytest.approx(0.3e-6)
    assert e.outer.groove.cos[0] == pytest.approx(50e-9)
    assert_allclose(e.outer.normal.cos, [0, 0.1e-6], atol=1e-18)
    assert e.ball_outer_deficit[0] == pytest.approx(0.1e-6) and e.ball_inner_deficit[
        1
    ] == pytest.approx(0.2e-6)
    assert e.tilt_x == pytest.approx(5e-6) and e.tilt_y == pytest.approx(-10e-6)
    # a given geometry overrides the file's
    g2, _ = R.load_error_file(p, g)
    assert g2 is g


@pytest.mark.parametrize(
    "text, match",
    [
        ("[geometry]\nballs = 16\n", "ball_diameter"),
        (
            GEOM + "[errors.inner.radial]\ncos = { 1 = 0.5 }\nfoo = 1\n",
            r"\[errors.inner.radial\], key 'foo': unknown key",
        ),
        (GEOM + "[errors.balls]\ndiameter = [0.1, 0.2]\n", "16 balls, got 2 values"),
        (
            GEOM + "[errors.inner.radial]\ncos = { 1 = 0.5 }\nprofile = 'x.csv'\nmax_order = 2\n",
            "not both",
        ),
        (GEOM + "[errors.inner.radial]\nprofile = 'missing.csv'\nmax_order = 2\n", "no such file"),
        (GEOM + "[errors.inner.radial]\nprofile = 'missing.csv'\n", "max_order"),
        (GEOM + "[errors.inner.radial]\ncos = { 1 = '2 kg' }\n", "is a mass, expected a length"),
        (GEOM + "[errors.inner.radial]\nsin = { 0 = 1 }\n", "sin has no order 0"),
        (GEOM + "[errors.inner.wobble]\ncos = { 1 = 1 }\n", "unknown key"),
        (GEOM + "[tilt]\nalpha = '3 mm'\n", "expected an angle"),
        (GEOM + "[errors.balls]\ndiameter = [0.1]\nouter_deficit = [0.1]\n", "not both"),
        (
            GEOM.replace(
                'pitch_diameter = "54 mm"',
                'inner_bottom_radius = "23.4 mm"\npitch_diameter = "54 mm"',
            ),
            "exactly one",
        ),
        (GEOM.replace("0.53", "0.49"), "outer_conformity must be > 0.5"),
        ("title = 'x'\n", "no \\[geometry\\] table"),
        ("[geometry\n", "not valid TOML"),
    ],
)
def test_error_file_problems_name_the_place(tmp_path, text, match):
    p = _write(tmp_path, text)
    with pytest.raises(CatalogError, match=match):
        R.load_error_file(p)


def test_error_file_is_not_modified(tmp_path):
    p = _write(
        tmp_path,
        GEOM + "[errors.balls]\ndiameter = [2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]\n",
    )
    before = p.read_bytes(), p.stat().st_mtime_ns
    R.load_error_file(p)
    assert (p.read_bytes(), p.stat().st_mtime_ns) == before


def test_missing_error_file():
    with pytest.raises(CatalogError, match="no such file"):
        R.load_error_file("/nonexistent/errors.toml")


def test_shipped_measured_profile_example():
    """The profile example: catalog geometry, a CSV roundness profile, inline samples, contact deficits and a
    tilt varying with rotation."""
    from pathlib import Path

    path = Path(__file__).resolve().parents[2] / "examples" / "runout" / "measured_profile.toml"
    geom, e = R.load_error_file(path)
    assert geom.n_balls == 16 and geom.contact_angle == pytest.approx(math.radians(40))
    assert geom.first_ball_angle == pytest.approx(math.radians(5))
    assert e.inner.radial.cos.size == 9 and e.outer.radial.cos.size == 4
    assert isinstance(e.tilt_x, R.FourierSeries) and isinstance(e.tilt_y, R.FourierSeries)
    t = R.rotation_sequence(geom, e, revolutions=2, steps_per_revolution=90, refine=True)
    assert np.all(t.displacement.converged)
    assert 0 < t.metrics.radial_ptp_max < 5 * UM


# ------------------------------------------------------------------------------ writing
finite = st.floats(
    allow_nan=False, allow_infinity=False
)  # any finite double, subnormals and -0.0 too


@settings(max_examples=60, deadline=None)
@given(
    coefficients=st.lists(finite, min_size=4, max_size=4),
    deficits=st.lists(finite, min_size=16, max_size=16),
    tilt=finite,
    first_ball_angle=st.floats(-10.0, 10.0),
)
def test_written_error_file_reads_back_bit_for_bit(
    tmp_path_factory, g, coefficients, deficits, tilt, first_ball_angle
):
    c = np.array(coefficients)
    series = R.FourierSeries(c, c[::-1])
    e = R.manufacturing_errors(
        16,
        outer=R.RacewayErrors(radial=series, axial=R.FourierSeries(c[:2], c[2:])),
        inner=R.RacewayErrors(groove=series, normal=R.FourierSeries(-c, c)),
        ball_outer_deficit=deficits,
        ball_inner_deficit=deficits[::-1],
        tilt_x=tilt,
        tilt_y=R.FourierSeries(c[:3], np.r_[0.0, c[1:3]]),
    )
    geometry = g._replace(first_ball_angle=first_ball_angle)
    path = R.write_error_file(tmp_path_factory.mktemp("w") / "e.toml", e, geometry, title='a "b"')
    g2, e2 = R.load_error_file(path)
    assert g2 == geometry
    for ring in ("outer", "inner"):
        for name in ("radial", "axial", "groove", "normal"):
            a, b = getattr(getattr(e, ring), name), getattr(getattr(e2, ring), name)
            assert (a is None) == (b is None), (ring, name)
            if a is not None:  # sin[0] multiplies sin(0 theta) = 0: it is not written
                assert np.array_equal(a.cos, b.cos) and np.array_equal(a.sin[1:], b.sin[1:])
    for name in ("ball_outer_deficit", "ball_inner_deficit"):
        assert np.array_equal(getattr(e, name), getattr(e2, name))
    assert e2.tilt_x == (tilt if tilt != 0.0 else 0.0)
    assert np.array_equal(e2.tilt_y.cos, e.tilt_y.cos) and np.array_equal(
        e2.tilt_y.sin, e.tilt_y.sin
    )


def test_write_error_file_refuses_what_a_file_cannot_hold(tmp_path, g):
    path = tmp_path / "e.toml"
    with pytest.raises(InputError, match="function of the rotation angle cannot be written"):
        R.write_error_file(path, R.manufacturing_errors(16, tilt_y=lambda psi: 0 * psi), g)
    two_d = R.FourierSeries(np.zeros((2, 3)), np.zeros((2, 3)))
    with pytest.raises(InputError, match="must be 1-D"):
        R.write_error_file(path, R.manufacturing_errors(16, inner=R.RacewayErrors(radial=two_d)), g)
    with pytest.raises(InputError, match=r"one value per ball \(16\)"):
        R.write_error_file(path, R.manufacturing_errors(15), g)
    with pytest.raises(InputError, match="errors must be a ManufacturingErrors"):
        R.write_error_file(path, None, g)
    assert list(tmp_path.iterdir()) == []  # nothing written, not even a temporary file


def test_sample_error_files_reproduce_the_samples(tmp_path, g):
    """Defect 6: the error files of the worst samples give back their metrics exactly."""
    r = R.monte_carlo(g, "G5", "P4", 12, 4, steps_per_revolution=30, chunk_size=5)
    worst = R.worst_samples(r, "radial_ptp_max", 2)
    paths = R.write_sample_error_files(tmp_path / "worst", r, g, worst)
    assert [p.name for p in paths] == [f"sample_{i}.toml" for i in worst]
    for i, path in zip(worst, paths):
        text = path.read_text(encoding="utf-8")
        assert "--revolutions 2 --steps-per-rev 30" in text and "G5 balls, P4 rings" in text
        geometry, errors = R.load_error_file(path)
        t = R.rotation_sequence(geometry, errors, revolutions=2, steps_per_revolution=30)
        for name in R.METRICS:
            assert getattr(t.metrics, name) == getattr(r.samples, name)[i], name
    with pytest.raises(InputError, match="result must be a MonteCarloResult"):
        R.write_sample_error_files(tmp_path, r.samples, g, worst)


def test_a_document_already_read_gives_what_its_file_gives_and_reads_no_file():
    import tomllib
    from pathlib import Path

    from bearinglab.runout import files

    folder = Path(__file__).resolve().parents[2] / "examples" / "runout"
    path = folder / "example3_mixed.toml"
    g1, e1 = files.load_error_file(path)
    g2, e2 = files.read_error_document(tomllib.loads(path.read_text(encoding="utf-8")))
    assert g1 == g2

    def same(a, b):  # field by field, arrays exactly
        if isinstance(a, tuple):
            return type(a) is type(b) and len(a) == len(b) and all(map(same, a, b))
        if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
            return np.array_equal(a, b)
        return a == b

    assert same(e1, e2)
    doc = tomllib.loads((folder / "measured_profile.toml").read_text(encoding="utf-8"))
    with pytest.raises(CatalogError, match="cannot refer to files") as err:
        files.read_error_document(doc, source="the posted document")
    assert str(err.value).startswith("the posted document, [")
