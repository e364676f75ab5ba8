"""Command line of the friction capability (spec 001): ``friction torque``, ``friction lab``, ``friction template``.

torque     friction torque of a bearing under combined load (one-term, two-term, Palmgren; SKF four-term)
lab        a measurement-session file -> the three tasks, cross-checks, conclusions and the HTML report
template   a blank, commented measurement-session file to start a new session

Commands
--------
COMMANDS   the ``friction`` command group, by name (the application adds it)
"""

import dataclasses
import sys
import warnings
from pathlib import Path
from typing import Annotated

import typer

from ..errors import InputError
from ._common import (
    BearingFile,
    BearingName,
    CatalogFile,
    ContactAngle,
    JsonFlag,
    OilOpt,
    TemperatureOpt,
    Viscosity100Opt,
    ViscosityIndexOpt,
    check_not_input,
    check_output_directory,
    console,
    emit_json,
    inputs_echo,
    lubricant_viscosity,
    parse_length,
    parse_speeds,
    parse_viscosity,
    print_warnings,
    resolve_bearing,
    speed_size,
    table,
)

__all__ = ["COMMANDS"]

friction_app = typer.Typer(
    help="Friction torque: handbook models and the friction-rig lab.",
    no_args_is_help=True,
)
_MODELS = ("one-term", "two-term", "palmgren", "skf")
_PANEL = "Bearing data (override the catalog)"


def _friction_bearing(
    bearing,
    bearing_file,
    catalog,
    bearing_type,
    contact_angle,
    bore,
    outside_diameter,
    mean_diameter,
    static_load_rating,
):
    from .. import friction
    from ..bearing import BallBearing
    from ..units import parse_quantity
    if bearing or bearing_file:
        base = resolve_bearing(bearing, bearing_file, catalog, contact_angle=contact_angle)
    else:
        if bearing_type is None and bore is None:
            raise InputError(
                "bearing: give --bearing NAME (e.g. 101), --bearing-file FILE, or --type, --bore, "
                "--mean-diameter/--outside-diameter and --static-load-rating"
            )
        base = BallBearing(
            designation="inline",
            type=bearing_type or "radial",
            contact_angle=None
            if contact_angle is None
            else parse_quantity(contact_angle, "angle", "contact-angle"),
        )
    changes = {}
    if bearing_type is not None:
        if bearing_type not in friction.BEARING_TYPES:
            raise InputError(
                f"type must be one of {list(friction.BEARING_TYPES)}, got {bearing_type!r}"
            )
        changes["type"] = bearing_type
    if bore is not None:
        changes["bore"] = parse_length(bore, "bore")
    if static_load_rating is not None:
        c0 = parse_quantity(static_load_rating, "force", "static-load-rating")
        if not c0 > 0:
            raise InputError(f"static-load-rating must be > 0 [N] (C0), got {c0:g} N")
        changes["static_load_rating"] = c0
    if mean_diameter is not None and outside_diameter is not None:
        raise InputError("mean-diameter: give --mean-diameter or --outside-diameter, not both")
    if outside_diameter is not None:
        changes["outside_diameter"] = parse_length(outside_diameter, "outside-diameter")
    if mean_diameter is not None:
        dm = parse_length(mean_diameter, "mean-diameter")
        d = changes.get("bore", base.bore)
        if d is None:
            raise InputError("mean-diameter: needs the bore (--bore) to give the outside diameter")
        if not dm > d:
            raise InputError(
                f"mean-diameter must be > bore [mm], got {dm * 1e3:g} mm with bore {d * 1e3:g} mm"
            )
        changes["outside_diameter"] = 2.0 * dm - d
    return dataclasses.replace(base, **changes) if changes else base


def _case_values(text, kind, name):
    import numpy as np

    from .._bounds import MAX_CASES
    from ..units import parse_values
    values = parse_values(text, kind, name, limit=MAX_CASES)
    if np.any(~(values >= 0)):  # a force: its magnitude (P0 takes |F_r| and |F_a|)
        raise InputError(f"{name} must be >= 0 [N], got {float(values[~(values >= 0)][0]):g} N")
    return values


