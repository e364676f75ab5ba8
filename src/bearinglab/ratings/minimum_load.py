r"""The minimum load of a running ball bearing, as bearing makers publish it (SKF).

Rules
-----
general_minimum_load     0.01 C: SKF's general rule for ball bearings
minimum_radial_load      F_rm = k_r (nu n/1000)^(2/3) (d_m/100)^2 of deep-groove bearings (and angular
                         pairs back-to-back or face-to-face), with the maker's factor k_r
minimum_axial_load       F_am = A (n/1000)^2 of single angular-contact bearings, with the maker's factor A
minimum_load_warnings    the cases of a running bearing whose equivalent load is below the rule

Below its minimum load a running bearing's balls skid and smear the raceways (the cage and the balls'
inertia drag them). The rules and their sources are in ``data/minimum_load.toml``; the catalogue's units
(kN, r/min, mm, mm^2/s) are converted here once. The test-stand criterion against gyroscopic slip of spec 000
(:func:`bearinglab.stand.min_axial_load_gyroscopic`, ``bearinglab stand-load``) is another thing: the
least stand load at which friction holds the balls against their gyroscopic moment at mu = 0.02.

References
----------
.. [1] SKF, *Rolling bearings*, PUB BU/P1 17000 EN, 2018: "Requisite minimum load" (0.01 C), deep groove
   ball bearings "Loads" p. 254 (F_rm), angular contact ball bearings "Loads" p. 398 (F_am).
"""

from __future__ import annotations

import tomllib
from functools import cache
from importlib import resources

import numpy as np

from .._validate import as_float, check_nonnegative, check_positive

__all__ = [
    "general_minimum_load",
    "minimum_axial_load",
    "minimum_load_rules",
    "minimum_load_warnings",
    "minimum_radial_load",
]

_KN, _RPM, _MM, _CST = 1e3, 2.0 * np.pi / 60.0, 1e-3, 1e-6  # N/kN, rad/s per r/min, m/mm, m^2/s per mm^2/s


@cache
def minimum_load_rules():
    """The rules of ``data/minimum_load.toml``, each with its ``source``.

    Returns
    -------
    dict
        ``general`` (``factor``), ``deep_groove`` and ``angular_contact`` (the constants of the formulas).
    """
    with (resources.files("bearinglab") / "data" / "minimum_load.toml").open("rb") as f:
        return tomllib.load(f)


def general_minimum_load(dynamic_load_rating):
    """SKF's general minimum load of a ball bearing, 0.01 C.

    Parameters
    ----------
    dynamic_load_rating : array_like
        C. [N]

    Returns
    -------
    ndarray or float
        0.01 C. [N]

    Examples
    --------
    >>> print(f"{general_minimum_load(14800.0):.0f} N")
    148 N
    """
    c = check_positive("dynamic_load_rating", dynamic_load_rating, "N")
    return (minimum_load_rules()["general"]["factor"] * c)[()]


def minimum_radial_load(shaft_speed, mean_diameter, kinematic_viscosity, minimum_load_factor):
    r"""SKF's minimum radial load of a deep-groove ball bearing, F_rm.

    Parameters
    ----------
    shaft_speed : array_like
        n. [rad/s]
    mean_diameter : array_like
        d_m = (d + D)/2. [m]
    kinematic_viscosity : array_like
        nu at the operating temperature. [m^2/s]
    minimum_load_factor : array_like
        k_r of the maker's product table (catalogue units: F_rm in kN). [-]

    Returns
    -------
    ndarray or float
        :math:`F_{rm} = k_r (\nu n / 1000)^{2/3} (d_m / 100)^2` (kN, mm^2/s, r/min, mm; here in SI). [N]

    Examples
    --------
    >>> print(f"{minimum_radial_load(3000 * 2 * np.pi / 60, 0.0385, 20e-6, 0.025) / 1e3:.4f} kN")
    0.0568 kN
    """
    rule = minimum_load_rules()["deep_groove"]
    n = check_nonnegative("shaft_speed", shaft_speed, "rad/s") / _RPM
    dm = check_positive("mean_diameter", mean_diameter, "m") / _MM
    nu = check_positive("kinematic_viscosity", kinematic_viscosity, "m^2/s") / _CST
    kr = check_positive("minimum_load_factor", minimum_load_factor, "-")
    frm = kr * (nu * n / rule["speed_viscosity_scale"]) ** rule["speed_viscosity_exponent"] \
        * (dm / rule["diameter_scale_mm"]) ** rule["diameter_exponent"]
    return (frm * _KN)[()]


