"""BicycleParameters' ``MooreRiderLean2012`` parameter set, both ways.

Moore (2012, PhD thesis UC Davis, "Leaning rider extension"; BicycleParameters'
``MooreRiderLean2012ParameterSet``) describes the same five bodies in his own frames: the rear frame
C and the fork E in axes pitched by the steer-axis tilt ``lam`` (``c3`` along the steer axis), the
geometry by the offsets ``d1`` (rear wheel centre to the steer axis), ``d2`` (along the steer axis
between the two offset lines), ``d3`` (fork offset), the centres of mass by ``l1, l2`` (C, from the
rear wheel centre along ``c1, c3``), ``l3, l4`` (E, from the front wheel centre along ``e1, e3``) and
``l5, l6`` (the upper body G, from the hip axis point ``d4`` below the rear wheel centre, along the
horizontal ``g1`` and the vertical ``g3``), inertias as tensor elements in those axes (``ic31`` is
``I_C13``), the lean joint's ``k9`` and ``c9``, and the speed ``v``.  The conversions are exact
(closed form both ways; ``lam`` follows from ``d1, d2, d3, rr, rf`` by the front wheel touching the
ground, solved in closed form).
"""

import math

import numpy as np
import yaml

from ..core.errors import InputError
from .parameters import BenchmarkParameters
from .family import build
from .registry import model_of
from .members.rider_lean.parameters import LeanJoint, RiderLeanParameters, UpperBody

PARAMETERIZATION = "MooreRiderLean2012"
"""The name BicycleParameters gives the set (``ParameterSet.parameterization``)."""
NAMES = ("c9", "d1", "d2", "d3", "d4", "g", "ic11", "ic22", "ic31", "ic33", "id11", "id22", "ie11", "ie22",
         "ie31", "ie33", "if11", "if22", "ig11", "ig22", "ig31", "ig33", "k9", "l1", "l2", "l3", "l4", "l5",
         "l6", "mc", "md", "me", "mf", "mg", "rf", "rr", "v")
"""The set's 37 names (``MooreRiderLean2012ParameterSet.par_strings``), alphabetical as it orders them."""


def _pitched(lam):
    """Columns: the pitched axes ``c1, c2, c3`` in benchmark coordinates (``c3`` along the steer axis)."""
    s, c = math.sin(lam), math.cos(lam)
    return np.array([[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]])


def _tensor(xx, yy, zz, xz):
    return np.array([[xx, 0.0, xz], [0.0, yy, 0.0], [xz, 0.0, zz]])


def to_moore_values(lean: RiderLeanParameters, speed: float = 1.0) -> dict:
    """``{name: float}`` of the ``MooreRiderLean2012`` set of ``lean`` at forward ``speed`` (m/s; the
    set carries a default speed, ``v``)."""
    b, u, j = lean.bicycle, lean.upper, lean.joint
    lam, s, c = b.lam, math.sin(b.lam), math.cos(b.lam)
    R = _pitched(lam)
    d1 = c * (b.c + b.w - b.rR * math.tan(lam))
    d3 = -c * (b.c - b.rF * math.tan(lam))
    IC = R.T @ _tensor(b.IBxx, b.IByy, b.IBzz, b.IBxz) @ R
    IE = R.T @ _tensor(b.IHxx, b.IHyy, b.IHzz, b.IHxz) @ R
    rear = np.array([b.xB, 0.0, b.zB + b.rR]) @ R            # from the rear wheel centre, in C axes
    front = np.array([b.xH - b.w, 0.0, b.zH + b.rF]) @ R      # from the front wheel centre, in E axes
    out = {
        "c9": j.damping, "d1": d1, "d2": (b.rR - b.rF + (d1 + d3) * s) / c, "d3": d3, "d4": u.hip_z + b.rR,
        "g": b.g, "ic11": IC[0, 0], "ic22": IC[1, 1], "ic31": IC[2, 0], "ic33": IC[2, 2],
        "id11": b.IRxx, "id22": b.IRyy, "ie11": IE[0, 0], "ie22": IE[1, 1], "ie31": IE[2, 0], "ie33": IE[2, 2],
        "if11": b.IFxx, "if22": b.IFyy, "ig11": u.Ixx, "ig22": u.Iyy, "ig31": u.Ixz, "ig33": u.Izz,
        "k9": j.stiffness, "l1": rear[0], "l2": rear[2], "l3": front[0], "l4": front[2],
        "l5": u.x, "l6": u.z - u.hip_z, "mc": b.mB, "md": b.mR, "me": b.mH, "mf": b.mF, "mg": u.mass,
        "rf": b.rF, "rr": b.rR, "v": speed,
    }
    return {k: float(out[k]) for k in NAMES}


