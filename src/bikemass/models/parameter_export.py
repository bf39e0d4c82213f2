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


def member_document(choice, params, members=None, stiffness=None, rider_included=False, source=""):
    """Every parameter a model of the family uses, as one parameter file (plain data) that every command
    reads back as the same model: the set the model takes (the 26 benchmark names, SI; a member that writes
    its own set, the leaning rider's ``MooreRiderLean2012`` form, replaces it), ``model:`` (the member
    combination's name), each member's block under its name (its ``write_block``: for the flexible frame
    the compliances, for the tyres the tyre file's form, for the arms their stiffness and damping), and
    ``frame_stiffness:`` the Whipple model's quasi-static S (N m/rad).

    ``choice`` is a :class:`~bikemass.models.registry.ModelChoice`; ``members`` ``{member name: typed
    parameters}`` (:attr:`bikemass.scenario.scenario.Built.members`); ``source`` says what made a member's
    parameters that take the stiffness choice (a material), written beside them."""
    members = members or {}
    doc = None
    for spec in choice.specs:
        write_set = spec.hook("write_set")
        if write_set is not None and members.get(spec.name) is not None:
            doc = write_set(members[spec.name])
    if doc is None:
        doc = {**params.to_dict(), **({"rider_included": True} if rider_included else {})}
    doc["model"] = choice.name
    for spec in choice.specs:
        write = spec.hook("write_block")
        if write is not None and members.get(spec.name) is not None:
            doc[spec.name] = {**write(members[spec.name]),
                              **({"source": str(source)} if source and spec.takes_stiffness else {})}
    if not choice.members and stiffness is not None:
        doc["frame_stiffness"] = [[float(x) for x in row] for row in stiffness]
    return doc


def member_units(choice):
    """The units of :func:`member_document`'s keys beside the benchmark parameters' (SI)."""
    out = {"frame_stiffness": "N m/rad"}
    for spec in choice.specs:
        units = spec.hook("units")
        if units is not None:
            out.update(units())
    return out
