r"""Manufacturing errors of an angular-contact spindle bearing -> initial inner-ring displacement and runout.

The method of spec 003 (a rigid, pre-deformation model, first order in the errors): raceway form
errors, ball-size scatter and a prescribed ring tilt push the inner ring off its nominal position; the
ring rests on the two or three balls of the lowest enveloping sinusoid of the generalized errors.

Geometry (spec 003 section 2; module ``geometry``)
--------------------------------------------------
SpindleGeometry         nominal geometry with the derived A0, S, R_b, R_c2, gamma, kappa
geometry_from_catalog   from D_w, d_m, f_o, f_i, tau0, n (catalogue form), optional H10 consistency check
geometry_from_radii     from r30, rho10, rho20, H20, tau0, n (radii form), optional H10 consistency check
geometry_from_bearing   from a :class:`~bearinglab.bearing.BallBearing`

Errors (section 3; ``deviations``)
----------------------------------
FourierSeries           cos/sin coefficients of one error function, by order [m]
fourier_series          build one from ``{order: value}`` mappings or arrays
evaluate_series         sum of a Fourier series at angles
roundness_coefficients  Fourier coefficients of a measured roundness profile (least squares)
RacewayErrors           delta-H, delta-S, delta-rho (and optionally the normal deviation) of one ring
ManufacturingErrors     both rings, the balls, the tilt
manufacturing_errors    build and check a ManufacturingErrors
normal_deviation        Delta_1, Delta_2 at a contact point, eqs. (3.1) and (3.2)

One position (sections 4-9; ``contact``)
----------------------------------------
ball_angles             ball azimuths over rotation, eq. (10.1)
generalized_error       Delta k of every ball, eq. (4.1)
sinusoid_from_pose      (a0, B, D) of a displaced, tilted ring, eq. (5.1)
pose_from_sinusoid      (dx, dy, dz) from (a0, B, D) and the tilt, eq. (5.2)
tie_break_centre        the point c of the normative tie-break, section 7.5
solve_contact           the contact problem (6.1): a0, B, D, contact set, load shares, degenerate face
contact_point_shifts    refinement shifts d tau1, d tau2, d theta2, eqs. (9.1)-(9.3)
initial_displacement    all of it at one or many rotation angles, optionally refined (section 9)

Rotation and runout (section 10; ``rotation``)
----------------------------------------------
rotation_sequence       the centre trajectory over revolutions, all positions in one batch
runout_metrics          radial peak-to-peak in x, y and over all directions, axial peak-to-peak, mean dz
synchronous_part        average at equal rotation angle over the revolutions
runout_spectrum         spectrum of the radial (forward/backward whirl) and axial motion, in orders
spectrum_lines          the spectral lines, labelled as cage, ring or combination lines

Plausibility (``plausibility``, not re-exported)
------------------------------------------------
check_errors            refuses errors of 5 % of D_w or more and tilts past 2 pi (InputError); called by
                        initial_displacement, which also warns (ValidityWarning) of displacements of 5 %
                        of A0 or more, beyond the first-order model's range
error_bounds, displacement_warnings, ERROR_LIMIT, LINEAR_LIMIT, TILT_LIMIT

Exact geometry (section 15, example 4; ``exact``)
-------------------------------------------------
exact_reduction         the same s(theta) without linearisation: largest ball between the ideal tori

Monte Carlo over tolerance classes (section 11; ``tolerances``)
---------------------------------------------------------------
BallGrade, RingClass    ISO 3290 ball grades and ring-class presets (``data/tolerance_classes.toml``)
tolerance_classes       all grades and classes, with their sources
ball_grade, ring_class  one of them by name
monte_carlo_chunk       per-sample metrics of a chunk of samples (seeded per sample)
monte_carlo             a whole study, serial or on dask (``execution=parallel.Execution(...)``)
monte_carlo_errors      the geometry and errors of chosen samples, exactly as the study drew them
worst_samples           indices of the samples with the largest value of a metric
summarize               mean, std, median, p95 and max of per-sample metrics

Files (``files``)
-----------------
load_error_file         the TOML error file of ``examples/runout/README.md``
load_geometry_file      the [geometry] table of a file
write_error_file        write one bearing's errors as such a file (exact round trip)
write_sample_error_files  the error files of chosen Monte Carlo samples, to reproduce them one by one

Engines: the contact problem, the first-approximation generalized errors and the trajectory diameter
run in numpy or in compiled kernels (``runout._compiled``, numba); ``engine="auto"`` (the default of
solve_contact, initial_displacement, rotation_sequence, runout_metrics and monte_carlo) takes the
compiled one whenever numba is installed. One engine gives the same bits in any batch, chunk or
executor; the two agree to 1e-13 um.

Units: SI throughout (m, rad). The spec states its tolerances in micrometres; the solvers scale them.
Every name is defined in the submodule of its topic and re-exported here; ``from bearinglab import
runout`` and ``runout.solve_contact`` stay the way to use them.
"""

