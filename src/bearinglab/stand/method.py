r"""The test-stand method of spec 000: axial load on a vibration test stand and the operating contact angle.

A bearing is checked on a vibration stand under a pure axial load that must keep the balls from
gyroscopic slip (section 3); the load sets the operating contact angle, which shifts the
characteristic frequencies (section 6). The force characteristic C* holds the contact stiffness at the
free contact angle (section 5), so the load-angle relation of :mod:`bearinglab.static` inverts by a
short Newton iteration that the paper prints row by row (sections 6.3 and 8).

Minimum stand load (spec 000 section 3)
---------------------------------------
min_axial_load               the printed criterion against gyroscopic slip, with the +20 % maximum
min_axial_load_gyroscopic    the same from its physical derivation (ball spin, cage speed, sliding friction)
StandLoad, MIN_LOAD_CONSTANT

Contact constants (spec 000 section 5)
--------------------------------------
stand_constants              curvature sums, cos(tau), Hertz coefficients, c_v, c_n and C*
StandConstants, PAPER_ELASTIC_CONSTANT

The elastic constant c_E comes from the bearing's materials by default,
c_E = (3/E')^(2/3)/2 (:func:`bearinglab.hertz.elastic_constant`), so that the method agrees with the rest
of the library for any ball and ring material; the source's printed steel value 0.592e-4 (cm^2/kgf)^(2/3)
is the option ``elastic_constant="paper"``, with which the worked example reproduces to the digit.

Operating contact angle (spec 000 section 6)
--------------------------------------------
series_coefficients          a0 ... a4 of the expansion of eq. (2)
operating_contact_angle      Newton on eq. (2) to tolerance, vectorized over loads and bearings (numpy, or
                             a compiled kernel in parallel over the cases: ``engine``)
engine_for                   the engine ``engine="auto"`` picks for a number of cases
iteration_table              the per-iteration table of the paper (k, x_k, angle, xi_a, F_a,k, Delta)
IterationRow

Analysis
--------
stand_analysis               every step of spec 000 for one bearing and load(s)
StandAnalysis

The static relations the method builds on (eq. (1) :func:`~bearinglab.static.thrust_from_angle`, eq. (3)
:func:`~bearinglab.static.first_approximation`, :func:`~bearinglab.static.axial_displacement_ratio`)
are in :mod:`bearinglab.static`.

References
----------
.. [1] V. A. Zaitsev and V. A. Voronkin, "Calculation of axial loads and operating contact angles of
   rolling bearings when assessing their quality on test stands," 2009 (spec 000 of this project).
.. [2] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, doi:10.1201/9781420006599.
"""

from __future__ import annotations

import math
import numbers
import warnings
from typing import NamedTuple

import numpy as np

from .. import _solve, geometry, hertz
from .._validate import check_integer, check_open_interval, check_positive, check_positive_finite
from ..bearing import STEEL
from ..errors import ConvergenceError, InputError
from ..units import CM, KGF, MM, RPM
from ._gap import _SQRT_HALF, _gap_step
from .static import _angle, axial_displacement_ratio, first_approximation, thrust_from_angle

__all__ = [
    "MIN_LOAD_CONSTANT",
    "PAPER_ELASTIC_CONSTANT",
    "IterationRow",
    "StandAnalysis",
    "StandConstants",
    "StandLoad",
    "constants_at_operating_angle",
    "engine_for",
    "iteration_table",
    "min_axial_load",
    "min_axial_load_gyroscopic",
    "operating_contact_angle",
    "series_coefficients",
    "stand_analysis",
    "stand_constants",
]

# (cm^2/kgf)^(2/3) -> (m^2/N)^(2/3): the unit of the approach coefficients c_v, c_n
_C_PAPER_UNIT = CM ** (4.0 / 3.0) / KGF ** (2.0 / 3.0)
# halvings of a Newton step that left (alpha0, 90 deg): 2000 take any finite step below any tolerance
# (2^-1075 x 1e308 is 0), so the loop ends whatever the step
_MAX_HALVINGS = 2000
#: The source's elastic constant 0.592e-4 (cm^2/kgf)^(2/3) in SI, (m^2/N)^(2/3); steel, E = 2.078e5 MPa,
#: nu = 0.3 (spec 000 section 5.3). It equals 2.7838e-4 (mm^2/N)^(2/3). Used only on request
#: (``elastic_constant="paper"``); the default is :func:`bearinglab.hertz.elastic_constant` of the materials.
PAPER_ELASTIC_CONSTANT = 0.592e-4 * _C_PAPER_UNIT
#: The constant of the printed minimum-load criterion, kgf with d, D0 in mm and n in rpm (spec 000 section 3).
MIN_LOAD_CONSTANT = 5.75e-12

# --------------------------------------------------------------------------- minimum stand load
class StandLoad(NamedTuple):
    """Axial load range of a bearing on a vibration test stand."""

    minimum: np.ndarray  # least load against gyroscopic slip [N]
    maximum: np.ndarray  # the paper's allowed maximum, 1.2 x minimum [N]


def min_axial_load(shaft_speed, n_balls, ball_diameter, pitch_diameter, contact_angle):
    r"""Least axial load that keeps the balls from gyroscopic slip on a test stand (spec 000 section 3).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speed. [rad/s]
    n_balls : array_like
        Number of balls z. [-]
    ball_diameter : array_like
        Ball diameter d. [m]
    pitch_diameter : array_like
        Pitch diameter D0. [m]
    contact_angle : array_like
        Contact angle, normally the free angle alpha0. [rad]

    Returns
    -------
    StandLoad
        ``minimum`` and the paper's allowed ``maximum`` (+20 %). [N]

    Notes
    -----
    The printed criterion, with d and D0 in mm, n in rpm and F in kgf:

    .. math:: F_a \ge 5.75\cdot10^{-12}\, z\, d^3 D_0\, n^2 \sin^2\alpha\,[1 - (d/D_0)^2\cos^2\alpha]

    It is 10 times the centrifugal force of a steel ball orbiting at half the shaft speed, the factor
    being 0.2/mu with a sliding friction coefficient mu = 0.02; see :func:`min_axial_load_gyroscopic`.

    Examples
    --------
    >>> import math
    >>> f = min_axial_load(3000 * math.pi / 30, 7, 2e-3, 8.7355e-3, math.radians(12))
    >>> print(f"{f.minimum / 9.80665:.3g} kgf")
    0.00104 kgf
    """
    n = np.abs(np.asarray(shaft_speed, dtype=float)) / RPM
    z = check_integer("n_balls", n_balls, 1)
    d = check_positive("ball_diameter", ball_diameter, "m") / MM
    dm = check_positive("pitch_diameter", pitch_diameter, "m") / MM
    a = check_open_interval("contact_angle", contact_angle, -1e-300, np.pi / 2, "deg", scale=180 / np.pi)
    f_kgf = MIN_LOAD_CONSTANT * z * d**3 * dm * n**2 * np.sin(a) ** 2 * (1.0 - (d / dm) ** 2 * np.cos(a) ** 2)
    f = f_kgf * KGF
    return StandLoad(f[()], (1.2 * f)[()])


