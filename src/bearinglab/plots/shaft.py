"""Figures of shaft systems (issue 33), drawn from the document of ``bearinglab shaft --json``.

drawing      the shaft to scale with its sections, bearings, supports, loads, gears and pulleys
lines        deflection, slope and bending moment along the shaft
overview     the drawing above the three lines, on one z axis
campbell     natural frequencies over speed, with the 1x line
study        a quantity over a parameter, one line per series (the spindle's stiffness against spacing)

Every function takes the document (or plain lists) and returns a Figure; matplotlib is loaded on first
use (:func:`bearinglab.plots.figure`).
"""

from __future__ import annotations

import numpy as np

from . import figure

__all__ = ["campbell", "drawing", "lines", "overview", "study"]

_SHAFT, _BORE, _RING, _LOAD = "#b9c3cc", "white", "#1f5fa8", "#c0392b"


def _draw(ax, doc):
    """The shaft of a document on an axes, to scale (z and radius in mm)."""
    from matplotlib.patches import Circle, Polygon, Rectangle

    shaft = doc["shaft"]
    rmax = max(s["diameter_mm"] for s in shaft["sections"]) / 2
    for s in shaft["sections"]:
        r, b = s["diameter_mm"] / 2, s["bore_mm"] / 2
        ax.add_patch(Rectangle((s["start_mm"], -r), s["length_mm"], 2 * r, fc=_SHAFT, ec="#4d5a66", lw=0.8))
        if b > 0:
            ax.add_patch(Rectangle((s["start_mm"], -b), s["length_mm"], 2 * b, fc=_BORE, ec="#4d5a66", lw=0.5))
    ax.axhline(0.0, color="#4d5a66", lw=0.5, ls="-.")
    top = rmax
    for sup in doc["supports"]:
        z = sup["position_mm"]
        for row in sup.get("bearings") or []:
            zr, w = row["position_mm"], row.get("width_mm") or 10.0
            ri, ro = (row.get("bore_mm") or 2 * rmax) / 2, (row.get("outside_diameter_mm") or 2.6 * rmax) / 2
            top = max(top, ro)
            for sign in (1, -1):
                ax.add_patch(Rectangle((zr - w / 2, sign * ri if sign > 0 else -ro), w, ro - ri, fc="#dce6f2",
                                       ec=_RING, lw=1.0))
                ax.add_patch(Circle((zr, sign * 0.5 * (ri + ro)), 0.3 * min(w, ro - ri), fc=_RING, ec=_RING))
        if sup["kind"] in ("linear", "rigid"):
            r = rmax * 1.05
            h = 0.35 * rmax
            tri = [(z, -r), (z - 0.4 * h, -r - h), (z + 0.4 * h, -r - h)]
            ax.add_patch(Polygon(tri, closed=True, fc="#dce6f2" if sup["kind"] == "linear" else _RING, ec=_RING))
        ax.annotate(sup["name"], (z, -top * 1.1), ha="center", va="top", fontsize="small", color=_RING)
    for g in doc.get("gears", []):
        r = g["pitch_diameter_mm"] / 2
        w = max(0.02 * shaft["length_mm"], 4.0)
        top = max(top, r)
        ax.add_patch(Rectangle((g["position_mm"] - w / 2, -r), w, 2 * r, fc="#f3e2c7", ec="#a0642a", lw=1.0))
    for p in doc.get("pulleys", []):
        w = max(0.02 * shaft["length_mm"], 4.0)
        ax.add_patch(Rectangle((p["position_mm"] - w / 2, -1.6 * rmax), w, 3.2 * rmax, fc="#e3d9f0", ec="#6c4a9b"))
    loads = [(ld["position_mm"], ld["force_N"]) for ld in doc.get("applied_loads", [])]
    big = max([float(np.hypot(f[0], f[1])) for _, f in loads] + [1e-300])
    for z, f in loads:
        fr = float(np.hypot(f[0], f[1]))
        if fr > 0:
            length = 0.6 * top * (0.4 + 0.6 * fr / big)
            ax.annotate("", (z, top * 1.05), (z, top * 1.05 + length),
                        arrowprops={"arrowstyle": "-|>", "color": _LOAD, "lw": 1.5})
            ax.annotate(f"{fr:.4g} N", (z, top * 1.1 + length), ha="center", va="bottom", fontsize="x-small",
                        color=_LOAD)
        if abs(f[2]) > 0:
            dz = 0.06 * shaft["length_mm"] * np.sign(f[2])
            ax.annotate("", (z + dz, 0.0), (z, 0.0), arrowprops={"arrowstyle": "-|>", "color": _LOAD, "lw": 1.5})
    ax.set_xlim(-0.08 * shaft["length_mm"], 1.05 * shaft["length_mm"])
    ax.set_ylim(-top * 1.6, top * 2.3)
    ax.set_aspect("equal", adjustable="box")
    ax.set_ylabel("r [mm]")


