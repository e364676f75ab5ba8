r"""The supports of a shaft system as the solver sees them: bearing rows, springs and constraints.

Bearings
--------
BearingRow             one bearing between a shaft node and its housing: frame, preload offset, seat springs
bearing_rows           every bearing of the supports (a set gives one row per bearing), with their offsets
first_contact_offset   the axial offset at which a bearing's rolling elements first touch
axial_displacement     the axial displacement of a bearing under a thrust (for a force preload)

Linear supports
---------------
linear_springs         the springs to the ground of the linear supports, as (dof, stiffness) pairs
constrained_dofs       the degrees of freedom held at zero (rigid supports, the torsion reference)

A bearing enters the system with its own frame (:mod:`bearinglab.reactions`): the relative displacement
of its inner ring (on the shaft node) to its outer ring (on the housing), d = T (u_shaft - u_housing) +
(0, 0, o, 0, 0), with T = diag(1, 1, s, s, s) for the orientation s (the mirror z -> -z of
:mod:`bearinglab.quasistatic.sets`) and o its axial offset: where it sits in its own axial play.

- An angular-contact bearing sits at first contact, o = A sin(alpha0) ([1]_), plus the ``axial_offset``
  given (a shim: > 0 preloads it against an opposed bearing); a set's bearings as ``bearing-set`` puts
  them, first contact plus half the interference, or the offset of each bearing under its group's share
  of a preload force.
- A deep-groove bearing sits centred in its axial play, o = ``axial_offset`` (default 0).
- With the shaft and housing temperatures, the inner ring moves by alpha_s (T_s - 20 degC) z along the
  shaft and the outer ring by alpha_h (T_h - 20 degC) z along the housing (both from z = 0; a common
  shift is taken up by the shaft's axial displacement), so o grows by s (alpha_s dT_s - alpha_h dT_h) z: a
  DB pair L apart loses (alpha_s dT_s - alpha_h dT_h) L of interference, as
  :func:`bearinglab.mounting.preload.operating_interference` has it; and each bearing's diametral
  clearance follows the mounting chain (:func:`bearinglab.mounting.chain.operating_clearance`, no fit
  interference, the ring temperatures those of shaft and housing, at the system's speed).
- A floating bearing (``axial`` False) slides in its housing: its housing's axial freedom carries no
  spring, so the bearing carries no thrust.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, *Essential Concepts of Bearing Technology*, 5th ed., CRC Press,
   2006, ch. 2 (end play of a ball bearing with diametral clearance).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..bearing import BallBearing
from ..errors import ConvergenceError, InputError
from .mesh import node_of
from .model import BearingSetSupport, BearingSupport, LinearSupport, RigidSupport

__all__ = ["BearingRow", "axial_displacement", "bearing_rows", "constrained_dofs", "first_contact_offset",
           "linear_springs"]

_MIRROR = np.array([1.0, 1.0, -1.0, -1.0, -1.0])
_REFERENCE_TEMPERATURE = 293.15  # 20 degC, bearinglab.mounting.thermal.REFERENCE_TEMPERATURE


class BearingRow(NamedTuple):
    """One bearing of the system, between a shaft node and its housing."""

    support: int
    """Index of its support in ``ShaftSystem.supports``."""
    name: str
    """The support's name (a set's bearings: the name and the bearing's index)."""
    bearing: BallBearing
    """The bearing, at its operating clearance."""
    position: float
    """z of its centre. [m]"""
    orientation: int
    """+1 or -1 (see :class:`~bearinglab.shaft.model.BearingSupport`)."""
    offset: float
    """o, the axial offset in its own frame at zero shaft displacement. [m]"""
    housing: np.ndarray
    """(5,) seat springs in series (inf: rigid; 0: free, the axial freedom of a floating bearing)."""
    node: int
    """The shaft node it sits on."""

    @property
    def transform(self):
        """(5,) the diagonal of T (own frame from the shaft frame)."""
        return _MIRROR.copy() if self.orientation < 0 else np.ones(5)


def first_contact_offset(bearing):
    """The axial offset of the ring centres at which a bearing's rolling elements first touch.

    Parameters
    ----------
    bearing : BallBearing

    Returns
    -------
    float
        A sin(alpha0), A = (f_i + f_o - 1) D (:func:`bearinglab.quasistatic.combined.axial_play_takeup`);
        0 for a bearing without clearance. [m]
    """
    from ..quasistatic import combined

    if bearing.type in ("four-point", "double-row-angular", "double-row-radial", "self-aligning", "thrust"):
        return float(combined._takeup(bearing))  # their own first contact (issue 30)
    if bearing.contact_angle is None or bearing.contact_angle == 0:
        return 0.0
    d, fi, fo = bearing.require("ball_diameter", "inner_conformity", "outer_conformity")
    return float(combined.axial_play_takeup(d, fi, fo, bearing.contact_angle))