def min_axial_load_gyroscopic(shaft_speed, n_balls, ball_diameter, pitch_diameter, contact_angle, *,
                              sliding_friction_coefficient=0.02, density=7850.0, friction_coefficient=None):
    r"""Least axial load against gyroscopic slip, from its physical derivation (spec 000 section 3).

    Parameters
    ----------
    shaft_speed : array_like
        Inner-ring speed omega. [rad/s]
    n_balls : array_like
        Number of balls z. [-]
    ball_diameter : array_like
        Ball diameter d. [m]
    pitch_diameter : array_like
        Pitch diameter D0. [m]
    contact_angle : array_like
        Contact angle alpha. [rad]
    sliding_friction_coefficient : float, optional
        Ball-race sliding friction coefficient mu that resists the gyroscopic spin (0.02 in the source).
        [-]
    density : float, optional
        Ball density (steel 7850). [kg/m^3]
    friction_coefficient : float, optional
        Deprecated name of ``sliding_friction_coefficient`` (warns with DeprecationWarning). [-]

    Returns
    -------
    ndarray
        The least axial load. [N]

    Notes
    -----
    Ball spin omega_B = (D0/(2d)) omega (1 - gamma^2), cage speed omega/2 (the (1 - gamma) factor is
    dropped, which is conservative), J = m d^2/10, M_g = J omega_B (omega/2) sin alpha, resisted while
    M_g <= mu P d with P = F_a/(z sin alpha):
    :math:`F_a = (0.2/\mu)\, z \sin^2\alpha\,(1-\gamma^2)\, m (D_0/2)(\omega/2)^2`.
    Agrees with :func:`min_axial_load` to 0.08 % for steel (the rounding of 5.75).
    """
    w = np.abs(np.asarray(shaft_speed, dtype=float))
    z = check_integer("n_balls", n_balls, 1)
    d = check_positive("ball_diameter", ball_diameter, "m")
    dm = check_positive("pitch_diameter", pitch_diameter, "m")
    if friction_coefficient is not None:
        warnings.warn("min_axial_load_gyroscopic(friction_coefficient=...) is deprecated, use "
                      "sliding_friction_coefficient=...", DeprecationWarning, stacklevel=2)
        sliding_friction_coefficient = friction_coefficient
    mu = check_positive("sliding_friction_coefficient", sliding_friction_coefficient, "-")
    rho = check_positive("density", density, "kg/m^3")
    a = np.asarray(contact_angle, dtype=float)
    gamma = d * np.cos(a) / dm
    mass = rho * np.pi * d**3 / 6.0
    centrifugal = mass * (dm / 2.0) * (w / 2.0) ** 2
    return ((0.2 / mu) * z * np.sin(a) ** 2 * (1.0 - gamma**2) * centrifugal)[()]


# --------------------------------------------------------------------------- contact constants
class StandConstants(NamedTuple):
    """Contact constants of spec 000 section 5 (SI; the paper's kgf-cm values are ``*_paper``)."""

    gamma: np.ndarray  # D cos(a0)/d_m [-]
    curvature_sum_inner: np.ndarray  # [1/m]
    curvature_sum_outer: np.ndarray  # [1/m]
    curvature_difference_inner: np.ndarray  # cos(tau_v) [-]
    curvature_difference_outer: np.ndarray  # cos(tau_n) [-]
    hertz_inner: hertz.HertzCoefficients
    hertz_outer: hertz.HertzCoefficients
    approach_inner: np.ndarray  # c_v [(m^2/N)^(2/3)]
    approach_outer: np.ndarray  # c_n [(m^2/N)^(2/3)]
    force_characteristic: np.ndarray  # C* [N]
    elastic_constant: float  # c_E used for c_v, c_n [(m^2/N)^(2/3)]

    @property
    def approach_inner_paper(self):
        """c_v in the paper's unit (cm^2/kgf)^(2/3)."""
        return self.approach_inner / _C_PAPER_UNIT

    @property
    def approach_outer_paper(self):
        """c_n in the paper's unit (cm^2/kgf)^(2/3)."""
        return self.approach_outer / _C_PAPER_UNIT

    @property
    def elastic_constant_paper(self):
        """c_E in the paper's unit (cm^2/kgf)^(2/3)."""
        return self.elastic_constant / _C_PAPER_UNIT

    @property
    def force_characteristic_kgf(self):
        """C* in kgf, the paper's unit."""
        return self.force_characteristic / KGF


def _elastic_constant(choice, ball_material, ring_material):
    """c_E from the option: None or "materials" (the pair's E'), "paper", or a number [(m^2/N)^(2/3)]."""
    if choice is None or (isinstance(choice, str) and choice == "materials"):
        ep = hertz.reduced_modulus(ball_material.elastic_modulus, ball_material.poisson_ratio,
                                   ring_material.elastic_modulus, ring_material.poisson_ratio)
        return float(hertz.elastic_constant(ep))
    if isinstance(choice, str) and choice == "paper":
        return PAPER_ELASTIC_CONSTANT
    if isinstance(choice, (str, bool)) or not isinstance(choice, numbers.Real):
        raise InputError(f"elastic_constant must be 'materials', 'paper' or a number [(m^2/N)^(2/3)], got {choice!r}")
    return float(check_positive("elastic_constant", choice, "(m^2/N)^(2/3)"))