def drawing(doc, *, title=None):
    """The shaft to scale with its sections, bearings, supports, loads, gears and pulleys.

    Parameters
    ----------
    doc : dict
        A document of :func:`bearinglab.calculations.shaft.document` (``shaft``, ``supports``,
        ``applied_loads``, ``gears``, ``pulleys``).
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
        Radial loads as arrows sized by their magnitude (in the plane of the drawing whatever their
        direction, labelled in N), axial loads along the axis; bearings as their rings and a ball,
        linear supports as open and rigid ones as filled triangles.
    """
    fig = figure(figsize=(8.0, 3.2))
    ax = fig.add_subplot()
    _draw(ax, doc)
    ax.set_xlabel("z [mm]")
    if title:
        ax.set_title(title, fontsize="medium")
    return fig


def _lines(axes, doc):
    rows = doc["deflection"]
    z = np.array([r["z_mm"] for r in rows])

    def col(key):
        return np.array([np.nan if r[key] is None else r[key] for r in rows])

    spec = ((axes[0], "displacement", "u", "deflection [um]"), (axes[1], "slope", "slope", "slope [mrad]"),
            (axes[2], "bending_moment", "M", "bending moment [N m]"))
    units = {"displacement": "_um", "slope": "_mrad", "bending_moment": "_Nm"}
    for ax, key, sym, label in spec:
        if key == "bending_moment":
            zz, mx, my = _moment_steps(z, col("bending_moment_x_Nm"), col("bending_moment_y_Nm"),
                                       col("shear_force_x_N"), col("shear_force_y_N"))
            ax.plot(zz, mx, color="#1f5fa8", label=f"{sym} x")
            ax.plot(zz, my, color="#c0392b", label=f"{sym} y")
            ax.plot(zz, np.hypot(mx, my), color="#333333", lw=0.8, ls="--", label="|M|")
        else:
            ax.plot(z, col(f"{key}_x{units[key]}"), color="#1f5fa8", label=f"{sym} x")
            ax.plot(z, col(f"{key}_y{units[key]}"), color="#c0392b", label=f"{sym} y")
        ax.set_ylabel(label)
        ax.axhline(0.0, color="#999999", lw=0.5)
        for sup in doc["supports"]:
            ax.axvline(sup["position_mm"], color="#1f5fa8", lw=0.5, ls=":")
        ax.legend(fontsize="x-small", loc="best")
    axes[-1].set_xlabel("z [mm]")


def _moment_steps(z, mx, my, vx, vy):
    """The bending moment as drawn: the rows hold it just right of each node; between two nodes it runs
    straight (the shear force V is constant there; M(z) = M(z_k) + (z - z_k) (V_y, -V_x), the moments of the
    resultant about the moving cut), and a bearing's or a load's moment is a jump at its node."""
    zz, ox, oy = [z[0]], [mx[0]], [my[0]]
    for k in range(1, len(z)):
        dz = (z[k] - z[k - 1]) * 1e-3  # mm -> m
        zz += [z[k], z[k]]
        ox += [mx[k - 1] + dz * vy[k - 1], mx[k]]
        oy += [my[k - 1] - dz * vx[k - 1], my[k]]
    return np.array(zz), np.array(ox), np.array(oy)


