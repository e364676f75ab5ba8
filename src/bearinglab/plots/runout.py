"""Figures of spec 003, the runout model (matplotlib, Agg canvas; functions return Figures).

Imported on use by the command line and the demo only, so ``import bearinglab`` does not load matplotlib.

Figures
-------
figure_contact      the source's figure 5: Delta k against ball azimuth, the fitted sinusoid, the
                    touching balls highlighted
figure_trajectory   the centre trajectory, x-y and polar
figure_axial        Delta z against rotation
figure_spectrum     the runout spectrum (radial forward/backward whirl and axial), labelled lines
figure_histograms   Monte Carlo histograms of the runout metrics

Writers (each file is written whole or not at all: temporary file in the same directory, then
os.replace): save, save_single, save_sequence, save_monte_carlo.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .. import runout
from .._io import atomic_output

__all__ = [
    "figure_axial",
    "figure_contact",
    "figure_histograms",
    "figure_spectrum",
    "figure_trajectory",
    "save",
    "save_monte_carlo",
    "save_sequence",
    "save_single",
]

UM = 1e-6


def _figure(**kw):
    fig = Figure(**kw)
    FigureCanvasAgg(fig)
    return fig


def save(fig, path, *, dpi=130):
    """Write a figure as PNG, whole or not at all (its directory is created).

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
    path : str or Path
        The PNG file.
    dpi : int
        Resolution. [1/inch]

    Returns
    -------
    Path
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with atomic_output(path, suffix=".png") as tmp:
        fig.savefig(tmp, dpi=dpi, format="png")
    return path