def stand_constants(n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity, free_angle, *,
                    delta_star_inner=None, delta_star_outer=None, elastic_constant=None):
    r"""Curvatures, Hertz coefficients, approach coefficients and force characteristic (spec 000 section 5).

    Parameters
    ----------
    n_balls : array_like
        Number of balls z. [-]
    ball_diameter : array_like
        Ball diameter d. [m]
    pitch_diameter : array_like
        Pitch diameter d_m. [m]
    inner_conformity, outer_conformity : array_like
        xi_v = r_v/d and xi_n = r_n/d, each > 0.5. [-]
    free_angle : array_like
        Free contact angle alpha0, in (0, 90 deg). [rad]
    delta_star_inner, delta_star_outer : array_like, optional
        Tabulated 2K/(pi mu) to use instead of the exact values (the paper's 0.63 and 0.852). [-]
    elastic_constant : float or "paper", optional
        c_E of c = c_E 2K/(pi mu) (d Sigma rho)^(1/3). Default None: the library's steel balls and rings
        (:data:`bearinglab.bearing.STEEL`), c_E = (3/E')^(2/3)/2; "paper": the source's printed 0.592e-4
        (cm^2/kgf)^(2/3) (:data:`PAPER_ELASTIC_CONSTANT`); or a number, e.g.
        ``hertz.elastic_constant(E')`` for other materials. [(m^2/N)^(2/3)]

    Returns
    -------
    StandConstants
        gamma, Sigma rho and cos(tau) per contact, Hertz coefficients, c_v, c_n and C* [N].

    Notes
    -----
    Spec 000 eqs. of section 5.1 (corrected sign pattern, evaluated from d_m, not from the catalogue
    T), section 5.2 (exact coefficients) and section 5.3:

    .. math::
        c_j = c_E\,(2K/\pi\mu)_j\,\sqrt[3]{d\,\Sigma\rho_j},\qquad
        C^* = \left(\frac{\xi}{c_n + c_v}\right)^{3/2} z\, d^2

    In the paper's units C* needs d in centimetres (7792 kgf for the example); in SI it is in newtons.

    Examples
    --------
    >>> import math
    >>> c = stand_constants(7, 2e-3, 8.7355e-3, 0.525, 0.58, math.radians(12),
    ...                     delta_star_inner=0.63, delta_star_outer=0.852, elastic_constant="paper")
    >>> print(f"{c.force_characteristic_kgf:.2f} kgf, c_n = {c.approach_outer_paper:.4e}")
    7792.36 kgf, c_n = 6.2580e-05
    """
    z = check_integer("n_balls", n_balls, 1)
    d = check_positive("ball_diameter", ball_diameter, "m")
    a0 = _angle("free_angle", free_angle)
    ce = _elastic_constant(elastic_constant, STEEL, STEEL)
    inner = geometry.raceway_curvature(d, pitch_diameter, inner_conformity, a0, race="inner")
    outer = geometry.raceway_curvature(d, pitch_diameter, outer_conformity, a0, race="outer")
    h_in = hertz.coefficients(inner.curvature_difference) if delta_star_inner is None else hertz.tabulated(delta_star_inner)
    h_out = hertz.coefficients(outer.curvature_difference) if delta_star_outer is None else hertz.tabulated(delta_star_outer)
    c_v = ce * np.asarray(h_in.delta_star) * np.cbrt(d * inner.curvature_sum)
    c_n = ce * np.asarray(h_out.delta_star) * np.cbrt(d * outer.curvature_sum)
    b = geometry.total_curvature(inner_conformity, outer_conformity)
    c_star = (b / (c_n + c_v)) ** 1.5 * z * d**2
    gamma = d * np.cos(a0) / np.asarray(pitch_diameter, dtype=float)
    return StandConstants(gamma[()], inner.curvature_sum, outer.curvature_sum, inner.curvature_difference,
                          outer.curvature_difference, h_in, h_out, c_v[()], c_n[()], np.asarray(c_star)[()],
                          float(ce))


# --------------------------------------------------------------------------- operating angle

def series_coefficients(thrust_ratio, free_angle):
    r"""Coefficients a0 ... a4 of the Taylor expansion of eq. (2) in x = alpha - alpha0 (spec 000 section 6.2).

    Parameters
    ----------
    thrust_ratio : array_like
        F_a / C*. [-]
    free_angle : array_like
        Free contact angle alpha0. [rad]

    Returns
    -------
    ndarray
        Shape ``(5,) + broadcast shape``: a0, a1, a2, a3, a4. [-]

    Notes
    -----
    With s = sin alpha0, t = tan alpha0 and sec = 1/cos alpha0 (the printed coefficients, verified):
    a0 = -(F_a/C*)^(2/3), a1 = s^(2/3) t, a2 = s^(2/3)(6 + cos^2 alpha0)/(6 cos^2 alpha0),
    a3 = (1/9) s^(2/3)(1.5 t + 2 cot alpha0 + 9 sec^2 t),
    a4 = (1/9) s^(2/3)[(4/9 - sec^2 + sec^4/2) cot^2 + 4.375 sec^4 + 4.25 sec^2 t^2 + 0.375 t^4].

    Examples
    --------
    >>> import math
    >>> print(np.round(series_coefficients(2 / 7792.357, math.radians(12)), 7))
    [-0.0040387  0.074598   0.4253049  0.4573164  0.1471544]
    """
    t_ratio = check_positive("thrust_ratio", thrust_ratio, "-")
    a0 = _angle("free_angle", free_angle)
    s23 = np.sin(a0) ** (2.0 / 3.0)
    t = np.tan(a0)
    sec2 = 1.0 / np.cos(a0) ** 2
    cot = 1.0 / t
    c0 = -(t_ratio ** (2.0 / 3.0))
    c1 = s23 * t
    c2 = s23 * (6.0 + np.cos(a0) ** 2) / (6.0 * np.cos(a0) ** 2)
    c3 = s23 / 9.0 * (1.5 * t + 2.0 * cot + 9.0 * sec2 * t)
    c4 = s23 / 9.0 * ((4.0 / 9.0 - sec2 + 0.5 * sec2**2) * cot**2 + 4.375 * sec2**2 + 4.25 * sec2 * t**2 + 0.375 * t**4)
    return np.stack(np.broadcast_arrays(c0, c1, c2, c3, c4))


