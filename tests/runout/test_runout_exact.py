"""The exact (not linearised) reduction of spec 003 section 15, example 4 (``runout.exact``)."""

import numpy as np
import pytest

from bearinglab import runout as R
from bearinglab.errors import ConvergenceError

UM = 1e-6


def um(x):
    return np.asarray(x) / UM


# ------------------------------------------------------------------------------ exact geometry
def test_exact_reduction_properties(g):
    th = R.ball_angles(0.0, g)
    assert np.max(np.abs(um(R.exact_reduction(th, 0.0, 0.0, 0.0, g)))) < 1e-9
    # a lateral shift is seen as a cos(theta) pattern of period 2 pi: balls opposite see opposite signs
    s = R.exact_reduction(np.array([0.0, np.pi]), 0.3 * UM, 0.0, 0.0, g)
    assert s[0] > 0 > s[1]
    with pytest.raises(ConvergenceError):
        R.exact_reduction(th, 0.8 * UM, -0.5 * UM, 2 * UM, g, max_iter=1)