def axial_displacement(bearing, thrust, *, shaft_speed=0.0, tol=1e-12, max_iter=100):
    r"""The axial displacement of a bearing's inner ring under a thrust alone (its own frame).

    Parameters
    ----------
    bearing : BallBearing
    thrust : float
        F_z > 0 on the inner ring. [N]
    shaft_speed : float, optional
        [rad/s]
    tol : float, optional
        Relative residual of the thrust. [-]
    max_iter : int, optional

    Returns
    -------
    float
        delta_z from the concentric position. [m]

    Notes
    -----
    Newton on F_z(delta_z) = thrust through :func:`bearinglab.reactions.bearing_reactions`, from a
    displacement past the solution (the thrust grows with delta_z and is convex beyond first contact, so
    the iterates fall monotonically onto the root). This is how each bearing of a set takes its share
    of a preload force (as :func:`bearinglab.quasistatic.sets.set_analysis` does it).
    """
    from ..reactions import bearing_reactions

    f = float(thrust)
    if not f > 0:
        raise InputError(f"thrust must be > 0 [N], got {f!r}")
    z0 = first_contact_offset(bearing)
    step = 1e-6 * max(bearing.pitch_diameter or 0.05, 1e-3) / 0.05  # 1 um for a 50 mm bearing
    dz = z0 + step
    for _ in range(200):  # past the root
        r = bearing_reactions(bearing, [0.0, 0.0, dz, 0.0, 0.0], shaft_speed)
        if r.force[2] >= f:
            break
        step *= 2.0
        dz = z0 + step
    else:
        raise ConvergenceError("shaft.axial_displacement", iterations=200, residual=np.nan, estimate=dz,
                               reason=f"no displacement gives the thrust {f:g} N")
    for it in range(1, max_iter + 1):
        r = bearing_reactions(bearing, [0.0, 0.0, dz, 0.0, 0.0], shaft_speed)
        res = r.force[2] - f
        if abs(res) <= tol * f:
            return float(dz)
        dz = max(dz - res / r.stiffness[2, 2], z0 + 0.5 * (dz - z0))
    raise ConvergenceError("shaft.axial_displacement", iterations=max_iter, residual=abs(res) / f, estimate=dz)


def _housing(support, axial):
    k = np.full(5, np.inf) if support.housing is None else support.housing.diagonal
    if not axial:
        k[2] = 0.0  # floating: the outer ring slides in its seat
    return k


def _set_offsets(members, preload, preload_offset, speed):
    """Each bearing's axial offset in its own frame, as quasistatic.sets assembles a set."""
    orient = np.array([o for _, _, o in members])
    opposed = not np.all(orient == orient[0])
    touch = np.array([first_contact_offset(b) if opposed else 0.0 for b, _, _ in members])
    if preload_offset is not None:
        if preload_offset != 0 and not opposed:
            raise InputError("preload_offset: a set without opposed bearings (tandem) has nothing to preload against")
        return touch + 0.5 * preload_offset
    if not preload:
        return touch
    if not opposed:
        raise InputError("preload: a tandem set has no opposed bearing to preload against")
    return np.array([axial_displacement(b, preload / np.sum(orient == o)) for b, _, o in members])


def _operating_bearing(bearing, system, seat_bore, name):
    """The bearing at the clearance the mounting chain gives for the system's temperatures."""
    from ..mounting import chain, materials

    if system.shaft_temperature is None and system.housing_temperature is None:
        return bearing, []
    if bearing.radial_clearance is None or bearing.bore is None or bearing.outside_diameter is None:
        note = (f"{name}: the temperatures do not change the clearance of {bearing.designation} (its bore, "
                "outside diameter and clearance are needed by the mounting chain)")
        return bearing, [note]
    t_s = system.shaft_temperature or _REFERENCE_TEMPERATURE
    t_h = system.housing_temperature or _REFERENCE_TEMPERATURE
    mat = system.shaft.material
    shaft = materials.MountingMaterial(mat.name, mat.elastic_modulus, mat.poisson_ratio, mat.density,
                                       system.shaft.thermal_expansion, "the shaft's material")
    m = chain.mounting_of(bearing, shaft_bore=min(seat_bore, 0.999 * bearing.bore), shaft_material=shaft,
                          housing_material=materials.material(system.housing_material))
    r = chain.operating_clearance(bearing.radial_clearance, 0.0, 0.0, m,
                                  chain.Conditions(inner_temperature=t_s, outer_temperature=t_h,
                                                   speed=abs(system.speed)))
    e = float(r.operating_clearance)
    if not e > 0:
        raise InputError(f"shaft_temperature: the temperatures take all the clearance of {name} "
                         f"({bearing.designation}: {e * 1e6:.3g} um left), a radial preload this model does not "
                         "take; lower the difference of shaft and housing temperature")
    return bearing.replace(radial_clearance=e), []


