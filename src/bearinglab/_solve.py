"""Default tolerances and iteration limits of the iterative solvers (one place, STYLE.md section 5)."""

__all__: list[str] = []

# spec 000 section 6.3: Newton on the load-angle relation
AXIAL_ANGLE_XTOL = 1e-12  # rad, |dx| below which the angle is converged
AXIAL_ANGLE_FTOL_PERCENT = 1e-10  # %, |F_k - F_a|/F_a below which the load is matched
AXIAL_ANGLE_MAX_ITER = 50

# Hertz: ellipticity from F(rho)
ELLIPTICITY_RTOL = 1e-14
ELLIPTICITY_MAX_ITER = 100

# spec 004 section 5.1: quasi-static Newton-Raphson
QUASISTATIC_TOL = 1e-12  # scaled residual norm
QUASISTATIC_MAX_ITER = 60
QUASISTATIC_SPEED_STEP_RPM = 1500.0  # continuation step in speed

# spec 003 section 9: refinement passes
RUNOUT_REFINE_TOL = 1e-9  # m
RUNOUT_REFINE_MAX_ITER = 20
