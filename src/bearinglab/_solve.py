"""Default tolerances and iteration limits of the iterative solvers (one place, STYLE.md section 5), and
the choice between a solver's numpy path and its compiled kernel (``engine``)."""

import importlib.util

from .errors import InputError

__all__: list[str] = []

ENGINES = ("auto", "numpy", "compiled")


def use_compiled(engine, *, auto):
    """True if a solver runs its compiled kernel: ``engine`` "compiled" (numba required), or "auto" where
    ``auto`` (the solver's own condition: a batch large enough, a method the kernel implements) holds and
    numba is installed. numba is looked up, not imported: a solver that stays on numpy never loads it."""
    if not isinstance(engine, str) or engine not in ENGINES:
        raise InputError(f"engine must be one of {list(ENGINES)}, got {engine!r}")
    if engine == "numpy" or (engine == "auto" and not auto):
        return False
    found = importlib.util.find_spec("numba") is not None
    if engine == "compiled" and not found:
        raise InputError("engine='compiled' needs numba, which is not installed (use engine='numpy' or 'auto')")
    return found

# spec 000 section 6.3: Newton on the load-angle relation
AXIAL_ANGLE_XTOL = 1e-12  # rad, |dx| below which the angle is converged
AXIAL_ANGLE_FTOL_PERCENT = 1e-10  # %, |F_k - F_a|/F_a below which the load is matched
AXIAL_ANGLE_MAX_ITER = 50
# its start: Halley on eq. (1) squared, a polynomial in the gap cos(alpha0) - cos(alpha)
AXIAL_ANGLE_START_RTOL = 1e-6  # relative step of the gap after which one more step is not taken (error ~ rtol^3)
AXIAL_ANGLE_START_MAX_ITER = 60
AXIAL_ANGLE_BLOCK = 16384  # cases evaluated together (a block's arrays stay in the CPU cache)
AXIAL_ANGLE_COMPILED_CASES = 1_000_000  # engine="auto": fewest cases of a call that the compiled kernel solves

# Hertz: ellipticity from F(rho)
ELLIPTICITY_RTOL = 1e-14
ELLIPTICITY_MAX_ITER = 100

# spec 004 section 5.1: quasi-static Newton-Raphson
QUASISTATIC_TOL = 1e-12  # scaled residual norm
QUASISTATIC_MAX_ITER = 60
QUASISTATIC_SPEED_STEP_RPM = 1500.0  # continuation step in speed

# spec 003 section 9: refinement passes (tolerance 1e-9 um on the pose, at most 30 passes)
RUNOUT_REFINE_TOL = 1e-15  # m
RUNOUT_REFINE_MAX_ITER = 30
QUASISTATIC_STAGE_MAX_ITER = 10  # Newton iterations per continuation step before the speed step is cut
QUASISTATIC_MAX_LOOPS = 1000  # batched iterations (all cases together) before the remaining cases are failed
# spec 003 sections 7-8: contact problem tolerances, in um and scaled by max(1, max|dk| / 1 um)
RUNOUT_TIE_TOL_UM = 1e-9  # eps of section 8: feasibility of a triple, ties between dual vertices
RUNOUT_CONTACT_TOL_UM = 1e-7  # section 7.6: slack below which a ball touches; shortest degenerate face
RUNOUT_FACE_TOL_UM = 1e-7  # section 8.2 step 4: feasibility of a face candidate
RUNOUT_STRICT_WEIGHT = 1e-9  # a dual weight above this makes a triangle strict (origin inside it)
# exact-geometry check of spec 003 example 4: Newton on the ball-centre position
RUNOUT_EXACT_XTOL = 1e-14  # m
RUNOUT_EXACT_MAX_ITER = 50

# ASTM D2270 inverted: bisection on log(nu100) for the nu100 of a viscosity index
# (bearinglab.ratings.lubrication.viscosity_100_from_index)
VISCOSITY_INDEX_RTOL = 1e-12  # relative width of the bracket on nu100
VISCOSITY_INDEX_MAX_ITER = 100

# Bearing temperature (bearinglab.thermal): bracketed root of friction power - heat dissipated, all cases
# together (Illinois regula falsi with a bisection fallback)
THERMAL_XTOL = 1e-12  # K, width of the bracket on the temperature
THERMAL_RTOL = 1e-12  # |P_f - P_d| relative to P_f at which a case is converged
THERMAL_MAX_ITER = 200