def torque(
    radial_load: Annotated[
        str,
        typer.Option(
            "--radial-load", "-R", help="F_r, e.g. '10 N', '1 kgf', or a list/range '0N:50N:10N'."
        ),
    ] = "0 N",
    axial_load: Annotated[
        str, typer.Option("--axial-load", "-A", help="F_a, e.g. '5 N' (list/range allowed).")
    ] = "0 N",
    speed: Annotated[
        str,
        typer.Option(
            "--speed", "-n", help="Inner-ring speed, e.g. '3000 rpm' (list/range allowed)."
        ),
    ] = "0 rpm",
    model: Annotated[
        str,
        typer.Option(
            "--model",
            "-m",
            help="one-term (default) | two-term (needs --f0) | palmgren (needs --viscosity, --palmgren-f0) | "
            "skf (needs --viscosity; --lubrication).",
        ),
    ] = "one-term",
    bearing: BearingName = None,
    bearing_file: BearingFile = None,
    catalog: CatalogFile = None,
    bearing_type: Annotated[
        str | None, typer.Option("--type", help="radial | angular.", rich_help_panel=_PANEL)
    ] = None,
    contact_angle: ContactAngle = None,
    bore: Annotated[
        str | None, typer.Option("--bore", help="d, e.g. '12 mm'.", rich_help_panel=_PANEL)
    ] = None,
    outside_diameter: Annotated[
        str | None,
        typer.Option("--outside-diameter", help="D, e.g. '28 mm'.", rich_help_panel=_PANEL),
    ] = None,
    mean_diameter: Annotated[
        str | None,
        typer.Option(
            "--mean-diameter", help="d_m = (d + D)/2, e.g. '20 mm'.", rich_help_panel=_PANEL
        ),
    ] = None,
    static_load_rating: Annotated[
        str | None,
        typer.Option("--static-load-rating", help="C0, e.g. '2227 N'.", rich_help_panel=_PANEL),
    ] = None,
    mu: Annotated[
        float | None,
        typer.Option(
            "--mu",
            help="Override of the handbook μ (0.0015 radial, 0.0020 angular).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    x0: Annotated[
        float | None,
        typer.Option(
            "--x0", help="Override of x0 (Table 1).", rich_help_panel="Handbook constants"
        ),
    ] = None,
    y0: Annotated[
        float | None,
        typer.Option(
            "--y0", help="Override of y0 (Table 1).", rich_help_panel="Handbook constants"
        ),
    ] = None,
    f: Annotated[
        float | None,
        typer.Option("--f", help="Override of f (Table 2).", rich_help_panel="Handbook constants"),
    ] = None,
    c: Annotated[
        float | None,
        typer.Option("--c", help="Override of c (Table 2).", rich_help_panel="Handbook constants"),
    ] = None,
    f0: Annotated[
        float | None,
        typer.Option(
            "--f0",
            help="Speed-term factor of T0 = f0·d_m³·n^(2/3) in N·mm⁻²·min^(2/3) (e.g. 2e-7; from `friction lab`, task 2).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    viscosity: Annotated[
        str | None,
        typer.Option(
            "--viscosity",
            help="Lubricant kinematic viscosity for --model palmgren, e.g. '20 cSt'.",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    palmgren_f0: Annotated[
        float | None,
        typer.Option(
            "--palmgren-f0",
            help="Palmgren's f0 (about 0.7-2 for deep-groove bearings) for --model palmgren.",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    lubrication: Annotated[
        str,
        typer.Option(
            "--lubrication",
            help="For --model skf: grease (default) | oil-air | oil-jet | oil-bath (with --oil-level, "
            "--drag-loss-factor).",
            rich_help_panel="Handbook constants",
        ),
    ] = "grease",
    oil: OilOpt = None,
    temperature: TemperatureOpt = None,
    viscosity_index: ViscosityIndexOpt = None,
    viscosity_100: Viscosity100Opt = None,
    oil_level: Annotated[
        str | None,
        typer.Option(
            "--oil-level",
            help="For --model skf --lubrication oil-bath: H from the lowest point of the outer raceway, "
            "e.g. '5 mm' (at most to the bearing's centre).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    drag_loss_factor: Annotated[
        float | None,
        typer.Option(
            "--drag-loss-factor",
            help="For --lubrication oil-bath: V_M read from SKF's drag loss diagram at H/d_m.",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    series: Annotated[
        str | None,
        typer.Option(
            "--series",
            help="For --model skf: the deep-groove series of SKF's constants, e.g. 62 (default: the "
            "bearing's series, else read from its designation).",
            rich_help_panel="Handbook constants",
        ),
    ] = None,
    json_out: JsonFlag = False,
):
    """Friction torque under combined load: the handbook models of the friction-rig lab (P0, T, T0 and T_F) or SKF's."""
    import numpy as np

    from .. import friction, tables
    from ..units import RPM
    if model not in _MODELS:
        raise InputError(f"model must be one of {list(_MODELS)}, got {model!r}")
    _check_constants(mu=mu, x0=x0, y0=y0, f=f, c=c, f0=f0, palmgren_f0=palmgren_f0)
    if model == "skf":
        b = resolve_bearing(bearing, bearing_file, catalog, contact_angle=contact_angle) if (
            bearing or bearing_file) else None
        if b is None:
            raise InputError("bearing: the skf model needs --bearing NAME or --bearing-file FILE (series, seals)")
        b = _skf_bearing(b, series)
        fr, fa, n = _cases(radial_load, axial_load, speed)
        _check_speed(b, n)
        _skf_torque(b, fr, fa, n, viscosity, lubrication, json_out,
                    oil=(oil, temperature, viscosity_index, viscosity_100), bath=(oil_level, drag_loss_factor))
        return
    if any(x is not None for x in (oil, temperature, viscosity_index, viscosity_100, oil_level, drag_loss_factor)):
        raise InputError("oil: --oil, --temperature, --viscosity-index, --viscosity-100, --oil-level and "
                         "--drag-loss-factor go with --model skf")
    if series is not None:
        raise InputError("series: only the skf model takes --series (SKF's geometry constants)")
    b = _friction_bearing(
        bearing,
        bearing_file,
        catalog,
        bearing_type,
        contact_angle,
        bore,
        outside_diameter,
        mean_diameter,
        static_load_rating,
    )
    fr, fa, n = _cases(radial_load, axial_load, speed)
    _check_speed(b, n)
    angle = b.contact_angle if b.type == "angular" else None
    if b.type == "angular" and angle is None and (x0 is None or y0 is None):
        raise InputError(
            "contact-angle: an angular-contact bearing needs --contact-angle (or --x0 and --y0)"
        )
    kw = {"bearing_type": b.type, "contact_angle": angle, "radial_factor": x0, "axial_factor": y0}
    p0 = np.atleast_1d(friction.equivalent_static_load(fr, fa, **kw))
    combined = np.atleast_1d(friction.combined_branch_governs(fr, fa, **kw))
    x0_used, y0_used = x0, y0
    if x0 is None or y0 is None:
        x_tab, y_tab = friction.static_load_factors(b.type, angle)
        x0_used = float(x_tab) if x0 is None else x0
        y0_used = float(y_tab) if y0 is None else y0
    info = {"bearing": b.designation, "type": b.type, "model": model, "x0": x0_used, "y0": y0_used}
    notes = _static_warnings(b, p0)
    if model == "one-term":
        speed_term, load_term = _one_term(b, p0, mu, info)
    else:
        speed_term, load_term = _two_term(b, model, angle, p0, n, f, c, f0, viscosity, palmgren_f0, info)
    total = speed_term + load_term
    rpm = tables.significant(n / RPM)  # a converted input shown without round-trip noise
    cases = [
        {
            "radial_load_N": float(fr[i]),
            "axial_load_N": float(fa[i]),
            "speed_rpm": float(rpm[i]),
            "equivalent_static_load_N": float(p0[i]),
            "branch": "x0*Fr+y0*Fa" if combined[i] else "Fr",
            "torque_Nmm": float(total[i] * 1e3),
            "torque_speed_term_Nmm": float(speed_term[i] * 1e3),
            "torque_load_term_Nmm": float(load_term[i] * 1e3),
        }
        for i in range(p0.size)
    ]
    echo = {"inputs": _echo(b, fr, fa, n, model=model, mu=mu, x0=x0, y0=y0, f=f, c=c, f0=f0,
                            viscosity_cSt=None if viscosity is None else _viscosity_cst(viscosity),
                            palmgren_f0=palmgren_f0), "warnings": notes}
    if json_out:
        emit_json({**info, **cases[0], **echo} if len(cases) == 1 else {**info, "cases": cases, **echo})
        return
    _print_torque(b, model, info, cases)
    print_warnings(notes)


_CONSTANT_UNITS = {"mu": "-", "x0": "-", "y0": "-", "f": "-", "c": "-", "f0": "N·mm⁻²·min^(2/3)", "palmgren_f0": "-"}


def _check_constants(**constants):
    """The handbook constants given: finite, and >= 0 but for the exponent c (the message names the option,
    not the library's parameter)."""
    import math

    for name, value in constants.items():
        if value is None:
            continue
        if not math.isfinite(value) or (name != "c" and value < 0):
            rule = "a finite number" if name == "c" else "a finite number >= 0"
            raise InputError(f"{name.replace('_', '-')} must be {rule} [{_CONSTANT_UNITS[name]}], got {value!r}")


def _check_speed(b, n):
    """The speed guard (d_m n), with the pitch diameter or the handbook's mean diameter, where known."""
    from .. import limits

    if speed_size(b) is not None:
        limits.check_speed(n, speed_size(b))


def _static_warnings(b, p0):
    """P0 of ISO 76 against C0 (bearinglab.limits), where the bearing has a static rating."""
    from .. import limits

    c0 = b.static_load_rating
    if c0 is None:
        try:
            from .. import ratings

            c0 = ratings.bearing_ratings(b).static_load_rating
        except (ValueError, ArithmeticError):  # no ball set to compute C0 from
            return []
    return limits.static_load_warnings(p0, c0)


def _viscosity_cst(text):
    return parse_viscosity(text) * 1e6


def _echo(b, fr, fa, n, **options):
    """The inputs as used (:func:`inputs_echo`): the bearing, the loads and speeds, the model's options."""
    from ..units import RPM

    one = fr.size == 1
    def value(x, scale=1.0):
        return float(x[0]) * scale if one else [v * scale for v in x.tolist()]

    return inputs_echo(b, radial_load_N=value(fr), axial_load_N=value(fa), speed_rpm=value(n, 1.0 / RPM),
                       **{k: v for k, v in options.items() if v is not None})


def _skf_bearing(b, series):
    """The bearing with its SKF series checked: the --series given, else the bearing's own, else the one
    its designation spells (:func:`bearinglab.friction.bearing_series`). An empty series is an error,
    never taken as 'not given'."""
    from .. import friction

    if b.type != "radial":  # angular contact: SKF's constants of the type (40 deg; others refused there)
        if series is not None:
            raise InputError(f"series: --series names SKF's deep-groove series; {b.designation!r} is {b.type}, "
                             f"whose constants are SKF's for its type")
        try:  # the model, not a field, is what does not apply (the web page leaves the section out)
            friction.angular_contact_constants(b.contact_angle)
        except InputError as exc:
            raise InputError(f"model: {exc}") from None
        return b
    known = list(friction.DEEP_GROOVE_CONSTANTS)
    for name, value in (("series", series), (f"series of {b.designation!r}", b.series)):
        if value is not None:
            if value.strip().upper() not in known:
                raise InputError(f"{name} must be one of {known} (SKF's deep-groove series), got {value!r}")
            return dataclasses.replace(b, series=value.strip().upper())
    try:
        friction.bearing_series(b.designation)
    except InputError as exc:
        raise InputError(f"series: {exc} (--series, e.g. --series 62)") from None
    return b


def _skf_torque(b, fr, fa, n, viscosity, lubrication, json_out, oil=(None,) * 4, bath=(None, None)):
    """The SKF four-term model (:func:`bearinglab.friction.skf_for_bearing`): moments, power loss, mu_sl."""
    from .. import friction, tables
    from ..units import RPM
    if viscosity is None and oil[0] is None:
        raise InputError("viscosity: the skf model needs --viscosity (e.g. '30 cSt'; of the base oil for grease), "
                         "or --oil VG68 with --temperature")
    nu = lubricant_viscosity(viscosity, *oil, required=True).viscosity
    kw = {}
    if lubrication == "oil-bath":
        if bath[0] is None or bath[1] is None:
            raise InputError("oil-level: --lubrication oil-bath needs --oil-level (e.g. '5 mm') and "
                             "--drag-loss-factor (V_M of SKF's diagram at H/d_m)")
        h = parse_length(bath[0], "oil-level", zero=True)
        dm = b.mean_diameter
        if h > dm / 2:
            raise InputError(f"oil-level must be <= d_m/2 = {dm / 2 * 1e3:g} mm [mm] (at most up to the bearing's "
                             f"centre), got {h * 1e3:g} mm")
        if not 0.0 <= bath[1] <= 1.0:
            raise InputError(f"drag-loss-factor must be in [0, 1] [-] (V_M of SKF's diagram), got {bath[1]:g}")
        kw = {"oil_level": h, "drag_loss_factor": bath[1]}
    elif bath[0] is not None or bath[1] is not None:
        raise InputError("oil-level: --oil-level and --drag-loss-factor go with --lubrication oil-bath")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the result returns its warnings (a seal moment left out)
        m = friction.skf_for_bearing(b, fr, fa, n, nu, lubrication=lubrication, **kw)  # checks the lubrication
    notes = [*m.warnings, *_skf_warnings(b, fr, fa)]
    moments = tables.rows(tables.skf_torque(m))
    rpm = tables.significant(n / RPM)
    cases = [{"radial_load_N": float(fr[i]), "axial_load_N": float(fa[i]), "speed_rpm": float(rpm[i]), **moments[i]}
             for i in range(len(moments))]
    info = {"bearing": b.designation, "type": b.type, "model": "skf", "lubrication": lubrication,
            "viscosity_cSt": float(tables.significant(nu * 1e6)[0])}
    echo = {"inputs": _echo(b, fr, fa, n, model="skf", lubrication=lubrication, viscosity_cSt=nu * 1e6),
            "warnings": notes}
    if json_out:
        emit_json({**info, **cases[0], **echo} if len(cases) == 1 else {**info, "cases": cases, **echo})
        return
    title = f"Friction torque of {b.designation} ({b.type}), SKF model, {lubrication}"
    caption = f"ν = {info['viscosity_cSt']:g} mm²/s; SKF {_skf_terms(m)}"
    inputs = ["F_r [N]", "F_a [N]", "n [rpm]"]
    parts = [("rolling_moment_Nmm", "M_rr"), ("sliding_moment_Nmm", "M_sl"), ("seal_moment_Nmm", "M_seal"),
             ("drag_moment_Nmm", "M_drag")]
    totals = [("total_moment_Nmm", "M [N·mm]", ".6g"), ("power_loss_W", "P [W]", ".6g"),
              ("sliding_friction_coefficient", "μ_sl", ".5f")]

    def given(r):
        return [f"{r['radial_load_N']:.6g}", f"{r['axial_load_N']:.6g}", f"{r['speed_rpm']:.6g}"]

    if len(cases) == 1:  # one case: every quantity on a line of its own (80 columns)
        r = cases[0]
        table(title, ["quantity", "value"],
              [*zip(inputs, given(r)), *((f"{name} [N·mm]", f"{r[k]:.6g}") for k, name in parts),
               *((name, f"{r[k]:{fmt}}") for k, name, fmt in totals)], caption=caption)
    else:  # several: the totals, then the four moments (two tables of 80 columns)
        table(title, [*inputs, *(name for _, name, _ in totals)],
              [[*given(r), *(f"{r[k]:{fmt}}" for k, _, fmt in totals)] for r in cases], caption=caption)
        table("The four moments [N·mm]", [*inputs, *(name for _, name in parts)],
              [[*given(r), *(f"{r[k]:.6g}" for k, _ in parts)] for r in cases])
    print_warnings(notes)


def _skf_terms(m):
    """The moments the SKF result holds, for the caption: the seal moment only where it was computed."""
    import numpy as np

    if np.any(np.asarray(m.seal_moment) > 0):  # the result says whether the model had seal data
        return "rolling, sliding, seal and drag moments"
    why = "not included, see the warnings" if m.warnings else "open bearing"
    return f"rolling, sliding and drag moments (no seal moment: {why})"


def _skf_warnings(b, fr, fa):
    """P0 of ISO 76 (from F_r, F_a) against C0, where the bearing has its ratings."""
    from .. import ratings

    try:
        angle = b.contact_angle or 0.0
        p0 = ratings.static_equivalent_load(fr, fa, angle, bearing_type=b.type)
    except (ValueError, ArithmeticError):  # an angle outside ISO 76's table: no P0
        return []
    return _static_warnings(b, p0)


def _cases(radial_load, axial_load, speed):
    """The radial loads, axial loads and speeds (SI), broadcast to one length."""
    import numpy as np
    fr = _case_values(radial_load, "force", "radial-load")
    fa = _case_values(axial_load, "force", "axial-load")
    n = parse_speeds(speed)
    sizes = {v.size for v in (fr, fa, n) if v.size > 1}
    if len(sizes) > 1:
        raise InputError(
            "radial-load, axial-load, speed: lists are paired element by element (rows of a log) and must "
            "have the same length, or one value"
        )
    return np.broadcast_arrays(fr, fa, n)


def _one_term(b, p0, mu, info):
    """Speed and load terms of the one-term model (the whole torque is the load term)."""
    import numpy as np

    from .. import friction
    d = b.require("bore")
    mu_used = friction.handbook_friction_coefficient(b.type) if mu is None else mu
    total = np.atleast_1d(friction.one_term(p0, d, bearing_type=b.type, reduced_friction_coefficient=mu))
    info.update({"mu": mu_used, "bore_mm": d * 1e3})
    return np.zeros_like(total), total  # one term, proportional to the load


def _two_term(b, model, angle, p0, n, f, c, f0, viscosity, palmgren_f0, info):
    """Speed and load terms of the two-term and the Palmgren model; the constants used go to ``info``."""
    import numpy as np

    from .. import friction
    dm = b.mean_diameter
    c0 = b.require("static_load_rating")
    f_used, c_used = f, c
    if f is None or c is None:
        f_tab, c_tab = friction.load_term_constants(b.type, angle)
        f_used = float(f_tab) if f is None else f
        c_used = float(c_tab) if c is None else c
    load_term = np.atleast_1d(
        friction.load_term(
            p0,
            dm,
            c0,
            bearing_type=b.type,
            contact_angle=angle,
            load_term_factor=f_used,
            load_term_exponent=c_used,
        )
    )
    if model == "two-term":
        if f0 is None:
            raise InputError(
                "f0: the two-term model needs --f0 [N·mm⁻²·min^(2/3)], e.g. 2e-7; it has no handbook "
                "value (measure it with `bearinglab friction lab`, task 2)"
            )
        speed_term = np.atleast_1d(friction.speed_term(n, dm, f0))
        info["f0"] = f0
    else:
        if viscosity is None or palmgren_f0 is None:
            raise InputError(
                "viscosity: the palmgren model needs --viscosity (e.g. '20 cSt') and --palmgren-f0 "
                "(e.g. 2)"
            )
        nu = parse_viscosity(viscosity)
        speed_term = np.atleast_1d(friction.palmgren(nu, n, dm, palmgren_f0))
        info.update(
            {
                "viscosity_cSt": nu * 1e6,
                "palmgren_f0": palmgren_f0,
                "equivalent_f0": float(
                    friction.speed_term_factor_from_palmgren(palmgren_f0, nu)
                ),
            }
        )
    info.update(
        {"f": f_used, "c": c_used, "mean_diameter_mm": dm * 1e3, "static_load_rating_N": c0}
    )
    return speed_term, load_term


def _print_torque(b, model, info, cases):
    """The torque table, with the constants used in the caption."""
    consts = ", ".join(
        f"{k} = {v:g}"
        for k, v in info.items()
        if isinstance(v, float) and not k.endswith(("_mm", "_N", "_cSt"))
    )
    table(
        f"Friction torque of {b.designation} ({b.type}), {model} model",
        [
            "F_r [N]",
            "F_a [N]",
            "n [rpm]",
            "P0 [N]",
            "branch",
            "T [N·mm]",
            "T0 [N·mm]",
            "T_F [N·mm]",
        ],
        [
            [
                f"{r['radial_load_N']:.6g}",
                f"{r['axial_load_N']:.6g}",
                f"{r['speed_rpm']:.6g}",
                f"{r['equivalent_static_load_N']:.6g}",
                r["branch"],
                f"{r['torque_Nmm']:.6g}",
                f"{r['torque_speed_term_Nmm']:.6g}",
                f"{r['torque_load_term_Nmm']:.6g}",
            ]
            for r in cases
        ],
        caption=consts + ("; the one-term model has no speed term" if model == "one-term" else ""),
    )


def lab(
    file: Annotated[
        Path,
        typer.Argument(help="Measurement-session file (TOML; see `bearinglab friction template`)."),
    ],
    out: Annotated[
        Path | None,
        typer.Option(
            "--out", "-o", help="Report directory (created; a previous report there is replaced)."
        ),
    ] = None,
    json_out: JsonFlag = False,
):
    """Reduce a session of the friction-rig lab: tasks 1-3, cross-checks, conclusions, and the HTML report."""
    from .. import report
    from ..lab import analysis, measurement

    if out is not None:
        check_output_directory(out, "out")
    session = measurement.read_session(file)
    result = analysis.analyse(session)
    files = report.write_report(result, out) if out is not None else None
    d = analysis.to_dict(result)
    if json_out:
        d["report"] = None if files is None else str(files.html)
        emit_json(d)
        return
    b = d["bearing"]
    console.print(
        f"[bold]Bearing {b['designation']}[/bold] ({b['type']}, d = {b['bore_mm']:g} mm, d_m = "
        f"{b['mean_diameter_mm']:g} mm, C0 = {b['static_load_rating_N']:g} N); {len(d['rows'])} rows from "
        f"{session.rows_source}"
    )
    if d["task1"]:
        table(
            "Task 1: μ (through the origin)",
            ["β [deg]", "n [rpm]", "μ", "± s.e.", "RMS [N·mm]", "μ/μ_hb − 1"],
            [
                [
                    f"{r['tilt_deg']:g}",
                    f"{r['speed_rpm']:.6g}",
                    f"{r['mu']:.6e}",
                    _se(r["mu_standard_error"]),
                    f"{r['residual_rms_Nmm']:.4e}",
                    f"{r['mu_relative_to_handbook']:+.1%}",
                ]
                for r in d["task1"]
            ],
        )
    if d["task2"]:
        table(
            "Task 2: f0 and T_F (f0 in N·mm⁻²·min^(2/3))",
            ["β [deg]", "Q [kg]", "f0", "± s.e.", "T_F [N·mm]", "± s.e.", "handbook T_F [N·mm]"],
            [
                [
                    f"{r['tilt_deg']:g}",
                    f"{r['mass_kg']:g}",
                    f"{r['f0']:.6e}",
                    _se(r["f0_standard_error"]),
                    f"{r['torque_load_term_Nmm']:.6e}",
                    _se(r["torque_load_term_standard_error_Nmm"]),
                    f"{r['handbook_torque_load_term_Nmm']:.4e}",
                ]
                for r in d["task2"]
            ],
        )
    if d["task3"]:
        table(
            "Task 3: f and T0",
            ["β [deg]", "n [rpm]", "f", "± s.e.", "T0 [N·mm]", "± s.e.", "f/f_hb − 1"],
            [
                [
                    f"{r['tilt_deg']:g}",
                    f"{r['speed_rpm']:.6g}",
                    f"{r['f']:.6e}",
                    _se(r["f_standard_error"]),
                    f"{r['torque_speed_term_Nmm']:.6e}",
                    _se(r["torque_speed_term_standard_error_Nmm"]),
                    f"{r['f_relative_to_handbook']:+.1%}",
                ]
                for r in d["task3"]
            ],
        )
    console.print("[bold]Conclusions[/bold]")
    for k, text in enumerate(d["conclusions"], start=1):
        console.print(f"{k}. {text}", highlight=False, markup=False)
    if files is None:
        console.print("No --out given: no report written.")
    else:
        console.print(f"Report: {files.html}", highlight=False, markup=False)


def _se(x):
    return "n/a" if x is None else f"{x:.2g}"


def template(
    file: Annotated[
        Path | None, typer.Argument(help="New session file to write (default: print on stdout).")
    ] = None,
    bearing: Annotated[
        str | None, typer.Option("--bearing", "-b", help="Catalog bearing to fill in, e.g. 18.")
    ] = None,
    force: Annotated[bool, typer.Option("--force", help="Replace an existing file.")] = False,
):
    """Write a blank, commented measurement-session file for a new session."""
    from ..lab import measurement

    if file is None or str(file) == "-":
        sys.stdout.write(measurement.template(bearing=bearing))
        return
    check_not_input(file, "file")  # not even with --force: the user catalog is an input
    path = measurement.write_template(file, bearing=bearing, overwrite=force)
    console.print(
        f"Wrote {path}. Fill in the bearing, the calibration tables and the rows, then run:\n"
        f"  bearinglab friction lab {path} --out {path.with_suffix('')}-report",
        highlight=False,
        markup=False,
    )


friction_app.command("torque")(torque)
friction_app.command("lab")(lab)
friction_app.command("template")(template)

#: The ``friction`` command group, as the application adds it.
COMMANDS = {"friction": friction_app}
