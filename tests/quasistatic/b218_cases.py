"""Shared cases of the tests of :mod:`bearinglab.quasistatic`: the 218 bearing of spec 004 and its solve.

Imported by the test modules of this folder (pytest puts the folder on sys.path, as for every test
module of a tree without __init__.py files).
"""

import math

import numpy as np
from hypothesis import settings
from hypothesis import strategies as st

from bearinglab import catalog, quasistatic
from bearinglab.units import RPM

B218 = catalog.get("B218")
GEO = quasistatic._bearing_args(B218)  # (Z, D, d_m, f_i, f_e, alpha0, E', rho) of the 218 bearing, steel
DEG = math.pi / 180.0
FAST = settings(max_examples=30, deadline=None)

loads = st.floats(2.5e3, 45e3)
speeds = st.floats(3000.0, 15000.0)


def _solve(fa, n_rpm, **kw):
    kw.setdefault("friction_limit", np.inf)
    return quasistatic.contact_angles(fa, np.asarray(n_rpm) * RPM, *GEO, **kw)


def _unknowns(s):
    """(X1, X2, delta_i, delta_e, delta_a) / D of a state, from its outputs."""
    _z, d, _dm, _fi, fo, _a0, _ep, _rho = GEO
    le = (fo - 0.5) * d + s.deflection_outer
    return np.stack([le * np.sin(s.contact_angle_outer), le * np.cos(s.contact_angle_outer), s.deflection_inner,
                     s.deflection_outer, s.axial_displacement], axis=-1) / d
