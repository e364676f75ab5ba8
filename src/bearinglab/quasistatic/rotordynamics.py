r"""Bearing stiffness for rotordynamics: export to a ``ross.BearingElement``.

Coefficients
------------
bearing_coefficients   kxx, kxy, kyx, kyy, kzz of one bearing (or from set stiffness matrices) over speeds
from_stiffness         the same from 5 x 5 stiffness matrices already computed
write_coefficients     the coefficients as a JSON file (SI units), written whole
speed_keyword          the ``BearingElement`` keyword of the rotor-speed table for a ROSS version

ROSS (the ``ross-rotordynamics`` package) models a bearing as a linear element on one node with the
translational coefficients kxx, kxy, kyx, kyy (and kzz), damping and mass, each tabulated over the rotor
speed. ROSS 3.0 renamed that table: ``speed=`` is the rotor speed, and ``frequency=`` now means the
excitation (whirl) frequency (petrobras/ross pull requests #1371 and #1404); ROSS 2.x called the rotor-speed
table ``frequency=``. The export writes the keyword the installed ROSS expects (:func:`speed_keyword`), or
the one asked for. The coefficients of a ball bearing depend on the rotor speed (centrifugal forces and
gyroscopic moments change the contact angles), not on the whirl frequency (the quasi-static model has no
damping and no inertia of its own). The 5 x 5 stiffness of :mod:`bearinglab.quasistatic.combined` also
has the tilt terms k_theta_theta (N m/rad), the force-tilt couplings k_x_theta (N/rad) and the axial-
radial/tilt couplings k_z_x, k_z_theta: a ``BearingElement`` cannot carry them. They matter for short
spindles and preloaded angular-contact sets; a ROSS model keeps them only by modelling the set as two
nodes (one element per bearing row) or with a user-defined element. The export holds no damping (the
quasi-static model has none): cxx = cyy = 0.

ROSS is not imported here: the dictionary's keys are ``BearingElement``'s keyword arguments, so
``ross.BearingElement(n=..., **coefficients)`` builds the element.
"""

from __future__ import annotations

import json
import sys
from importlib import metadata

import numpy as np

from .._io import write_text
from .._validate import as_float, check_nonnegative
from ..errors import InputError
from . import combined

__all__ = ["bearing_coefficients", "from_stiffness", "speed_keyword", "write_coefficients"]

_KEYS = {"kxx": (0, 0), "kxy": (0, 1), "kyx": (1, 0), "kyy": (1, 1), "kzz": (2, 2)}
_SPEED_KEYWORDS = ("speed", "frequency")


def speed_keyword(version=None):
    """The ``ross.BearingElement`` keyword of a table over the rotor speed: "speed" (ROSS 3) or "frequency".

    Parameters
    ----------
    version : str, optional
        A ROSS version ("2.3.0", "3.1.0"). Default: the installed ROSS, read from the signature of
        ``BearingElement`` if ross is already imported, else from the package metadata without importing
        it (importing ross takes seconds); "speed", the keyword of the current ROSS, if none is installed.

    Returns
    -------
    str
        "speed" for ROSS 3.0 and later, "frequency" before (where ``frequency=`` meant the rotor speed).

    Examples
    --------
    >>> speed_keyword("2.3.0"), speed_keyword("3.0.0")
    ('frequency', 'speed')
    """
    if version is None:
        ross = sys.modules.get("ross")
        element = getattr(ross, "BearingElement", None)
        if element is not None:
            import inspect

            return "speed" if "speed" in inspect.signature(element).parameters else "frequency"
        try:
            version = metadata.version("ross-rotordynamics")
        except metadata.PackageNotFoundError:
            return "speed"
    major = str(version).strip().split(".")[0]
    if not major.isdigit():
        raise InputError(f"version must be a ROSS version such as '3.1.0', got {version!r}")
    return "speed" if int(major) >= 3 else "frequency"


