"""The shaft-system file: read as written, and every bad input refused in one line naming its field."""

import json
import math

import pytest

from bearinglab import shaft
from bearinglab.errors import InputError

GOOD = '''
speed = "3000 rpm"
gravity = "-y"
[material]
material = "steel"
[[sections]]
length = "50 mm"
diameter = "30 mm"
[[sections]]
length = "200 mm"
diameter = "35 mm"
bore = "10 mm"
[[sections]]
length = "50 mm"
diameter = "30 mm"
[[supports]]
name = "A"
position = "25 mm"
bearing = "6206"
axial = true
housing = { radial_stiffness = "500 N/um" }
[[supports]]
name = "B"
position = "275 mm"
bearing = "6206"
[[gears]]
position = "150 mm"
pitch_diameter = "120 mm"
helix_angle = "12 deg"
power = "5 kW"
mesh_angle = "90 deg"
mass = "2 kg"
polar_inertia = "0.004 kg*m^2"
[[pulleys]]
position = "300 mm"
force = "800 N"
direction = "180 deg"
torque = "-15.915494309189533 N*m"
[[cases]]
time_share = 0.25
factor = 1.5
[[cases]]
time_share = "75 %"
factor = 0.8
[lubricant]
oil = "VG68"
temperature = "70 degC"
contamination = "normal"
'''


def test_a_file_reads_into_the_model():
    d = shaft.from_text(GOOD)
    s = d.system
    assert s.speed == pytest.approx(3000 * 2 * math.pi / 60)
    assert [sec.length for sec in s.shaft.sections] == pytest.approx([0.05, 0.2, 0.05])
    assert s.shaft.sections[1].bore == pytest.approx(0.01)
    assert s.supports[0].axial and not s.supports[1].axial
    assert s.supports[0].housing.radial_stiffness == pytest.approx(5e8)
    assert s.gears[0].power == pytest.approx(5000.0) and s.gears[0].pressure_angle == pytest.approx(math.radians(20))
    assert s.gravity == pytest.approx((0.0, -9.80665, 0.0))
    assert list(d.time_share) == pytest.approx([0.25, 0.75]) and list(d.case_factor) == [1.5, 0.8]
    assert list(d.case_speed) == pytest.approx([s.speed, s.speed])
    assert d.lubricant == {"iso_vg": 68, "temperature": pytest.approx(343.15), "contamination": "normal_cleanliness"}
    # the same document as JSON
    import tomllib

    j = shaft.from_text(json.dumps(tomllib.loads(GOOD)))
    assert j.system == s


def _replace(text, old, new):
    assert old in text
    return text.replace(old, new, 1)


BAD = [
    ("a support outside the shaft", 'position = "275 mm"', 'position = "325 mm"',
     r"^supports\[1\]\.position: B at 325 mm lies outside the shaft \(0 \.\.\. 300 mm\)$"),
    ("overlapping sections", 'length = "200 mm"', 'length = "200 mm"\nstart = "40 mm"',
     r"^sections\[1\]\.start: the section overlaps the section before it"),
    ("no axial location", "axial = true\n", "",
     r"^supports: no support locates the shaft axially; mark the fixed bearing\(s\) with axial = true$"),
    ("a bearing wider than its seat", 'position = "25 mm"', 'position = "45 mm"',
     r"^supports\[0\]\.position: bearing 6206 \(width 16 mm\) at 45 mm is wider than its seat"),
    ("a mechanism", '[[supports]]\nname = "B"\nposition = "275 mm"\nbearing = "6206"\n', "",
     r"^supports: a mechanism: 1 support holds the shaft at one point"),
    ("a bare number", 'length = "50 mm"', "length = 50", r"^sections\[0\]\.length: 50 has no unit"),
    ("an unknown key", 'bearing = "6206"\naxial', 'bearing = "6206"\naxis = 1\naxial',
     r"^supports\[0\] \(A\)\.axis: unknown key"),
    ("a wrong dimension", 'force = "800 N"', 'force = "800 mm"', r"^pulleys\[0\]\.force: '800 mm' is a length"),
    ("an unknown bearing", 'bearing = "6206"\naxial', 'bearing = "9999 XYZ"\naxial', r"^supports\[0\] \(A\)\.bearing: "),
    ("torques that do not balance", 'torque = "-15.915494309189533 N*m"', 'torque = "-10 N*m"',
     r"^loads: the torques on the shaft do not balance \(their sum is 5\.91549 N m"),
    ("shares that do not sum to 1", 'time_share = "75 %"', 'time_share = "70 %"',
     r"^cases: the time shares sum to 0\.95, not 1$"),
    ("two kinds of support", 'bearing = "6206"\naxial', 'bearing = "6206"\nrigid = true\naxial',
     r"^supports\[0\] \(A\): give one of bearing, bearing_set, radial_stiffness or rigid = true, got bearing, rigid$"),
    ("invalid TOML", "[material]", "[material", r"^document: not valid TOML"),
    ("a case whose torques do not balance", 'factor = 0.8', 'factor = 0.8\nspeed = "1500 rpm"',
     r"^cases\[1\]\.loads: the torques on the shaft do not balance"),
]


@pytest.mark.parametrize("old,new,pattern", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_gets_one_line_naming_the_field(old, new, pattern):
    with pytest.raises(InputError, match=pattern) as err:
        shaft.from_text(_replace(GOOD, old, new))
    assert "\n" not in str(err.value)


def test_a_file_on_disk_and_its_json(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(GOOD, encoding="utf-8")
    assert shaft.load(path).system == shaft.from_text(GOOD).system
    with pytest.raises(InputError, match="no such file"):
        shaft.load(tmp_path / "missing.json")


def test_the_python_model_checks_itself():
    b = shaft.reading.from_text(GOOD).system.supports[0].bearing
    with pytest.raises(InputError, match="bore must be < the diameter 30 mm, got 40 mm"):
        shaft.Section(0.1, 0.03, 0.04)
    with pytest.raises(InputError, match="orientation must be"):
        shaft.BearingSupport("A", 0.1, b, orientation=0)
    with pytest.raises(InputError, match="give the gear's torque or its power"):
        shaft.Gear(0.1, 0.1, 0.3)
    with pytest.raises(InputError, match="elements must be a whole number in 1 ... 400"):
        shaft.from_text(GOOD).system.replace(elements=1000)