def figure_contact(d):
    """Figure 5 of the source: Delta k^i against ball azimuth, the sinusoid s(theta), the contacts.

    Parameters
    ----------
    d : Displacement
        One position (:func:`bearinglab.runout.initial_displacement` at a single angle).

    Returns
    -------
    matplotlib.figure.Figure
    """
    c = d.contact
    fig = _figure(figsize=(8, 4.5))
    ax = fig.add_subplot()
    th = np.mod(np.degrees(d.ball_angle), 360.0)
    dk = np.asarray(d.generalized_error) / UM
    grid = np.linspace(0.0, 360.0, 721)
    s = (c.constant + c.sine * np.sin(np.radians(grid)) + c.cosine * np.cos(np.radians(grid))) / UM
    ax.plot(
        grid,
        s,
        color="C0",
        lw=1.5,
        label=f"s(θ) = a0 + B sin θ + D cos θ   (a0 = {c.constant / UM:.4f} µm)",
    )
    touch = np.asarray(c.contact)
    ax.scatter(
        th[~touch], dk[~touch], facecolors="white", edgecolors="C7", zorder=3, label="loose ball"
    )
    ax.scatter(th[touch], dk[touch], color="C3", zorder=4, s=45, label="ball in contact")
    for i, (x, y) in enumerate(zip(th, dk)):
        ax.annotate(
            str(i + 1), (x, y), textcoords="offset points", xytext=(0, 6), ha="center", fontsize=7
        )
    ax.set_xlim(0, 360)
    ax.set_xticks(np.arange(0, 361, 45))
    ax.set_xlabel("ball azimuth θ [deg]")
    ax.set_ylabel("generalized error Δk [µm]")
    deg = " (degenerate face)" if bool(c.degenerate) else ""
    ax.set_title(
        f"ψ = {math.degrees(float(d.rotation_angle)):.3g}°: Δx = {d.x / UM:.4f}, Δy = {d.y / UM:.4f}, "
        f"Δz = {d.z / UM:.4f} µm{deg}",
        fontsize=10,
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    fig.tight_layout()
    return fig


def figure_trajectory(t):
    """The centre trajectory, x-y and polar.

    Parameters
    ----------
    t : Trajectory
        From :func:`bearinglab.runout.rotation_sequence`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    d = t.displacement
    x, y = d.x / UM, d.y / UM
    fig = _figure(figsize=(10, 4.6))
    ax = fig.add_subplot(1, 2, 1)
    ax.plot(x, y, lw=0.8, color="C0")
    ax.plot(x[:1], y[:1], "o", color="C3", label="ψ = start")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("Δx [µm]")
    ax.set_ylabel("Δy [µm]")
    m = t.metrics
    ax.set_title(
        f"ptp x {m.radial_ptp_x / UM:.3f}, y {m.radial_ptp_y / UM:.3f}, max {m.radial_ptp_max / UM:.3f} µm",
        fontsize=9,
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax2 = fig.add_subplot(1, 2, 2, projection="polar")
    ax2.plot(np.arctan2(y, x), np.hypot(x, y), lw=0.8, color="C0")
    ax2.set_title("centre position, polar (radius in µm)", fontsize=9)
    fig.suptitle(
        f"Inner-ring centre trajectory, {t.revolutions} revolutions × {t.steps_per_revolution} steps"
    )
    fig.tight_layout()
    return fig


def figure_axial(t):
    """Delta z against the rotation angle (in revolutions).

    Parameters
    ----------
    t : Trajectory
        From :func:`bearinglab.runout.rotation_sequence`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    d = t.displacement
    fig = _figure(figsize=(9, 3.8))
    ax = fig.add_subplot()
    revs = t.rotation_angle / (2 * np.pi)
    ax.plot(revs, d.z / UM, lw=0.9, color="C2", label="Δz")
    ax.axhline(
        t.metrics.dz_mean / UM,
        color="k",
        lw=0.8,
        ls="--",
        label=f"mean {t.metrics.dz_mean / UM:.4f} µm",
    )
    ax.set_xlabel("inner-ring rotation ψ [rev]")
    ax.set_ylabel("Δz [µm]")
    ax.set_title(f"Axial displacement: peak-to-peak {t.metrics.axial_ptp / UM:.4f} µm", fontsize=10)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    return fig


def figure_spectrum(spectrum, lines=()):
    """Amplitude spectra of the radial (forward/backward whirl) and axial motion, lines labelled.

    Parameters
    ----------
    spectrum : Spectrum
        From :func:`bearinglab.runout.runout_spectrum`.
    lines : sequence of SpectrumLine
        Lines to label (:func:`bearinglab.runout.spectrum_lines`).

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = _figure(figsize=(10, 6))
    o = spectrum.order
    top = max(2.0, float(np.max([ln.order for ln in lines], initial=0.0)) * 1.15)
    keep = o <= top
    ax = fig.add_subplot(2, 1, 1)
    ax.vlines(
        o[keep][1:],
        0,
        spectrum.radial_forward[keep][1:] / UM,
        color="C0",
        lw=1.2,
        label="forward whirl",
    )
    ax.vlines(
        o[keep][1:] + 0.02 * (o[1] - o[0]),
        0,
        -spectrum.radial_backward[keep][1:] / UM,
        color="C1",
        lw=1.2,
        label="backward whirl (drawn downwards)",
    )
    ax.axhline(0, color="k", lw=0.5)
    ax.set_ylabel("radial amplitude [µm]")
    ax.legend(fontsize=8)
    ax2 = fig.add_subplot(2, 1, 2, sharex=ax)
    ax2.vlines(o[keep][1:], 0, spectrum.axial[keep][1:] / UM, color="C2", lw=1.2, label="axial")
    ax2.set_ylabel("axial amplitude [µm]")
    ax2.set_xlabel("order (cycles per inner-ring revolution)")
    ax2.legend(fontsize=8)
    for ln in lines:
        a = ln.amplitude / UM
        if ln.component == "axial":
            ax2.annotate(
                f"{ln.label}\n{ln.source}",
                (ln.order, a),
                fontsize=7,
                ha="center",
                xytext=(0, 3),
                textcoords="offset points",
            )
        else:
            sign = 1.0 if ln.component == "radial forward" else -1.0
            ax.annotate(
                ln.label,
                (ln.order, sign * a),
                fontsize=7,
                ha="center",
                xytext=(0, 3 if sign > 0 else -10),
                textcoords="offset points",
            )
    for a in (ax, ax2):
        a.grid(alpha=0.3)
    fig.suptitle("Runout spectrum (κ: cage order; ×: shaft order)")
    fig.tight_layout()
    return fig


def figure_histograms(result):
    """Histograms of the per-sample metrics of a Monte Carlo study.

    Parameters
    ----------
    result : MonteCarloResult
        From :func:`bearinglab.runout.monte_carlo`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = _figure(figsize=(10, 7))
    names = ("radial_ptp_x", "radial_ptp_y", "radial_ptp_max", "axial_ptp")
    for k, name in enumerate(names):
        ax = fig.add_subplot(2, 2, k + 1)
        v = getattr(result.samples, name) / UM
        s = result.summary[name]
        ax.hist(v, bins=min(40, max(10, v.size // 10)), color="C0", alpha=0.75)
        ax.axvline(s.mean / UM, color="k", lw=1, label=f"mean {s.mean / UM:.3f}")
        ax.axvline(s.p95 / UM, color="C3", lw=1, ls="--", label=f"p95 {s.p95 / UM:.3f}")
        ax.set_xlabel(f"{name.replace('_', ' ')} [µm]")
        ax.set_ylabel("samples")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
    fig.suptitle(
        f"Monte Carlo: {result.ball_grade.name} balls, {result.ring_class.name} rings, "
        f"{result.samples.sample_index.size} samples, seed {result.seed}"
    )
    fig.tight_layout()
    return fig


def save_single(d, directory):
    """Write figure 5 of one position as ``runout_contact_psi<deg>.png``.

    Parameters
    ----------
    d : Displacement
        One position.
    directory : str or Path
        Where to write.

    Returns
    -------
    list of Path
    """
    psi = math.degrees(float(d.rotation_angle))
    return [save(figure_contact(d), Path(directory) / f"runout_contact_psi{psi:g}.png")]


def save_sequence(t, spectrum=None, lines=None, directory="."):
    """Write the trajectory, axial, spectrum and first-position figures of a sequence.

    Parameters
    ----------
    t : Trajectory
        From :func:`bearinglab.runout.rotation_sequence`.
    spectrum : Spectrum, optional
        Its spectrum (computed when not given).
    lines : sequence of SpectrumLine, optional
        Lines to label (found when not given).
    directory : str or Path
        Where to write.

    Returns
    -------
    list of Path
    """
    d = t.displacement
    if spectrum is None:
        spectrum = runout.runout_spectrum(d.x, d.y, d.z, t.steps_per_revolution)
    if lines is None:
        lines = runout.spectrum_lines(spectrum, t.cage_ratio)
    directory = Path(directory)
    return [
        save(figure_trajectory(t), directory / "runout_trajectory.png"),
        save(figure_axial(t), directory / "runout_axial.png"),
        save(figure_spectrum(spectrum, lines), directory / "runout_spectrum.png"),
        *save_single(_position(d, 0), directory),
    ]


def _position(d, k):
    """Position k of a batched Displacement as a single-position one."""
    c = runout.ContactSolution(*(np.asarray(v)[k] for v in d.contact))
    fields = [np.asarray(v)[k] for v in (d.rotation_angle, d.ball_angle, d.generalized_error)]
    rest = [
        np.asarray(v)[k]
        for v in (d.x, d.y, d.z, d.free_play, d.tilt_x, d.tilt_y, d.passes, d.converged)
    ]
    return runout.Displacement(
        *fields,
        c,
        *rest,
        runout.Shifts(*(np.asarray(v)[k] for v in d.shifts)),
        runout.Pose(*(np.asarray(v)[k] for v in d.first_approximation)),
        np.asarray(d.last_change)[k],
    )


def save_monte_carlo(result, directory):
    """Write the histograms of a Monte Carlo study as ``runout_monte_carlo.png``.

    Parameters
    ----------
    result : MonteCarloResult
        The study.
    directory : str or Path
        Where to write.

    Returns
    -------
    list of Path
    """
    return [save(figure_histograms(result), Path(directory) / "runout_monte_carlo.png")]