from __future__ import annotations

from .contact import (
    ContactSolution,
    Displacement,
    Pose,
    Shifts,
    Sinusoid,
    ball_angles,
    contact_point_shifts,
    generalized_error,
    initial_displacement,
    pose_from_sinusoid,
    sinusoid_from_pose,
    solve_contact,
    tie_break_centre,
)
from .deviations import (
    FourierSeries,
    ManufacturingErrors,
    RacewayErrors,
    evaluate_series,
    fourier_series,
    manufacturing_errors,
    normal_deviation,
    roundness_coefficients,
)
from .exact import exact_reduction
from .files import load_error_file, load_geometry_file, write_error_file, write_sample_error_files
from .geometry import (
    SpindleGeometry,
    geometry_from_bearing,
    geometry_from_catalog,
    geometry_from_radii,
)
from .rotation import (
    METRICS,
    RunoutMetrics,
    Spectrum,
    SpectrumLine,
    Trajectory,
    rotation_sequence,
    runout_metrics,
    runout_spectrum,
    spectrum_lines,
    synchronous_part,
)
from .tolerances import (
    BallGrade,
    MonteCarloResult,
    MonteCarloSamples,
    RingClass,
    SampleErrors,
    Summary,
    ball_grade,
    monte_carlo,
    monte_carlo_chunk,
    monte_carlo_errors,
    ring_class,
    summarize,
    tolerance_classes,
    worst_samples,
)

__all__ = [
    "METRICS",
    "BallGrade",
    "ContactSolution",
    "Displacement",
    "FourierSeries",
    "ManufacturingErrors",
    "MonteCarloResult",
    "MonteCarloSamples",
    "Pose",
    "RacewayErrors",
    "RingClass",
    "RunoutMetrics",
    "SampleErrors",
    "Shifts",
    "Sinusoid",
    "Spectrum",
    "SpectrumLine",
    "SpindleGeometry",
    "Summary",
    "Trajectory",
    "ball_angles",
    "ball_grade",
    "contact_point_shifts",
    "evaluate_series",
    "exact_reduction",
    "fourier_series",
    "generalized_error",
    "geometry_from_bearing",
    "geometry_from_catalog",
    "geometry_from_radii",
    "initial_displacement",
    "load_error_file",
    "load_geometry_file",
    "manufacturing_errors",
    "monte_carlo",
    "monte_carlo_chunk",
    "monte_carlo_errors",
    "normal_deviation",
    "pose_from_sinusoid",
    "ring_class",
    "rotation_sequence",
    "roundness_coefficients",
    "runout_metrics",
    "runout_spectrum",
    "sinusoid_from_pose",
    "solve_contact",
    "spectrum_lines",
    "summarize",
    "synchronous_part",
    "tie_break_centre",
    "tolerance_classes",
    "worst_samples",
    "write_error_file",
    "write_sample_error_files",
]