def lines(doc, *, title=None):
    """Deflection, slope and bending moment along the shaft, x and y components.

    Parameters
    ----------
    doc : dict
        A document with ``deflection`` rows and ``supports``.
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = figure(figsize=(8.0, 7.0))
    axes = fig.subplots(3, 1, sharex=True)
    _lines(axes, doc)
    if title:
        fig.suptitle(title, fontsize="medium")
    return fig


def overview(doc, *, title=None):
    """The drawing above the deflection, slope and bending-moment lines, on one z axis.

    Parameters
    ----------
    doc : dict
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure

    Examples
    --------
    >>> doc = {"shaft": {"length_mm": 100.0, "sections": [{"start_mm": 0.0, "length_mm": 100.0,
    ...        "diameter_mm": 20.0, "bore_mm": 0.0}]}, "supports": [{"name": "A", "kind": "rigid",
    ...        "position_mm": 0.0}], "deflection": [{"z_mm": z, "displacement_x_um": 0.0,
    ...        "displacement_y_um": z, "slope_x_mrad": 0.0, "slope_y_mrad": 1.0, "bending_moment_x_Nm": 0.0,
    ...        "bending_moment_y_Nm": 0.0, "bending_moment_Nm": 0.0, "shear_force_x_N": 0.0,
    ...        "shear_force_y_N": 0.0} for z in (0.0, 100.0)]}
    >>> len(overview(doc).axes)
    4
    """
    fig = figure(figsize=(8.0, 9.0))
    grid = fig.add_gridspec(4, 1, height_ratios=[1.3, 1, 1, 1])
    ax0 = fig.add_subplot(grid[0])
    _draw(ax0, doc)
    axes = [fig.add_subplot(grid[k], sharex=ax0) for k in (1, 2, 3)]
    _lines(axes, doc)
    if title:
        fig.suptitle(title, fontsize="medium")
    return fig


def campbell(speed_rpm, frequency_hz, *, whirl=None, title=None):
    """A Campbell diagram: natural frequencies over speed, with the 1x (synchronous) line.

    Parameters
    ----------
    speed_rpm : array_like
        (s,) speeds. [rpm]
    frequency_hz : array_like
        (s, k) frequencies at each speed. [Hz]
    whirl : sequence of sequence of str, optional
        "forward" / "backward" of each, for the markers.
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    n = np.asarray(speed_rpm, dtype=float)
    f = np.asarray(frequency_hz, dtype=float)
    fig = figure(figsize=(6.4, 4.6))
    ax = fig.add_subplot()
    for k in range(f.shape[1]):
        ax.plot(n, f[:, k], color="#1f5fa8", lw=1.0)
        if whirl is not None:
            for i in range(len(n)):
                if k < len(whirl[i]):
                    ax.plot(n[i], f[i, k], "^" if whirl[i][k] == "forward" else "v", color="#1f5fa8", ms=4)
    ax.plot(n, n / 60.0, color=_LOAD, ls="--", lw=1.0, label="1x")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("natural frequency [Hz]")
    ax.legend(fontsize="small")
    if title:
        ax.set_title(title, fontsize="medium")
    return fig


def study(x, series, *, xlabel, ylabel, title=None):
    """A quantity over a parameter, one line per series.

    Parameters
    ----------
    x : array_like
        (p,) the parameter.
    series : dict
        Label -> (p,) values.
    xlabel, ylabel : str
    title : str, optional

    Returns
    -------
    matplotlib.figure.Figure
    """
    fig = figure(figsize=(6.4, 4.4))
    ax = fig.add_subplot()
    for label, y in series.items():
        ax.plot(x, y, marker="o", ms=3, label=label)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, lw=0.3)
    ax.legend(fontsize="small")
    if title:
        ax.set_title(title, fontsize="medium")
    return fig