def from_stiffness(stiffness, shaft_speeds, *, speed_key=None):
    """``BearingElement`` keyword arguments from 5 x 5 stiffness matrices, one per speed.

    Parameters
    ----------
    stiffness : array_like
        (n, 5, 5) in the order (x, y, z, theta_x, theta_y). [N/m, N/rad, N m/m, N m/rad]
    shaft_speeds : array_like
        (n,) rotor speeds, strictly increasing (ROSS interpolates over them). [rad/s]
    speed_key : {"speed", "frequency"}, optional
        The keyword of the speed table: "speed" for ROSS 3, "frequency" for ROSS 2. Default: what the
        installed ROSS expects (:func:`speed_keyword`).

    Returns
    -------
    dict
        ``kxx``, ``kxy``, ``kyx``, ``kyy``, ``kzz`` [N/m], ``cxx``, ``cyy`` (zeros) [N s/m] and the rotor
        speeds under ``speed_key`` [rad/s], each an (n,) array.

    Examples
    --------
    >>> c = from_stiffness(np.diag([2e8, 2e8, 5e7, 1e4, 1e4])[None], [0.0], speed_key="speed")
    >>> print(sorted(c), c["kxx"])
    ['cxx', 'cyy', 'kxx', 'kxy', 'kyx', 'kyy', 'kzz', 'speed'] [2.e+08]
    """
    key = speed_keyword() if speed_key is None else speed_key
    if key not in _SPEED_KEYWORDS:
        raise InputError(f"speed_key must be one of {list(_SPEED_KEYWORDS)}, got {speed_key!r}")
    k = as_float("stiffness", stiffness)
    w = np.atleast_1d(check_nonnegative("shaft_speeds", shaft_speeds, "rad/s"))
    if k.ndim != 3 or k.shape[1:] != (5, 5) or len(k) != w.size:
        raise InputError(f"stiffness must have shape (n, 5, 5) with n = len(shaft_speeds) = {w.size}, got {k.shape}")
    if not np.all(np.isfinite(k)):
        raise InputError("stiffness must be finite (a case that did not converge has no stiffness)")
    if np.any(np.diff(w) <= 0):  # ROSS refuses (3.x) or misreads (2.x, interp1d) any other table
        raise InputError(f"shaft_speeds must be strictly increasing for a ROSS table, got {w.tolist()} rad/s")
    out = {name: k[:, i, j].copy() for name, (i, j) in _KEYS.items()}
    out.update(cxx=np.zeros(w.size), cyy=np.zeros(w.size))
    out[key] = w.astype(float)
    return out


def bearing_coefficients(bearing, loads, shaft_speeds, *, speed_key=None, **options):
    """Stiffness coefficients of one bearing under a load, over a list of speeds, for ROSS.

    Parameters
    ----------
    bearing : BallBearing
        See :func:`bearinglab.quasistatic.combined.combined_analysis`.
    loads : array_like
        (5,) F_x, F_y, F_z [N], M_x, M_y [N m] (the same at every speed).
    shaft_speeds : array_like
        (n,) speeds. [rad/s]
    speed_key : {"speed", "frequency"}, optional
        See :func:`from_stiffness`.

    Other Parameters
    ----------------
    **options
        Passed to :func:`~bearinglab.quasistatic.combined.combined_analysis`.

    Returns
    -------
    dict
        See :func:`from_stiffness`.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> from bearinglab.units import RPM
    >>> c = bearing_coefficients(catalog.get("B218"), [0, 0, 10e3, 0, 0], [0.0, 10000 * RPM])
    >>> print(np.round(c["kxx"] / 1e6))
    [408.  49.]
    """
    w = np.atleast_1d(check_nonnegative("shaft_speeds", shaft_speeds, "rad/s")).astype(float)
    f = as_float("loads", loads)
    if f.shape != (5,):
        raise InputError(f"loads must have shape (5,), got {f.shape}")
    r = combined.combined_analysis(bearing, np.broadcast_to(f, w.shape + (5,)), w, **options)
    return from_stiffness(r.stiffness, w, speed_key=speed_key)


def write_coefficients(coefficients, path):
    """Write the coefficients as JSON (lists of floats, SI units), whole or not at all.

    Parameters
    ----------
    coefficients : dict
        From :func:`bearing_coefficients` or :func:`from_stiffness`.
    path : str or Path
        Output file.

    Returns
    -------
    Path
        The file written; ``ross.BearingElement(n=..., **json.load(...))`` reads it back.
    """
    text = json.dumps({k: np.asarray(v, dtype=float).tolist() for k, v in coefficients.items()}, indent=1)
    return write_text(path, text + "\n")