def _newton_step(axial_load, thrust, alpha, free_angle):
    """Newton increment of spec 000 section 6.3 (exact Newton for (F/F_a)^(2/3) - 1 = 0)."""
    gap = np.cos(free_angle) - np.cos(alpha)
    slope = np.tan(alpha) + (2.0 / 3.0) / np.tan(alpha) + np.sin(alpha) / gap
    return ((axial_load / thrust) ** (2.0 / 3.0) - 1.0) / slope


def operating_contact_angle(axial_load, force_characteristic, free_angle, *, xtol=_solve.AXIAL_ANGLE_XTOL,
                            ftol_percent=_solve.AXIAL_ANGLE_FTOL_PERCENT, max_iter=_solve.AXIAL_ANGLE_MAX_ITER,
                            engine="auto"):
    r"""Operating contact angle under a pure axial load (spec 000 section 6): the Newton of section 6.3.

    Parameters
    ----------
    axial_load : array_like
        F_a > 0. [N]
    force_characteristic : array_like
        C* > 0 (see :func:`stand_constants`). [N]
    free_angle : array_like
        alpha0, in (0, 90 deg). [rad]
    xtol : float, optional
        Converged where abs(Delta x) < xtol. [rad]
    ftol_percent : float, optional
        ... or where abs(F_a,k - F_a) / F_a < ftol_percent. [%]
    max_iter : int, optional
        Iteration limit (Newton steps of section 6.3 after the start).
    engine : {"auto", "numpy", "compiled"}, optional
        "numpy": the batched numpy path; "compiled": the same operations case by case in a numba kernel,
        parallel over the cases (needs numba); "auto" (default): the compiled kernel when numba is
        installed and the call has at least ``_solve.AXIAL_ANGLE_COMPILED_CASES`` (10^6) cases (the
        size of the broadcast inputs), else numpy. The choice depends on this call alone, never on what
        ran before in the process: loading numba and the kernel costs about half a second, so a smaller
        batch, and a one-case call, does not import numba. Each engine gives the same bits for a case in
        any batch, chunk or executor. Across engines the angles agree to 4 ulp with the default
        tolerances (the answer is the start, which passes the load test; the engines' libraries may
        round a sine or an arc cosine differently, e.g. numpy's SIMD functions on AVX-512 hosts) and
        to ``xtol`` where the Newton of section 6.3 runs; a case converges on both.

    Returns
    -------
    ndarray
        The operating contact angle alpha in (alpha0, 90 deg), broadcast over the inputs. [rad]

    Raises
    ------
    ConvergenceError
        If some element has not converged in ``max_iter`` iterations or left (alpha0, 90 deg).

    Notes
    -----
    Newton on eq. (2), :math:`f(x) = [\cos\alpha_0/\cos(\alpha_0+x) - 1]\sin^{2/3}(\alpha_0+x) - (F_a/C^*)^{2/3}`,
    with the increment (the paper prints it as "x_k =", it is Delta x_k)

    .. math:: \Delta x_k = \frac{(F_a/F_{a,k})^{2/3} - 1}{\tan\alpha_k + \tfrac23\cot\alpha_k + \sin\alpha_k/(\cos\alpha_0 - \cos\alpha_k)}

    and the convergence test of section 6.3 (``xtol``, ``ftol_percent``). The start is not the paper's x0
    of eq. (3) (:func:`~bearinglab.static.first_approximation`, which the iteration table keeps) but the
    root of eq. (1) squared, a polynomial in the gap y = cos alpha0 - cos alpha that needs no
    trigonometric function (:func:`_gap_start`). As in the paper's table, the load test of section 6.3 is
    made at the start first: where it holds (for every load tried, the start being the root to the last
    digits) the start is the answer and no Newton step is taken; elsewhere the Newton of section 6.3
    runs from it. Each case stops on its own convergence, so with one engine its angle does not depend
    on the batch or the chunk it is solved in (the numpy path evaluates the cases in blocks that fit the
    CPU cache).

    Examples
    --------
    >>> import math
    >>> a = operating_contact_angle(2 * 9.80665, 7792.357 * 9.80665, math.radians(12))
    >>> print(f"{math.degrees(a):.6f} deg")
    14.467605 deg
    """
    fa = check_positive("axial_load", axial_load, "N")
    cs = check_positive("force_characteristic", force_characteristic, "N")
    a0 = _angle("free_angle", free_angle)
    shape = np.broadcast_shapes(fa.shape, cs.shape, a0.shape)
    n = math.prod(shape)
    compiled = _compiled_engine(engine, n)
    # flat inputs; a single value (one bearing) stays a scalar, so that its sine and cosine are taken once
    flat = [x.reshape(()) if x.size == 1 else np.broadcast_to(x, shape).ravel() for x in (fa, cs, a0)]
    if compiled:
        from . import (
            _compiled as _stand_compiled,  # imports numba: only when the compiled path runs
        )

        alpha, iterations, residual, n_bad = _stand_compiled.solve(*flat, n, xtol, ftol_percent, max_iter)
        ok = iterations >= 0 if n_bad else np.ones(1, dtype=bool)
    else:
        alpha, residual = np.empty(n), np.empty(n)
        ok = np.empty(n, dtype=bool)
        block = _solve.AXIAL_ANGLE_BLOCK
        for lo in range(0, n, block):  # a loop over blocks of cases, not over cases: the arrays stay in cache
            part = [x if x.ndim == 0 else x[lo:lo + block] for x in flat]
            alpha[lo:lo + block], ok[lo:lo + block], residual[lo:lo + block] = _newton(
                *part, min(block, n - lo), xtol, ftol_percent, max_iter)
    if not ok.all():
        raise ConvergenceError("stand.operating_contact_angle", iterations=max_iter,
                               residual=residual.reshape(shape)[()], estimate=alpha.reshape(shape)[()],
                               reason="the angle did not settle in (alpha0, 90 deg)")
    return alpha.reshape(shape)[()]


