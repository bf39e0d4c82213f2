"""Benchmark parameter sets as text: YAML, JSON, a table, CSV, or the BicycleParameters file.

YAML and JSON hold the 26 Meijaard names (SI, radians), a ``units`` block, and
``rider_included: true`` when the rear body B holds a rider, so the output is itself a
benchmark parameter file that bikemass reads back (and refuses to add a second rider to).  The
``bicycleparameters`` format is the ``<Name>Benchmark.txt`` file that the
BicycleParameters package reads from ``bicycles/<Name>/Parameters/``: one
``name = value`` line per parameter, ``#`` comment lines allowed.  Values are
written with ``repr`` (17 significant digits) so they read back bit for bit (below
:data:`bikemass.core.output.ZERO` as 0, like every number bikemass writes).  The
``bicycleparameters-yaml`` format is what BicycleParameters' ``ParameterSet.to_yaml`` writes
(``parameterization: Meijaard2007`` with ``values:``; the rider-lean model's
``MooreRiderLean2012`` set is :func:`bikemass.models.moore2012.moore_yaml`).
"""

import yaml


from ..core.choices import PARAMETER_FORMATS as FORMATS
from ..core.errors import InputError
from ..core.output import as_written, dumps, table, with_units
from .parameters import DESCRIPTIONS, NAMES, parameter_units
from .plausibility import EN15194_FRONT_SHARE, front_load


