r"""A shaft system exported to ROSS (ross-rotordynamics): shaft elements, disks and bearing coefficients.

Export
------
ross_elements   the rotor as plain keyword arguments of ROSS's elements (no ROSS needed)
to_ross         the ``ross.Rotor`` itself (imports ROSS, the optional ``ross`` extra)

Each element of the mesh becomes a ``ross.ShaftElement`` (Timoshenko, shear after Cowper, rotary
inertia and gyroscopic terms: the same matrices as :mod:`bearinglab.shaft.elements`), each gear, pulley
and mass with an inertia a ``ross.DiskElement``, each bearing (every bearing of a set on its own node)
a ``ross.BearingElement`` with bearinglab's coefficients over a table of speeds: the system solved at
each speed, each bearing's tangent stiffness at its operating point in series with its housing, turned
into the shaft's frame (:func:`bearinglab.quasistatic.rotordynamics.from_stiffness`; the keyword of the
speed table follows the installed ROSS). A linear support becomes a BearingElement of its radial and
axial stiffness.

What ROSS cannot hold is left out and named in the warnings: a BearingElement has translational
coefficients only, so a bearing's tilt stiffness and force-tilt couplings, and a linear support's tilt
stiffness, are lost (they matter for short spindles and preloaded angular-contact sets, see
:mod:`bearinglab.quasistatic.rotordynamics`); a rigid support becomes a spring of 1e12 N/m; the
housing's tilt springs act only through the bearing's condensed translational stiffness.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .model import LinearSupport, RigidSupport

__all__ = ["ross_elements", "to_ross"]

_RIGID = 1e12  # N/m: a rigid support as a ROSS bearing


def ross_elements(state, speeds=None):
    """The rotor of a solved shaft system as keyword arguments of ROSS's elements.

    Parameters
    ----------
    state : SystemState
        A solution (:func:`bearinglab.shaft.solve`) whose cases are the speeds of the table, strictly
        increasing (:func:`bearinglab.shaft.load_cases` with ``speed=...``), or one case.
    speeds : array_like, optional
        Ignored unless given to check that they are the state's case speeds. [rad/s]

    Returns
    -------
    dict
        ``material`` (name, rho, E, Poisson), ``shaft`` (list of ShaftElement keyword arguments with ``n``),
        ``disks`` (DiskElement keywords), ``bearings`` (BearingElement keywords, each with its ``n``) and
        ``warnings``.
    """
    from ..quasistatic.rotordynamics import from_stiffness
    from .mesh import node_of
    from .outputs import _series

    asm = state.assembly
    system, mesh = asm.system, asm.mesh
    w = np.abs(np.asarray(state.cases.speed, dtype=float))
    if speeds is not None and not np.allclose(np.abs(np.asarray(speeds, dtype=float)), w):
        raise InputError("speeds must be the speeds of the state's load cases")
    if not np.all(np.isfinite(state.row_stiffness)):
        raise InputError("a load case did not converge: it has no bearing coefficients")
    mat = system.shaft.material
    out = {"material": {"name": "shaft_steel" if "steel" in mat.name else "shaft_material",
                        "rho": mat.density, "E": mat.elastic_modulus, "Poisson": mat.poisson_ratio},
           "shaft": [], "disks": [], "bearings": [], "warnings": []}
    for e in range(len(mesh.z) - 1):
        out["shaft"].append({"n": e, "L": float(mesh.z[e + 1] - mesh.z[e]), "idl": float(mesh.bore[e]),
                             "odl": float(mesh.diameter[e]), "idr": float(mesh.bore[e]),
                             "odr": float(mesh.diameter[e]), "shear_effects": True, "rotary_inertia": True,
                             "gyroscopic": True, "shear_method_calc": "cowper"})
    for item in (*system.gears, *system.pulleys, *system.masses):
        if item.mass > 0 or item.polar_inertia > 0:
            ip = float(item.polar_inertia)
            idd = 0.5 * ip if item.diametral_inertia is None else float(item.diametral_inertia)
            out["disks"].append({"n": node_of(mesh.z, item.position), "m": float(item.mass), "Id": idd, "Ip": ip})
    tilt = False
    for j, r in enumerate(asm.rows):
        t = r.transform
        k = np.array([_series(state.row_stiffness[c, j] * (t[:, None] * t[None, :]), r.housing) for c in range(len(w))])
        tilt |= bool(np.any(np.abs(k[:, 3:, 3:]) > 0))
        coeffs = from_stiffness(k, w) if len(w) > 1 else {key: v[0] for key, v in from_stiffness(k, w).items()
                                                          if key not in ("speed", "frequency")}
        out["bearings"].append({"n": r.node, "tag": r.name, **coeffs})
    if tilt:
        out["warnings"].append("ROSS's BearingElement has no tilt stiffness: the bearings' tilt stiffness and "
                               "force-tilt couplings are left out of the exported rotor")
    for s in system.supports:
        if isinstance(s, LinearSupport):
            n = node_of(mesh.z, s.position)
            out["bearings"].append({"n": n, "tag": s.name, "kxx": s.radial_stiffness, "kyy": s.radial_stiffness,
                                    "kzz": s.axial_stiffness or 0.0, "cxx": 0.0, "cyy": 0.0})
            if s.tilt_stiffness > 0:
                out["warnings"].append(f"{s.name}: its tilt stiffness is left out (ROSS's BearingElement has none)")
        elif isinstance(s, RigidSupport):
            n = node_of(mesh.z, s.position)
            out["bearings"].append({"n": n, "tag": s.name, "kxx": _RIGID, "kyy": _RIGID,
                                    "kzz": _RIGID if s.axial else 0.0, "cxx": 0.0, "cyy": 0.0})
            out["warnings"].append(f"{s.name}: a rigid support is exported as a spring of {_RIGID:g} N/m")
    return out


def to_ross(state, speeds=None):
    """The ``ross.Rotor`` of a solved shaft system, with bearinglab's speed-dependent bearing coefficients.

    Parameters
    ----------
    state : SystemState
        See :func:`ross_elements`.
    speeds : array_like, optional
        See :func:`ross_elements`.

    Returns
    -------
    ross.Rotor
        Needs the ``ross`` extra (ross-rotordynamics); the export's warnings are raised as UserWarning.
    """
    import warnings

    try:
        import ross
    except ImportError as exc:  # pragma: no cover - the extra is installed in the tests
        raise InputError("to_ross needs ROSS: pip install 'bearinglab[ross]'") from exc
    data = ross_elements(state, speeds)
    for note in data["warnings"]:
        warnings.warn(note, UserWarning, stacklevel=2)
    m = data["material"]
    material = ross.Material(name=m["name"], rho=m["rho"], E=m["E"], Poisson=m["Poisson"])
    shaft = [ross.ShaftElement(material=material, **{k: v for k, v in e.items() if k != "n"}, n=e["n"])
             for e in data["shaft"]]
    disks = [ross.DiskElement(**d) for d in data["disks"]]
    bearings = [ross.BearingElement(**b) for b in data["bearings"]]
    return ross.Rotor(shaft, disks, bearings)