def _compiled_engine(engine, n):
    """True if the compiled kernel solves ``n`` cases: engine "compiled"; or "auto" with numba installed and
    at least ``_solve.AXIAL_ANGLE_COMPILED_CASES`` cases (loading numba and the kernel costs about 0.5 s).
    The call alone decides: a kernel loaded earlier in the process does not change the choice, so the same
    call gives the same bits wherever it runs."""
    return _solve.use_compiled(engine, auto=n >= _solve.AXIAL_ANGLE_COMPILED_CASES)


def engine_for(n_cases):
    """The engine that ``engine="auto"`` picks for ``n_cases`` cases: "compiled" or "numpy".

    A caller that splits one study into batches (a sweep in chunks) resolves the engine once, for the whole
    study, and passes it to every batch, so that the chunk size does not choose the engine.

    Parameters
    ----------
    n_cases : int
        Number of cases of the whole study. [-]

    Returns
    -------
    str
        "compiled" (numba installed and at least ``_solve.AXIAL_ANGLE_COMPILED_CASES`` cases) or "numpy".

    Examples
    --------
    >>> engine_for(1)
    'numpy'
    """
    n_cases = int(check_integer("n_cases", n_cases, 0))
    return "compiled" if _compiled_engine("auto", n_cases) else "numpy"


def _gap_start(thrust_ratio, cos_a0, sin_a0, n, *, rtol=_solve.AXIAL_ANGLE_START_RTOL,
               max_iter=_solve.AXIAL_ANGLE_START_MAX_ITER):
    r"""Start of the Newton of section 6.3: the gap y = cos alpha0 - cos alpha at the root of eq. (1) squared.

    With u = cos alpha, y = cos alpha0 - u and T = F_a/C*, eq. (1) squared is T^2 u^3 = (c0 - u)^3 (1 - u^2),

    .. math:: P(y) = y^3 (\sin^2\alpha_0 + 2 y\cos\alpha_0 - y^2) - T^2 (\cos\alpha_0 - y)^3 = 0,

    with P(0) < 0 < P(cos alpha0) and P', P'' > 0 on (0, cos alpha0]. Halley's iteration (:func:`_gap_step`,
    cubic convergence, arithmetic only) starts from the smaller of the roots of the two leading-order
    truncations, sin^2 alpha0 y^3 = T^2 cos^3 alpha0 (small loads, a cube root, taken only where it is the
    smaller: their cubes are compared) and 2 cos alpha0 y^4 = T^2 cos^3 alpha0 (small free angles, a square
    root), both above the root; each case stops after a step below ``rtol`` times the gap (the error left is
    then of order rtol^3, below the rounding of y). Two or three steps for ordinary loads. Returns y for
    ``n`` cases.
    """
    s2 = sin_a0 * sin_a0
    tt = thrust_ratio * thrust_ratio
    q = tt / s2
    arg = thrust_ratio * (cos_a0 * _SQRT_HALF)
    small_angle = np.sqrt(arg)  # the root of 2 cos(alpha0) y^4 = T^2 cos^3(alpha0)
    # the root of sin^2(alpha0) y^3 = T^2 cos^3(alpha0), a cube root, is taken only where it is the smaller
    small_load = cos_a0 * cos_a0 * cos_a0 * q < small_angle * arg  # compared as cubes
    root = np.cbrt(q, out=np.array(small_angle, dtype=float), where=small_load)
    y = np.where(small_load, cos_a0 * root, small_angle)
    y = np.array(np.broadcast_to(np.minimum(y, cos_a0), (n,)))
    live = np.ones(n, dtype=bool)
    for _ in range(max_iter):
        dy = _gap_step(y, cos_a0, s2, tt)
        y = np.where(live, y - dy, y)
        live &= np.abs(dy) > rtol * y
        if not live.any():
            break
    return y


def _start_test(thrust_ratio, y, cos_a0, sin2_a0):
    """F_a / F_a,k of eq. (1) at the gap y, with cos alpha = cos alpha0 - y and sin^2 alpha = 1 - cos^2 alpha
    written without cancellation: T / (q sqrt(q sin^2 alpha)), q = y / cos alpha = cos alpha0/cos alpha - 1;
    returns (F_a / F_a,k, cos alpha, sin^2 alpha)."""
    u = cos_a0 - y
    w = sin2_a0 + (2.0 * cos_a0 - y) * y
    with np.errstate(divide="ignore", invalid="ignore"):  # y = cos alpha0 (90 deg): the test fails, no warning
        q = y / u
        return thrust_ratio / (q * np.sqrt(q * w)), u, w


def _angle_of(u, w):
    """alpha from cos alpha = u and sin^2 alpha = w: arcsin(sqrt(w)) below 45 deg, where arccos(u) would lose
    digits (its slope is 1/sin alpha), arccos(u) above; one inverse function per case."""
    small = u > _SQRT_HALF
    alpha = np.arccos(u, out=np.empty(np.shape(u)), where=~small)
    return np.arcsin(np.sqrt(w), out=alpha, where=small)


def _newton(fa, cs, a0, n, xtol, ftol_percent, max_iter):
    """The solve of ``n`` cases: the start (:func:`_gap_start`), its load test, and for a case that fails it
    the Newton of section 6.3; (alpha, converged, 1/ratio - 1)."""
    cos_a0, sin_a0 = np.cos(a0), np.sin(a0)  # one sine and cosine per bearing, not per case
    t = fa / cs
    y = _gap_start(t, cos_a0, sin_a0, n)
    ratio, u, w = _start_test(t, y, cos_a0, sin_a0 * sin_a0)
    alpha = _angle_of(u, w)
    live = ~(np.abs(ratio - 1.0) * 100.0 < ftol_percent)  # the load test of section 6.3 at the start
    if not live.any():
        return alpha, ~live, np.zeros(n)
    # the cases that fail it (none among the loads tried) take the Newton of section 6.3, each on its own
    idx = np.flatnonzero(live)
    a = alpha[idx]
    part = [x if np.ndim(x) == 0 else x[idx] for x in (fa, cs, a0, cos_a0)]
    a, ok, res = _section_newton(*part, np.where(a < np.pi / 2, a, 0.5 * (part[2] + np.pi / 2)), xtol,
                                 ftol_percent, max_iter)
    alpha[idx] = a
    residual = np.zeros(n)
    residual[idx] = res
    return alpha, ~live | _scatter(live, ok), residual