def format_parameters(params, fmt, title="", rider_included=False, std=None):
    """Text of ``params`` (:class:`~bikemass.models.parameters.BenchmarkParameters`) in ``fmt``;
    ``rider_included``: the rear body B holds a rider; ``std``: a measured set's standard deviations
    (``{name: SI}``), written as an ``uncertainty:`` block (YAML, JSON: what bikemass reads back), a
    std column (table, CSV) or ``value+/-std`` (``bicycleparameters``)."""
    values = params.to_dict()
    std = {k: float(v) for k, v in (std or {}).items() if v > 0}
    if fmt in ("yaml", "json"):
        block = {"uncertainty": {k: std[k] for k in NAMES if k in std}} if std else {}
        return dumps(with_units({**values, **({"rider_included": True} if rider_included else {}), **block},
                                parameter_units()), fmt)
    if fmt == "bicycleparameters":
        return bicycleparameters_text(params, title + (" (rider included in B)" if rider_included else ""), std)
    if fmt == "bicycleparameters-yaml":
        return meijaard_yaml(params, rider_included=rider_included)
    units = parameter_units()
    if fmt == "table":
        rows = [[k, DESCRIPTIONS[k].split(" [")[0], values[k], *([std.get(k, 0.0)] if std else []), units[k]]
                for k in NAMES]
        text = (f"{title}\n" if title else "") + table(["parameter", "meaning", "value", *(["std"] if std else []),
                                                         "unit"], rows, "{:.6g}")
        share, kg = front_load(params)
        verdict = ("" if not rider_included else "meets" if share >= EN15194_FRONT_SHARE else "BELOW")
        rule = f" ({verdict} EN 15194: at least {EN15194_FRONT_SHARE * 100:.0f} % with the rider seated)" if verdict else ""
        return text.rstrip("\n") + f"\nfront wheel load: {share * 100:.1f} % of the weight ({kg:.2f} kg){rule}\n"
    if fmt == "csv":
        if std:
            return "parameter,value,std,unit\n" + "".join(
                f"{k},{as_written(values[k], units[k])!r},{std.get(k, 0.0)!r},{units[k]}\n" for k in NAMES)
        return "parameter,value,unit\n" + "".join(f"{k},{as_written(values[k], units[k])!r},{units[k]}\n"
                                                    for k in NAMES)
    raise InputError("format", fmt, f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")


def bicycleparameters_text(params, title="", std=None):
    """The BicycleParameters ``<Name>Benchmark.txt`` text (no blank lines: its reader rejects them);
    ``std``: ``value+/-std`` where a standard deviation is given (as BicycleParameters writes them)."""
    values, units, std = params.to_dict(), parameter_units(), std or {}
    header = [f"# {line}" for line in (title, "written by bikemass; SI units, radians") if line]
    return "\n".join(header + [f"{name} = {as_written(values[name], units[name])!r}"
                                + (f"+/-{std[name]!r}" if std.get(name) else "") for name in NAMES]) + "\n"


MEIJAARD = "Meijaard2007"
"""The name BicycleParameters gives the benchmark set (``ParameterSet.parameterization``)."""


def meijaard_yaml(params, speed=1.0, rider_included=False):
    """The YAML text BicycleParameters' ``ParameterSet.to_yaml`` writes for the ``Meijaard2007`` set of
    ``params`` at forward ``speed`` (m/s; the set carries a default speed, ``v``); ``rider: true`` when
    the rear body B holds a rider."""
    values = {name: float(getattr(params, name)) for name in NAMES}
    data = {"description": "", "parameterization": MEIJAARD, "parameters": "",
            "rider": True if rider_included else None, "values": {**values, "v": float(speed)}}
    return yaml.safe_dump(data, sort_keys=True)


def member_document(choice, params, lean=None, compliances=None, tyres=None, stiffness=None, rider_included=False,
                    source="", arms=None):
    """Every parameter a model of the family uses, as one parameter file (plain data) that every command
    reads back as the same model: the set the model takes (the 26 benchmark names, SI; for a model
    with ``rider-lean`` the ``MooreRiderLean2012`` set of the rider split at the hips), ``model:`` (the
    member combination's name), and each member's block (:data:`~bikemass.bicycle.parameter_sets.MEMBER_KEYS`):
    ``flexible:`` the frame's and the fork's compliances (axis, stiffness N m/rad, modal inertia),
    ``tyre:`` the tyre file's form, ``arms:`` the arms' stiffness (N m/rad) and damping (N m s/rad) about
    the steer axis, ``frame_stiffness:`` the Whipple model's quasi-static S (N m/rad).

    ``choice`` is a :class:`~bikemass.models.registry.ModelChoice`; ``source`` says what made the
    compliances (a material), written beside them."""
    from .moore2012 import PARAMETERIZATION, to_moore_values          # lazy: only a rider-lean file needs it
    if choice.has("rider-lean"):
        doc = {"description": "", "parameterization": PARAMETERIZATION, "parameters": "", "rider": None,
               "values": to_moore_values(lean)}
    else:
        doc = {**params.to_dict(), **({"rider_included": True} if rider_included else {})}
    doc["model"] = choice.name
    if choice.has("flexible") and compliances is not None:
        doc["flexible"] = {**compliances.to_dict(), **({"source": str(source)} if source else {})}
    if choice.has("tyre") and tyres is not None:
        doc["tyre"] = {w: {"cornering_coefficient": f"{t.cornering_coefficient!r} 1/rad",
                           "camber_coefficient": f"{t.camber_coefficient!r} 1/rad",
                           "relaxation_length": t.relaxation_length,
                           # the moments only when a tyre has them (a force-only tyre's file as before)
                           **({"pneumatic_trail": f"{t.pneumatic_trail!r} m"} if t.pneumatic_trail else {}),
                           **({"twisting_coefficient": f"{t.twisting_coefficient!r} m/rad"}
                              if t.twisting_coefficient else {})}
                       for w, t in (("front", tyres.front), ("rear", tyres.rear))}
    if choice.has("arms") and arms is not None:
        doc["arms"] = arms.to_dict()
    if not choice.members and stiffness is not None:
        doc["frame_stiffness"] = [[float(x) for x in row] for row in stiffness]
    return doc


def member_units():
    """The units of :func:`member_document`'s keys beside the benchmark parameters' (SI)."""
    from .compliance import Compliance          # lazy: numpy; the text formats above do not need it
    from .members.arms.parameters import Arms                      # lazy: loads the config reader (numpy), as Compliance does
    return {**{k: u for k, u in Compliance.units().items() if u}, "relaxation_length": "m",
            "frame_stiffness": "N m/rad", **Arms.units()}