def moore_yaml(lean: RiderLeanParameters, speed: float = 1.0) -> str:
    """The YAML text that BicycleParameters' ``ParameterSet.to_yaml`` writes for the set of ``lean``
    (keys ``description, parameterization, parameters, rider, values``; every float exact)."""
    data = {"description": "", "parameterization": PARAMETERIZATION, "parameters": "", "rider": None,
            "values": to_moore_values(lean, speed)}
    return yaml.safe_dump(data, sort_keys=True)


def _steer_tilt(d1, d2, d3, rr, rf):
    """The steer-axis tilt (rad) at which the front wheel touches the ground, upright and straight:
    ``d2 cos(lam) - (d1 + d3) sin(lam) = rr - rf``."""
    r = math.hypot(d2, d1 + d3)
    if not abs(rr - rf) < r:
        raise ValueError("no pitch puts the front wheel on the ground")
    return math.acos((rr - rf) / r) - math.atan2(d1 + d3, d2)


def from_moore_values(values, source="values") -> RiderLeanParameters:
    """:class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` of a ``MooreRiderLean2012`` values mapping
    (``{name: float}``, the ``values:`` of BicycleParameters' YAML; ``v`` may be left out: the model does
    not need it); :class:`~bikemass.core.errors.InputError` naming ``source`` and the key otherwise."""
    if not hasattr(values, "keys"):
        raise InputError(source, "values", f"a mapping of the {PARAMETERIZATION} parameters")
    unknown = sorted(set(values) - set(NAMES))
    if unknown:
        raise InputError(source, f"values.{unknown[0]}", f"no such parameter in {PARAMETERIZATION} "
                         f"(names: {', '.join(NAMES)})")
    p = {}
    for name in NAMES:
        if name == "v" and name not in values:
            continue
        if name not in values:
            raise InputError(source, f"values.{name}", "a required parameter that is missing")
        x = values[name]
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
            raise InputError(source, f"values.{name}", f"a finite number, got {x!r}")
        p[name] = float(x)
    for name in ("g", "rf", "rr", "mc", "md", "me", "mf", "mg"):
        if not p[name] > 0:
            raise InputError(source, f"values.{name}", f"a positive number, got {p[name]!r}")
    try:
        lam = _steer_tilt(p["d1"], p["d2"], p["d3"], p["rr"], p["rf"])
    except ValueError as exc:
        raise InputError(source, "values", f"d1, d2, d3, rf, rr of a bicycle whose front wheel reaches the "
                         f"ground ({exc})") from None
    c = math.cos(lam)
    R = _pitched(lam)
    trail = p["rf"] * math.tan(lam) - p["d3"] / c
    w = p["d1"] / c + p["rr"] * math.tan(lam) - trail
    xB, _, zB = (float(x) for x in R @ [p["l1"], 0.0, p["l2"]])
    xH, _, zH = (float(x) for x in R @ [p["l3"], 0.0, p["l4"]])
    IB = (R @ _tensor(p["ic11"], p["ic22"], p["ic33"], p["ic31"]) @ R.T).tolist()
    IH = (R @ _tensor(p["ie11"], p["ie22"], p["ie33"], p["ie31"]) @ R.T).tolist()
    bicycle = BenchmarkParameters(
        w=w, c=trail, lam=lam, g=p["g"], rR=p["rr"], mR=p["md"], IRxx=p["id11"], IRyy=p["id22"],
        xB=xB, zB=zB - p["rr"], mB=p["mc"], IBxx=IB[0][0], IByy=IB[1][1], IBzz=IB[2][2], IBxz=IB[0][2],
        xH=w + xH, zH=zH - p["rf"], mH=p["me"], IHxx=IH[0][0], IHyy=IH[1][1], IHzz=IH[2][2], IHxz=IH[0][2],
        rF=p["rf"], mF=p["mf"], IFxx=p["if11"], IFyy=p["if22"])
    hip_z = p["d4"] - p["rr"]
    upper = UpperBody(mass=p["mg"], x=p["l5"], z=hip_z + p["l6"], Ixx=p["ig11"], Iyy=p["ig22"],
                      Izz=p["ig33"], Ixz=p["ig31"], hip_z=hip_z)
    return RiderLeanParameters(bicycle, upper, LeanJoint(stiffness=p["k9"], damping=p["c9"]))


def moore_linear_model(values, model=None, tyres=None, source="values"):
    """The :class:`~bikemass.models.linear.LinearModel` of ``model`` (default the set's own member, the
    leaning rider; any combination, see :func:`~bikemass.models.family.build`) from a
    ``MooreRiderLean2012`` values mapping (see :func:`from_moore_values`)."""
    subject = from_moore_values(values, source)
    return build(model_of(subject, model), subject, tyres=tyres)