def _scatter(mask, values):
    out = np.zeros(mask.shape, dtype=bool)
    out[mask] = values
    return out


def _section_newton(fa, cs, a0, cos_a0, alpha, xtol, ftol_percent, max_iter):
    """The Newton of section 6.3 from ``alpha``: (alpha, converged, 1/ratio - 1 of the last step, 0 where
    converged)."""
    # A converged case is frozen (its step set to zero) while the others go on, so that each case takes
    # exactly the steps it would take alone: the result does not depend on the batch or chunk it sits in.
    live = np.ones(alpha.shape, dtype=bool)
    ratio = np.full(alpha.shape, np.nan)  # max_iter = 0: nothing converged, no residual
    for _ in range(max_iter):
        ca, sa = np.cos(alpha), np.sin(alpha)
        gap = cos_a0 - ca
        c = gap / ca
        ratio = fa / (cs * c * np.sqrt(c) * sa)  # F_a / F_a,k, eq. (1)
        tan = sa / ca
        dx = np.where(live, (np.cbrt(ratio * ratio) - 1.0) / (tan + (2.0 / 3.0) / tan + sa / gap), 0.0)
        new = alpha + dx
        # stay inside (alpha0, 90 deg): a step out of the domain is halved toward the boundary
        new = np.where(new <= a0, 0.5 * (alpha + a0), new)
        alpha = np.where(new >= np.pi / 2, 0.5 * (alpha + np.pi / 2), new)
        live &= ~((np.abs(dx) < xtol) | (np.abs(ratio - 1.0) * 100.0 < ftol_percent))
        if not live.any():
            return alpha, ~live, np.zeros(alpha.shape)
    return alpha, ~live, np.where(live, 1.0 / ratio - 1.0, 0.0)  # a converged case has no residual


class IterationRow(NamedTuple):
    """One row of the paper's iteration table (spec 000 section 8)."""

    k: int
    x: float  # x_k [rad]
    contact_angle: float  # alpha0 + x_k [rad] (the pi = 3.14, truncated-seconds angle in legacy mode)
    axial_displacement_ratio: float  # xi_a [-]
    axial_load: float  # F_a,k [N]
    error_percent: float  # Delta_k = (F_a,k - F_a)/F_a [%]


def _legacy_angle(free_angle, x):
    """alpha0 + x converted to degrees with pi = 3.14 (spec 000 section 9.9); the paper prints it with
    the seconds truncated (``units.to_dms(..., truncate=True)``) but evaluates xi_a and F at it unrounded."""
    return math.radians(math.degrees(free_angle) + x * 180.0 / 3.14)


def iteration_table(axial_load, force_characteristic, free_angle, *, x0=None, reproduce_print=False,
                    xtol=_solve.AXIAL_ANGLE_XTOL, ftol_percent=_solve.AXIAL_ANGLE_FTOL_PERCENT,
                    max_iter=_solve.AXIAL_ANGLE_MAX_ITER, max_rows=None):
    r"""The paper's iteration table for one bearing and load (spec 000 sections 6.3 and 8).

    Parameters
    ----------
    axial_load : float
        F_a. [N]
    force_characteristic : float
        C*. [N]
    free_angle : float
        alpha0. [rad]
    x0 : float, optional
        Start instead of :func:`first_approximation` (the paper's printed 0.0433985). [rad]
    reproduce_print : bool, optional
        Legacy mode: angles from x with pi = 3.14 and truncated seconds, F cut to three kgf decimals
        in the Newton step, as the paper computed (spec 000 section 8).
    xtol : float, optional
        Converged where abs(Delta x) < xtol. [rad]
    ftol_percent : float, optional
        ... or where abs(Delta_k) < ftol_percent. [%]
    max_iter : int, optional
        Iteration limit.
    max_rows : int, optional
        Stop after this many rows (the paper prints two); ``None`` iterates to convergence.

    Returns
    -------
    list of IterationRow
        k, x_k, alpha_k, xi_a, F_a,k [N], Delta_k [%]; the last row is the converged one unless
        ``max_rows`` stopped it first.

    Raises
    ------
    ConvergenceError
        If the tolerance is not met within ``max_iter`` rows (and ``max_rows`` is None).
    """
    fa = float(check_positive_finite("axial_load", axial_load, "N"))
    cs = float(check_positive_finite("force_characteristic", force_characteristic, "N"))
    a0 = float(_angle("free_angle", free_angle))
    if x0 is None:  # eq. (3) can overshoot 90 deg at absurd loads: start half-way there at most
        x = min(float(first_approximation(fa / cs, a0)), 0.5 * (math.pi / 2 - a0))
    else:
        x = float(x0)
        if not 0.0 < x < math.pi / 2 - a0:
            raise InputError(f"x0 must be in (0, {math.pi / 2 - a0:.6g}) [rad] (the start alpha0 + x0 between the "
                             f"free angle and 90 deg), got {x0!r}")
    if max_rows is not None and not (isinstance(max_rows, int) and max_rows >= 1):
        raise InputError(f"max_rows must be an integer >= 1 [-], got {max_rows!r}")
    if reproduce_print and fa < 0.001 * KGF:  # the paper's F cut to three kgf decimals would be 0
        raise InputError(f"axial_load must be >= 0.001 kgf = {0.001 * KGF:g} [N] to reproduce the paper's rounding "
                         f"(F cut to three kgf decimals), got {fa:g} N")
    rows = []
    limit = max_iter if max_rows is None else max_rows
    settled = False  # the previous step was below xtol: this row is the converged one
    for k in range(limit):
        alpha = _legacy_angle(a0, x) if reproduce_print else a0 + x
        if not a0 < alpha < math.pi / 2:
            raise ConvergenceError("stand.iteration_table", iterations=k, residual=float("nan"), estimate=alpha,
                                   reason="the angle left (alpha0, 90 deg)")
        thrust = float(thrust_from_angle(alpha, cs, a0))
        # legacy: the paper steps with F cut to three kgf decimals (2.02994 -> 2.029, spec 000 section 9.12)
        step_thrust = math.floor(thrust / KGF * 1000.0) / 1000.0 * KGF if reproduce_print else thrust
        error = (step_thrust - fa) / fa * 100.0
        rows.append(IterationRow(k, x, alpha, float(axial_displacement_ratio(alpha, a0)), thrust, error))
        if max_rows is None and (settled or abs(error) < ftol_percent):
            return rows
        if not step_thrust > 0:  # legacy: a thrust below 0.001 kgf at this angle is cut to 0
            raise ConvergenceError("stand.iteration_table", iterations=k, residual=error / 100, estimate=alpha,
                                   reason="the paper's rounding cut the thrust at this angle to 0 kgf")
        dx = float(_newton_step(fa, step_thrust, alpha, a0))
        for _halving in range(_MAX_HALVINGS):  # keep the iterate in (alpha0, 90 deg); a bounded loop
            if a0 < a0 + x + dx < math.pi / 2 or not abs(dx) > xtol:
                break
            dx *= 0.5
        settled = abs(dx) < xtol
        x += dx
    if max_rows is None:
        raise ConvergenceError("stand.iteration_table", iterations=limit, residual=rows[-1].error_percent / 100,
                               estimate=rows[-1].contact_angle)
    return rows