def minimum_axial_load(shaft_speed, minimum_axial_load_factor):
    r"""SKF's minimum axial load of a single angular-contact ball bearing (or a tandem pair), F_am.

    Parameters
    ----------
    shaft_speed : array_like
        n. [rad/s]
    minimum_axial_load_factor : array_like
        A of the maker's product table (catalogue units: F_am in kN). [-]

    Returns
    -------
    ndarray or float
        :math:`F_{am} = A (n / 1000)^2` (kN, r/min; here in SI). [N]

    Examples
    --------
    >>> print(f"{minimum_axial_load(10000 * 2 * np.pi / 60, 0.00377) / 1e3:.4f} kN")
    0.3770 kN
    """
    rule = minimum_load_rules()["angular_contact"]
    n = check_nonnegative("shaft_speed", shaft_speed, "rad/s") / _RPM
    a = check_positive("minimum_axial_load_factor", minimum_axial_load_factor, "-")
    return (a * (n / rule["speed_scale"]) ** rule["speed_exponent"] * _KN)[()]


def minimum_load_warnings(equivalent_load, shaft_speed, dynamic_load_rating, *, rating="C", load="P",
                          case_index=None):
    """The cases of a running ball bearing loaded below SKF's general minimum load 0.01 C.

    Parameters
    ----------
    equivalent_load : array_like
        The bearing's load, one per case (ISO 281's P = X F_r + Y F_a where defined). [N]
    shaft_speed : array_like
        Speed, one per case; a case at rest is not judged. [rad/s]
    dynamic_load_rating : float
        C. [N]
    rating : str
        How C was obtained, for the message ("C", "C (ISO 281, from the geometry)").
    load : str
        What ``equivalent_load`` is, for the message ("P = X F_r + Y F_a (ISO 281)").
    case_index : array_like, optional
        Case numbers to quote (default 0, 1, ...).

    Returns
    -------
    list of str
        One message (the number of cases and the first one, loads in kN to 4 significant digits), or none.

    Notes
    -----
    The general rule of [1]_; the makers' finer rules (:func:`minimum_radial_load`,
    :func:`minimum_axial_load`) need a factor from their product tables for each bearing.

    References
    ----------
    .. [1] SKF, *Rolling bearings*, PUB BU/P1 17000 EN, 2018, "Requisite minimum load".

    Examples
    --------
    >>> minimum_load_warnings([50.0, 5000.0], [1500.0, 1500.0], 143210.0)[0][:63]
    'minimum load: 1 of 2 case(s) at speed below 0.01 C = 1.432 kN ('
    """
    p = np.ravel(as_float("equivalent_load", equivalent_load))
    w = np.ravel(as_float("shaft_speed", shaft_speed))
    p, w = np.broadcast_arrays(p, w)
    fmin = float(general_minimum_load(dynamic_load_rating))
    low = (w > 0) & (p < fmin)
    if not low.any():
        return []
    idx = np.arange(p.size) if case_index is None else np.ravel(case_index)
    k = int(np.flatnonzero(low)[0])
    return [(f"minimum load: {int(low.sum())} of {p.size} case(s) at speed below 0.01 {rating} = "
             f"{fmin / _KN:.4g} kN (SKF's minimum load of ball bearings, Rolling bearings 2018), e.g. case "
             f"{idx[k]}: {load} = {p[k] / _KN:.4g} kN: the balls may skid and smear the raceways; add load or "
             "preload (the test-stand criterion against gyroscopic slip is `bearinglab stand-load`)")]
