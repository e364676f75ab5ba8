r"""High-speed angular-contact ball bearing under pure thrust: the quasi-static model of spec 004.

Ball centrifugal force and gyroscopic moment pull the inner and outer contact angles apart at speed.
Under pure thrust every ball is in the same state, so the model is one ball plus the ring (spec 004
section 3): five equations in the ball-centre position, the two contact deflections and the axial
displacement of the inner ring. Every public name of the subpackages is available here.

One ball at speed (:mod:`~bearinglab.quasistatic.ball`, spec 004 eqs. 8-13)
-------------------------------------------------------------------------------
printed_constants              the constants of eqs. (8) and (12), in N, mm, rpm, from a ball density
centrifugal_force              F_c = m (d_m/2) omega_m^2                                   eq. (8)
gyroscopic_moment              M_g = J omega_R omega_m sin(beta), J = m D^2/10              eq. (12)
attitude_angle                 ball attitude angle beta, outer- or inner-raceway control    eq. (10)
ball_speeds                    cage (orbital) and ball-spin speeds, outer ring fixed        eqs. (9), (13)
required_friction_coefficient  2 M_g / (D Q_e), the friction outer-raceway control needs
friction_coefficient           deprecated alias of required_friction_coefficient
PrintedConstants, BallSpeeds, CONSTANTS, HARRIS_CENTRIFUGAL_CONSTANT, HARRIS_GYROSCOPIC_CONSTANT,
PAPER_GYROSCOPIC_CONSTANT, RACEWAY_CONTROLS, FRICTION_WARNING_LIMIT

Contact (:mod:`~bearinglab.quasistatic.contact`, spec 004 eqs. 14-21)
------------------------------------------------------------------------
contact_stiffness              K_i, K_e at the operating angles, exact Hertz (:mod:`bearinglab.hertz`)
Stiffness

Equilibrium (:mod:`~bearinglab.quasistatic.equations`, spec 004 sections 3, 5.1, 5.2)
--------------------------------------------------------------------------------------
residual                       scaled residuals and Jacobian of the five equations (section 5.1)
angle_residual                 E3 and E7 of the paper's contact-angle iteration for trial angles (5.2)
Residual, AngleResidual, STATUS

Solutions and analyses (:mod:`~bearinglab.quasistatic.thrust`)
---------------------------------------------------------------
contact_angles                 the solution for arrays of loads and speeds: batched Newton-Raphson with
                               continuation in speed (5.1, :mod:`~bearinglab.quasistatic.continuation`),
                               or the paper's contact-angle search (5.2, :mod:`~bearinglab.quasistatic.search`)
zero_displacement_thrust       the thrust at which the axial displacement changes sign, per speed
high_speed_analysis            one :class:`~bearinglab.bearing.BallBearing`, loads and speeds broadcast
sign_change_thrust             the thrust at which delta_a changes sign, for one bearing and its speeds
sweep                          a loads x speeds grid (``execution=parallel.Execution(...)``); failures flagged
result_table                   the result as columns in engineering units (CSV, JSON)
HighSpeedState

Combined loads (submodules, imported with the package)
------------------------------------------------------
combined                       the 5-DOF inner ring under Fx, Fy, Fz, Mx, My, at rest and at speed: load
                               distribution, contact angles and pressures per ball, tangent stiffness
sets                           preloaded bearing sets (DB, DF, DT) on one shaft: distribution and stiffness
preload                        a single bearing with zero or negative clearance: its preload and stiffness
rotordynamics                  speed-dependent kxx, kxy, kyx, kyy, kzz for ``ross.BearingElement``
light_load                     light-load criteria at speed: the maker's minimum load (0.01 C), an
                               outer angle near zero, the test-stand flag against gyroscopic slip

Conventions: the outer ring is fixed and the inner ring turns at ``shaft_speed`` >= 0 (the model is
symmetric in the direction of rotation); the thrust acts on the inner ring. The gyroscopic moment M_g
is a magnitude (>= 0) and the friction that resists it enters eqs. (5)-(7) with the physical sign of
spec 004 section 4.

References
----------
.. [1] Zhao Chunjiang, Cui Guohua, Wang Guoqiang, Huang Qingxue and Zhang Fangping, "Precise definition
   of the contact-angle field of a high-speed angular-contact ball bearing under axial load,"
   Transactions of the CSAM, vol. 39, no. 12, pp. 154-156, 209, 2008 (spec 004 of this project).
.. [2] A. B. Jones, "A general theory for elastically constrained ball and radial roller bearings under
   arbitrary load and speed conditions," J. Basic Eng., vol. 82, no. 2, pp. 309-320, 1960,
   doi:10.1115/1.3662587.
.. [3] T. A. Harris and M. N. Kotzalas, *Advanced Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 3 (high-speed ball bearings), doi:10.1201/9781420006582.
"""

from __future__ import annotations

from . import combined, light_load, preload, rotordynamics, sets
from .ball import (
    CONSTANTS,
    FRICTION_WARNING_LIMIT,
    HARRIS_CENTRIFUGAL_CONSTANT,
    HARRIS_GYROSCOPIC_CONSTANT,
    PAPER_GYROSCOPIC_CONSTANT,
    RACEWAY_CONTROLS,
    BallSpeeds,
    PrintedConstants,
    attitude_angle,
    ball_speeds,
    centrifugal_force,
    friction_coefficient,
    gyroscopic_moment,
    printed_constants,
    required_friction_coefficient,
)
from .contact import Stiffness, contact_stiffness
from .continuation import _static_start, _unknowns_from  # noqa: F401  (bench/high_speed.py, for now)
from .equations import (  # noqa: F401
    STATUS,
    AngleResidual,
    Residual,
    _equations,
    _prepare,
    angle_residual,
    residual,
)
from .thrust import (  # noqa: F401  (_bearing_args: bench and tests, for now)
    HighSpeedState,
    _bearing_args,
    contact_angles,
    high_speed_analysis,
    result_table,
    sign_change_thrust,
    sweep,
    zero_displacement_thrust,
)

__all__ = [
    "CONSTANTS",
    "FRICTION_WARNING_LIMIT",
    "HARRIS_CENTRIFUGAL_CONSTANT",
    "HARRIS_GYROSCOPIC_CONSTANT",
    "PAPER_GYROSCOPIC_CONSTANT",
    "RACEWAY_CONTROLS",
    "STATUS",
    "AngleResidual",
    "BallSpeeds",
    "HighSpeedState",
    "PrintedConstants",
    "Residual",
    "Stiffness",
    "angle_residual",
    "attitude_angle",
    "ball_speeds",
    "centrifugal_force",
    "combined",
    "contact_angles",
    "contact_stiffness",
    "friction_coefficient",
    "gyroscopic_moment",
    "high_speed_analysis",
    "light_load",
    "preload",
    "printed_constants",
    "required_friction_coefficient",
    "residual",
    "result_table",
    "rotordynamics",
    "sets",
    "sign_change_thrust",
    "sweep",
    "zero_displacement_thrust",
]
