r"""Bearing stiffness for rotordynamics: export to a ``ross.BearingElement``.

Coefficients
------------
bearing_coefficients   kxx, kxy, kyx, kyy, kzz of one bearing (or from set stiffness matrices) over speeds
from_stiffness         the same from 5 x 5 stiffness matrices already computed
write_coefficients     the coefficients as a JSON file (SI units), written whole

ROSS (the ``ross-rotordynamics`` package) models a bearing as a linear element on one node with the
translational coefficients kxx, kxy, kyx, kyy (and kzz), damping and mass, each a function of
frequency (here the shaft speed). The 5 x 5 stiffness of :mod:`bearinglab.quasistatic.combined` also
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

import numpy as np

from .._io import write_text
from .._validate import as_float, check_nonnegative
from ..errors import InputError
from . import combined

__all__ = ["bearing_coefficients", "from_stiffness", "write_coefficients"]

_KEYS = {"kxx": (0, 0), "kxy": (0, 1), "kyx": (1, 0), "kyy": (1, 1), "kzz": (2, 2)}


def from_stiffness(stiffness, shaft_speeds):
    """``BearingElement`` keyword arguments from 5 x 5 stiffness matrices, one per speed.

    Parameters
    ----------
    stiffness : array_like
        (n, 5, 5) in the order (x, y, z, theta_x, theta_y). [N/m, N/rad, N m/m, N m/rad]
    shaft_speeds : array_like
        (n,) speeds, ROSS's ``frequency``. [rad/s]

    Returns
    -------
    dict
        ``kxx``, ``kxy``, ``kyx``, ``kyy``, ``kzz`` [N/m], ``cxx``, ``cyy`` (zeros) [N s/m] and
        ``frequency`` [rad/s], each an (n,) array.

    Examples
    --------
    >>> c = from_stiffness(np.diag([2e8, 2e8, 5e7, 1e4, 1e4])[None], [0.0])
    >>> print(sorted(c), c["kxx"])
    ['cxx', 'cyy', 'frequency', 'kxx', 'kxy', 'kyx', 'kyy', 'kzz'] [2.e+08]
    """
    k = as_float("stiffness", stiffness)
    w = np.atleast_1d(check_nonnegative("shaft_speeds", shaft_speeds, "rad/s"))
    if k.ndim != 3 or k.shape[1:] != (5, 5) or len(k) != w.size:
        raise InputError(f"stiffness must have shape (n, 5, 5) with n = len(shaft_speeds) = {w.size}, got {k.shape}")
    if not np.all(np.isfinite(k)):
        raise InputError("stiffness must be finite (a case that did not converge has no stiffness)")
    out = {name: k[:, i, j].copy() for name, (i, j) in _KEYS.items()}
    out.update(cxx=np.zeros(w.size), cyy=np.zeros(w.size), frequency=w.astype(float))
    return out


def bearing_coefficients(bearing, loads, shaft_speeds, **options):
    """Stiffness coefficients of one bearing under a load, over a list of speeds, for ROSS.

    Parameters
    ----------
    bearing : BallBearing
        See :func:`bearinglab.quasistatic.combined.combined_analysis`.
    loads : array_like
        (5,) F_x, F_y, F_z [N], M_x, M_y [N m] (the same at every speed).
    shaft_speeds : array_like
        (n,) speeds. [rad/s]

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
    return from_stiffness(r.stiffness, w)


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