# --------------------------------------------------------------------------- analysis
def constants_at_operating_angle(axial_load, n_balls, ball_diameter, pitch_diameter, inner_conformity,
                                 outer_conformity, free_angle, *, elastic_constant=None,
                                 xtol=_solve.AXIAL_ANGLE_XTOL, max_iter=_solve.AXIAL_ANGLE_MAX_ITER,
                                 engine="auto"):
    r"""Exact-Hertz contact constants evaluated at the operating angle they produce, and that angle.

    Parameters
    ----------
    axial_load : array_like
        F_a > 0. [N]
    n_balls : array_like
        Number of balls z. [-]
    ball_diameter : array_like
        Ball diameter d. [m]
    pitch_diameter : array_like
        Pitch diameter d_m. [m]
    inner_conformity, outer_conformity : array_like
        xi_v, xi_n, each > 0.5. [-]
    free_angle : array_like
        Free contact angle alpha0, in (0, 90 deg). [rad]
    elastic_constant : float or "paper", optional
        As in :func:`stand_constants`. [(m^2/N)^(2/3)]
    xtol : float, optional
        Change of the angle between two passes below which it is converged. [rad]
    max_iter : int, optional
        Passes at most. [-]
    engine : {"auto", "numpy", "compiled"}, optional
        The engine of every :func:`operating_contact_angle` solve (the same rule for "auto").

    Returns
    -------
    tuple of (StandConstants, ndarray)
        The constants at the operating angle (arrays over the loads) and the operating angle [rad].

    Raises
    ------
    ConvergenceError
        The fixed point did not settle within ``max_iter`` passes.

    Notes
    -----
    Spec 000 holds the curvature sums, and with them C*, at the free angle alpha0 (section 5). The
    exact static solution evaluates them at the loaded angle, as the high-speed model does at zero
    speed (spec 004 section 5.3) and as :func:`bearinglab.static.contact_angle_under_thrust` does.
    Here the spec-000 relation eq. (2) is solved with C*(alpha) by a fixed point: alpha_{k+1} solves
    eq. (2) with C*(alpha_k). C* changes little with the angle (6e-5 deg of angle for B218 at 20 kN),
    so the map contracts strongly and three or four passes reach 1e-12 rad. At the fixed point the
    spec-000 Newton with this C* converges to the same angle, so the iteration table and the
    operating angle agree.

    Examples
    --------
    >>> import math
    >>> from bearinglab import catalog, hertz
    >>> b = catalog.get("B218")
    >>> c, a = constants_at_operating_angle(20e3, b.n_balls, b.ball_diameter, b.pitch_diameter,
    ...     b.inner_conformity, b.outer_conformity, b.contact_angle,
    ...     elastic_constant=hertz.elastic_constant(b.reduced_modulus))
    >>> print(f"{math.degrees(a):.6f} deg")
    41.608640 deg
    """
    fa = check_positive("axial_load", axial_load, "N")
    a0 = _angle("free_angle", free_angle)
    args = (n_balls, ball_diameter, pitch_diameter, inner_conformity, outer_conformity)
    alpha = operating_contact_angle(fa, stand_constants(*args, a0, elastic_constant=elastic_constant)
                                    .force_characteristic, a0, engine=engine)
    # Each case stops at its own fixed point (converged cases are frozen, constants and angle), so a case's
    # result does not depend on the batch or chunk it is solved in.
    live = np.ones(np.shape(alpha), dtype=bool)
    final = None
    step = np.inf
    for it in range(1, int(max_iter) + 1):
        consts = stand_constants(*args, alpha, elastic_constant=elastic_constant)
        new = operating_contact_angle(fa, consts.force_characteristic, a0, engine=engine)
        moved = np.abs(new - alpha)
        step = np.max(np.where(live, moved, 0.0), initial=0.0)
        if final is None:
            final = consts
        else:  # frozen cases keep the constants of the iteration they converged in
            final = _keep_frozen(live, consts, final)
        alpha = np.where(live, new, alpha)
        live &= moved > xtol
        if not live.any():
            return final, alpha[()]
    raise ConvergenceError("operating contact angle with the stiffness at the loaded angle", iterations=it,
                           residual=step, estimate=alpha)


def _keep_frozen(live, new, old):
    """``new`` where ``live``, else ``old``, field by field through nested named tuples; a 0-d field of a
    batch does not depend on the case (it is the same in both) and keeps its shape."""
    if isinstance(new, tuple):
        return type(new)(*(_keep_frozen(live, a, b) for a, b in zip(new, old)))
    if np.ndim(new) == 0 and np.ndim(live) > 0:
        return new
    return np.where(live, new, old)[()]


class StandAnalysis(NamedTuple):
    """Every step of spec 000 for one bearing at one axial load (or an array of loads)."""

    axial_load: np.ndarray  # F_a [N]
    free_angle: float  # alpha0 [rad]
    constants: StandConstants
    series: np.ndarray  # a0..a4 [-]
    first_approximation: np.ndarray  # x0 [rad]
    contact_angle: np.ndarray  # converged operating angle [rad]
    axial_displacement_ratio: np.ndarray  # xi_a [-]
    axial_displacement: np.ndarray  # delta_a [m]
    ball_load: np.ndarray  # P = F_a/(z sin alpha) [N]
    iterations: list  # IterationRow list (scalar load only; empty for arrays)
    hertz: str  # "exact" or "table"