def bearing_rows(system, mesh):
    """Every bearing of a shaft system, one row per bearing, with its node, frame, offset and seat.

    Parameters
    ----------
    system : ShaftSystem
    mesh : Mesh

    Returns
    -------
    rows : list of BearingRow
    notes : list of str
        Warnings (a bearing whose clearance the temperatures cannot change, its seat's bore against its
        bore).
    """
    rows, notes = [], []
    thermal = system.shaft_temperature is not None or system.housing_temperature is not None
    if thermal:
        from ..mounting import materials

        a_s = system.shaft.thermal_expansion
        a_h = materials.material(system.housing_material).thermal_expansion
        d_s = (system.shaft_temperature or _REFERENCE_TEMPERATURE) - _REFERENCE_TEMPERATURE
        d_h = (system.housing_temperature or _REFERENCE_TEMPERATURE) - _REFERENCE_TEMPERATURE
        growth = a_s * d_s - a_h * d_h  # relative axial growth per metre of z [-]
    else:
        growth = 0.0
    secs = system.shaft.sections
    for k, s in enumerate(system.supports):
        if isinstance(s, BearingSupport):
            members = [(s.bearing, s.position, s.orientation)]
            angular = s.bearing.type == "angular"
            offsets = [(first_contact_offset(s.bearing) if angular else 0.0) + s.axial_offset]
            names = [s.name]
        elif isinstance(s, BearingSetSupport):
            members = s.rows()
            offsets = list(_set_offsets(members, s.preload, s.preload_offset, system.speed))
            names = [f"{s.name}[{j}]" for j in range(len(members))]
        else:
            continue
        for (b, z, o), off, name in zip(members, offsets, names, strict=True):
            seat = secs[system.shaft.section_at(z)]
            if b.bore is not None and abs(seat.diameter - b.bore) > 0.5e-3:
                notes.append(f"{name}: the seat's diameter {seat.diameter * 1e3:g} mm differs from the bore "
                             f"{b.bore * 1e3:g} mm of {b.designation}")
            b_op, more = _operating_bearing(b, system, seat.bore, name)
            notes += more
            off = off + o * growth * z
            rows.append(BearingRow(k, name, b_op, float(z), int(o), float(off), _housing(s, s.axial),
                                   node_of(mesh.z, z)))
    return rows, notes


def linear_springs(system, mesh):
    """The springs of the linear supports: (global dof, stiffness) pairs.

    Parameters
    ----------
    system : ShaftSystem
    mesh : Mesh

    Returns
    -------
    list of tuple
        (dof index, k) with k in N/m or N m/rad.
    """
    out = []
    for s in system.supports:
        if isinstance(s, LinearSupport):
            i = 6 * node_of(mesh.z, s.position)
            out += [(i, s.radial_stiffness), (i + 1, s.radial_stiffness)]
            if s.axial_stiffness is not None:
                out.append((i + 2, s.axial_stiffness))
            if s.tilt_stiffness > 0:
                out += [(i + 3, s.tilt_stiffness), (i + 4, s.tilt_stiffness)]
    return out


def constrained_dofs(system, mesh):
    """The degrees of freedom held at zero: rigid supports and the torsion reference (node 0's theta_z).

    Parameters
    ----------
    system : ShaftSystem
    mesh : Mesh

    Returns
    -------
    list of int
        Global dof indices, sorted.

    Notes
    -----
    Nothing holds the shaft in torsion (the bearings carry no torque): the torques on it balance
    (checked by :class:`~bearinglab.shaft.model.ShaftSystem`), and the twist is counted from the left
    end. A linear support that locates axially without its own stiffness holds u_z rigidly.
    """
    out = {5}
    for s in system.supports:
        i = 6 * node_of(mesh.z, s.position)
        if isinstance(s, RigidSupport):
            out |= {i, i + 1} | ({i + 2} if s.axial else set())
        elif isinstance(s, LinearSupport) and s.axial and s.axial_stiffness is None:
            out.add(i + 2)
    return sorted(out)
