"""The blank measurement-session file of the friction-rig lab: its text and a safe writer.

template           the text of a blank, commented session file (valid TOML)
write_template     write it to a new file (never over an existing one unless asked; written whole)
FORMAT             the format identifier the template writes and :mod:`.measurement` reads

:mod:`bearinglab.lab.measurement` reads the file back and re-exports these names.
"""

from __future__ import annotations

from pathlib import Path

from .. import catalog as _catalog
from .._io import write_text
from ..errors import InputError

__all__ = ["FORMAT", "template", "write_template"]

FORMAT = "bearinglab-friction-session/1"

_TEMPLATE = """\
# bearinglab friction-rig measurement session (the friction-rig lab; DP11A-type rig).
# Fill in the bearing, the calibration tables and the rows, then run
#     bearinglab friction lab THIS_FILE --out report-dir
# Quantities are strings with units ("8 mm", "1354 N", "0 kg"). Lines starting with # are comments.
# The format is documented in examples/friction/README.md.
format = "{format}"

[session]
title = ""
date = ""                 # e.g. "2024-03-14"
operator = ""
rig = "DP11A"
lubricant = ""            # oil or grease, and the temperature if known
notes = ""

[bearing]
{bearing_block}

[handbook]
# Optional overrides of the handbook constants (plain numbers). Without them the lab's handbook
# values apply: x0, y0 by bearing type, mu, and f, c by bearing series.
# x0 = 0.6
# y0 = 0.5
# mu = 0.0015
# f = 0.0009
# c = 0.55

# Optional task 4: the SKF four-term model fitted to the rows (examples/friction/skf_6205.toml).
# [skf]
# viscosity = "30 mm^2/s"   # operating viscosity of the oil (of the base oil for grease), required
# lubrication = "grease"    # grease | oil-air | oil-jet
# series = "62"             # bearing series of the SKF constants (or r1, r2, s1, s2 as numbers)
# fit = "sliding"           # sliding (mu_sl) | rolling (a scale on M_rr) | both

[rig]
tare_mass = "0 kg"        # added to every Q (housing, holder); the source uses 0
gravity = "9.81 m/s^2"    # the source's value

# Calibration tables: [reading, value] pairs with strictly increasing readings
# and values, at least 2 points. Conversion is piecewise linear; a reading outside a table is an
# error. Leave a table empty if no row uses it (rows may give speed and torque directly).
[calibration.speed]
unit = "rpm"
points = [
    # [0, 0],
    # [10, 455],
]

[calibration.torque_1]    # switch position 1 (the more sensitive one)
unit = "N*mm"
points = [
    # [0, 0.0],
    # [10, 0.0102],
]

[calibration.torque_2]    # switch position 2
unit = "N*mm"
points = [
    # [0, 0.0],
    # [10, 0.041],
]

[measurements]
# One row per measurement. series: T4 = load series at fixed tilt (Table 4; give the speed-column
# label, rows with the same label share a speed setting), T5 = speed series at fixed Q (Table 5).
# Give speed_reading or speed, and torque_reading with its switch position (1 or 2) or torque.
# Empty cells are "not given". The rows may instead live in a CSV file: file = "rows.csv".
csv = \'\'\'
series, tilt [deg], mass [kg], column, speed_reading, torque_reading, switch, speed [rpm], torque [N*mm], note
\'\'\'
"""

_BEARING_BLANK = '''\
# A catalog bearing (bearinglab catalog list), e.g. one of the lab's 1000095, 18, 101:
# catalog = "18"
# or the bearing's data:
designation = ""
type = "radial"           # radial | angular
# contact_angle = "26 deg"  # angular contact only
bore = ""                 # d, e.g. "8 mm"
mean_diameter = ""        # d_m = (d + D)/2, e.g. "13.5 mm" (or outside_diameter = "19 mm")
static_load_rating = ""   # C0, e.g. "1354 N"'''


def template(*, bearing=None):
    """Text of a blank, commented measurement-session file.

    Parameters
    ----------
    bearing : str, optional
        Catalog name to fill in (e.g. ``"18"``); otherwise the inline bearing fields are left blank.

    Returns
    -------
    str
        Valid TOML. Run as it is, it stops at the first thing left to fill in.

    Examples
    --------
    >>> "[calibration.torque_2]" in template()
    True
    """
    if bearing is None:
        block = _BEARING_BLANK
    else:
        b = _catalog.get(bearing)

        def known(value, scale, unit):  # a catalog entry may lack the envelope or C0 (B218, 4-1006095)
            return "not in the catalog" if value is None else f"{value * scale:g} {unit}"

        dm = None if b.bore is None or b.outside_diameter is None else b.mean_diameter
        block = (
            f'catalog = "{bearing}"          # {b.type}, d = {known(b.bore, 1e3, "mm")}, d_m = '
            f"{known(dm, 1e3, 'mm')}, C0 = {known(b.static_load_rating, 1.0, 'N')}\n"
            "# Fields given here override the catalog (type, contact_angle, bore, mean_diameter,\n"
            "# outside_diameter, static_load_rating)."
        )
    return _TEMPLATE.format(format=FORMAT, bearing_block=block)


def write_template(path, *, bearing=None, overwrite=False):
    """Write a blank session file (whole, via a temporary file and a rename).

    Parameters
    ----------
    path : str or Path
        The new file.
    bearing : str, optional
        Catalog name to fill in.
    overwrite : bool
        Replace an existing file; by default an existing file is an error (it may hold data).

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    InputError
        The file exists (and ``overwrite`` is false), or the bearing is unknown.
    """
    path = Path(path)
    text = template(bearing=bearing)
    if path.exists() and not overwrite:
        raise InputError(f"{path}: file exists; choose a new name (or --force to replace it)")
    if path.is_dir():
        raise InputError(f"{path}: is a directory")
    write_text(path, text)
    return path