def stand_analysis(bearing, axial_load, *, hertz="exact", elastic_constant=None, stiffness_at=None,
                   reproduce_print=False, x0=None, max_rows=None):
    """Run every step of the test-stand method for a bearing (spec 000 sections 4-8).

    Parameters
    ----------
    bearing : BallBearing
        Needs n_balls, ball_diameter, pitch_diameter, both conformities and a contact angle in (0, 90 deg)
        (or a radial clearance that gives one).
    axial_load : array_like
        F_a > 0. [N]
    hertz : {"exact", "table"}, optional
        Exact Hertz coefficients (default) or the bearing's tabulated ones (``bearing.hertz_table``).
    elastic_constant : {None, "materials", "paper"} or float, optional
        c_E of spec 000 section 5.3. None or "materials" (default): from the bearing's ball and ring
        materials, c_E = (3/E')^(2/3)/2 (:func:`bearinglab.hertz.elastic_constant`), with which C* is
        exactly Z K_n (B D)^1.5 of the library's exact Hertz stiffness at alpha0; "paper": the source's
        printed 0.592e-4 (cm^2/kgf)^(2/3) for steel (:data:`PAPER_ELASTIC_CONSTANT`), to reproduce
        its worked example; or a number. [(m^2/N)^(2/3)]
    stiffness_at : {None, "operating", "free"}, optional
        Angle at which the curvature sums, and with them C*, are evaluated. "free": at alpha0, as
        spec 000 does; "operating": at the loaded angle (:func:`constants_at_operating_angle`), the
        exact static solution that the high-speed model gives at zero speed and the combined-load
        model gives under pure thrust. Default: "operating" with exact Hertz, "free" with the
        tabulated coefficients (the paper's method).
    reproduce_print : bool, optional
        Legacy mode of the iteration table (spec 000 section 8).
    x0 : float, optional
        Start of the iteration table instead of eq. (3). [rad]
    max_rows : int, optional
        Rows of the iteration table (``None``: to convergence).

    Returns
    -------
    StandAnalysis

    Notes
    -----
    Spec 000 holds the contact stiffness at the free angle alpha0 (C*, section 5); with
    ``stiffness_at="free"`` and the default elastic constant the angle is
    ``static.contact_angle_under_thrust(..., stiffness_at="free")`` to the solver tolerance. The
    default with exact Hertz evaluates C* at the loaded angle instead, so that one bearing under one
    thrust has one operating angle in the whole library: the high-speed model at zero speed
    (:func:`bearinglab.quasistatic.high_speed_analysis`, spec 004 section 5.3) gives the same angle to
    1e-9 deg. The two choices differ by the change of the raceway curvature sums between alpha0 and
    alpha: 6.06e-5 deg for B218 at 20 kN (41.608701 deg at alpha0, 41.608640 deg at alpha). The
    source's printed constant (``elastic_constant="paper"``) moves the angle by a further 1.5e-3 deg
    for B218 at 20 kN. With "operating", ``constants`` holds arrays over the loads.

    Examples
    --------
    >>> from bearinglab import catalog
    >>> r = stand_analysis(catalog.get("4-1006095"), 2 * 9.80665, hertz="table", elastic_constant="paper")
    >>> import math; print(f"{math.degrees(r.contact_angle):.5f} deg in {len(r.iterations)} rows")
    14.46761 deg in 4 rows
    """
    from ..bearing import check_model

    check_model(bearing, "axial-angle")
    z, d, dm, fi, fo, a0 = bearing.require("n_balls", "ball_diameter", "pitch_diameter", "inner_conformity",
                                           "outer_conformity", "contact_angle")
    if not 0.0 < a0 < math.pi / 2:
        raise InputError(f"contact_angle must be in (0, 90) [deg] for the axial-load method, got {math.degrees(a0):g}")
    if hertz == "table":
        table = bearing.hertz_table or {}
        if "inner" not in table or "outer" not in table:
            raise InputError(f"hertz: bearing {bearing.designation!r} has no tabulated Hertz coefficients "
                             "(hertz_table = { inner = ..., outer = ... }); use hertz='exact'")
        ds_i, ds_o = table["inner"], table["outer"]
    elif hertz == "exact":
        ds_i = ds_o = None
    else:
        raise InputError(f"hertz must be one of ['exact', 'table'], got {hertz!r}")
    if stiffness_at is None:
        stiffness_at = "operating" if hertz == "exact" else "free"
    if stiffness_at not in ("operating", "free"):
        raise InputError(f"stiffness_at must be one of ['operating', 'free'], got {stiffness_at!r}")
    if stiffness_at == "operating" and hertz == "table":
        raise InputError("stiffness_at: 'operating' needs hertz='exact' (the tabulated coefficients belong to alpha0)")
    ce = _elastic_constant(elastic_constant, bearing.ball_material, bearing.ring_material)
    fa = check_positive("axial_load", axial_load, "N")
    if stiffness_at == "operating":
        consts, alpha = constants_at_operating_angle(fa, z, d, dm, fi, fo, a0, elastic_constant=ce)
    else:
        consts = stand_constants(z, d, dm, fi, fo, a0, delta_star_inner=ds_i, delta_star_outer=ds_o,
                                 elastic_constant=ce)
        alpha = operating_contact_angle(fa, consts.force_characteristic, a0)
    cs = consts.force_characteristic
    xi_a = axial_displacement_ratio(alpha, a0)
    rows = []
    if np.ndim(fa) == 0:
        rows = iteration_table(float(fa), float(cs), a0, x0=x0, reproduce_print=reproduce_print, max_rows=max_rows)
    return StandAnalysis(fa, a0, consts, series_coefficients(fa / cs, a0), first_approximation(fa / cs, a0),
                         alpha, xi_a, (xi_a * bearing.groove_distance)[()], (fa / (z * np.sin(alpha)))[()], rows, hertz)
