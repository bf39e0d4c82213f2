"""Parameter sets in YAML: bikemass's benchmark parameter files and BicycleParameters' parameter-set
files, read into typed values.

BicycleParameters (Moore et al.) writes a parameter set either flat (the values at the top
level, as its ``tests/parameter_sets/benchmark-*.yml`` ship) or as its ``ParameterSet.to_yaml``
does: ``parameterization:``, ``values:`` and the metadata ``parameters:`` (a label),
``rider:`` (whether the rear frame holds a rider) and ``description:``.  Three
parameterizations are read:

* ``benchmark`` (``Meijaard2007``): the 26 names of Meijaard et al. (2007), as bikemass's own
  parameter files; the names the BicycleParameters text format also allows beside them
  (``IRzz``, ``yB``, a handlebar ``G`` and fork ``S``, ...) are checked and used as
  :mod:`bikemass.bicycle.parameter_text` does, so a set means the same in YAML and in text;
* ``principal`` (``Moore2019``; Moore and Hubbard 2019): the rear frame ``D`` and a rigid rider
  ``P`` apart, each rigid body by its mass, mass centre and principal radii of gyration
  ``k?aa``, ``k?yy``, ``k?bb`` with the angle ``alpha?`` of its ``a`` axis; converted to the
  benchmark set (:func:`principal_to_benchmark`);
* ``MooreRiderLean2012`` (Moore 2012): the Whipple model with a rider's upper body ``G``
  leaning on the rear frame; converted exactly to the rider-lean model's
  :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters`
  (:func:`~bikemass.models.moore2012.from_moore_values`), its named values kept as read in
  :attr:`ParameterSetFile.values`.

Each may hold the speed ``v`` (m/s), which is not a bicycle parameter: it is accepted and
kept as :attr:`ParameterSetFile.speed`.  A bare angle (``lam``, ``alpha?``) is radians, as
these formats define it; any value may carry a unit.  Every problem is one
:class:`~bikemass.core.errors.InputError` naming the file and the key.
"""

from dataclasses import dataclass
from types import MappingProxyType

import warnings
import os
import numpy as np

from ..core.config import Node, load_yaml
from ..core.errors import InputError, short
from ..mass.inertia import MassProperties, combine
from .parameter_text import (AXISYMMETRIC, LATERAL, SPLIT_BODIES, ParameterFileWarning, ParameterText,
                             _parse_value, printed_resolution, body_names, measured_parameters)
from ..models.parameter_export import member_units
from ..models.registry import MEMBERS, ModelChoice
from ..models.parameters import NAMES, SPEED_KEY, BenchmarkParameters, check_units, dimension, sign_rule
from ..models.moore2012 import NAMES as MOORE_NAMES, PARAMETERIZATION as MOORE_PARAMETERIZATION, from_moore_values
from ..models.plausibility import check_parameter_file
from ..core.errors import wrong_type
from .parameter_text import read_parameter_text
from .measured import benchmark_from_measured, looks_measured, measured_data, measured_data_of_node

BENCHMARK, PRINCIPAL, RIDER_LEAN = "benchmark", "principal", MOORE_PARAMETERIZATION
"""The parameterizations read (bikemass's names for them)."""
PARAMETERIZATIONS = {"benchmark": BENCHMARK, "Meijaard2007": BENCHMARK, "principal": PRINCIPAL,
                     "Moore2019": PRINCIPAL, "MooreRiderLean2012": RIDER_LEAN}
"""``parameterization:`` as BicycleParameters' files and its ``to_yaml`` write it -> bikemass's name."""
MEMBER_KEYS = ("model", *MEMBERS, "frame_stiffness")
"""Blocks a parameter file may carry beside its parameter set: what ``bikemass params --model M``
writes so that every command reads back the same model (the model it was written for, each member's
parameters under its name, the Whipple model's quasi-static S in N m/rad); read by
:mod:`bikemass.scenario.inputs`."""
SET_KEYS = ("parameterization", "values", "parameters", "rider", "description", "name", "source", "units",
            "warnings", "uncertainty", *MEMBER_KEYS)
"""Top-level keys of the ``parameterization:`` / ``values:`` form (``warnings``: as in :data:`FILE_KEYS`)."""
FILE_KEYS = ("name", "description", "source", "rider_included", "units", "warnings", "uncertainty", *MEMBER_KEYS)
"""Metadata keys of bikemass's own (flat) benchmark parameter files (``warnings``: what bikemass
warned about when it wrote the file as JSON; read back, the set is checked again)."""

BENCHMARK_EXTRAS = (*AXISYMMETRIC, *LATERAL, *(n for part in SPLIT_BODIES for n in body_names(part)))
"""Names a benchmark set may hold beside the 26, as in BicycleParameters' text files."""

PRINCIPAL_NAMES = ("w", "c", "lam", "g", "rR", "mR", "kRaa", "kRyy", "rF", "mF", "kFaa", "kFyy",
                   "mD", "xD", "zD", "kDaa", "kDyy", "kDbb", "alphaD",
                   "mP", "xP", "zP", "kPaa", "kPyy", "kPbb", "alphaP",
                   "mH", "xH", "zH", "kHaa", "kHyy", "kHbb", "alphaH")
"""The principal parameters the benchmark set follows from (Moore and Hubbard 2019)."""
PRINCIPAL_IMPLIED = {"xR": lambda p: 0.0, "xF": lambda p: p["w"], "zR": lambda p: -p["rR"],
                     "zF": lambda p: -p["rF"], "kRbb": lambda p: p["kRaa"], "kFbb": lambda p: p["kFaa"],
                     **{f"y{b}": (lambda p: 0.0) for b in "DPHRF"}}
"""Principal parameters a file may repeat although the others fix them: wheel centres at the
axles, axisymmetric wheels, every body in the plane of symmetry.  Checked, not used."""
PRINCIPAL_DRAWING = ("lP", "wP")
"""The rider's length and width: for drawing the rider only."""
PRINCIPAL_ONLY = tuple(n for n in PRINCIPAL_NAMES if n not in NAMES)
"""Names by which a flat file is known to be principal (``yH`` and the like a benchmark file may
hold too)."""

CHECK_RELATIVE = 1e-4
"""An implied principal parameter passes when within this fraction (of the larger magnitude)
plus half a unit in its last printed digit (the files print 5 significant digits)."""


RIDER_LEAN_NAMES = tuple(n for n in MOORE_NAMES if n != SPEED_KEY)
"""The 36 rider-lean names (Moore's set without the speed ``v``)."""


def _rider_lean_rule(name):
    """``(dimension, positive, nonnegative)`` of a rider-lean parameter."""
    if name == "g":
        return "acceleration", True, False
    if name == "k9":
        return "stiffness", False, True
    if name == "c9":
        return "damping", False, True
    if name.startswith("i"):
        return "inertia", False, not name.endswith("31")
    if name.startswith("m"):
        return "mass", True, False
    return "length", name in ("rf", "rr"), False


def _principal_rule(name):
    """``(dimension, positive, nonnegative)`` of a principal parameter."""
    if name in NAMES:
        return (dimension(name), *sign_rule(name))
    if name.startswith("alpha"):
        return "angle", False, False
    if name.startswith("m"):
        return "mass", name in ("mD", "mP", "mH"), name in ("mR", "mF")
    return "length", False, name.startswith("k") or name in PRINCIPAL_DRAWING


@dataclass(frozen=True)
class ParameterSetFile:
    """One parameter set read from YAML.

    Attributes
    ----------
    parameterization : str
        ``"benchmark"``, ``"principal"`` or ``"MooreRiderLean2012"``.
    parameters : BenchmarkParameters or RiderLeanParameters
        The benchmark set (a principal set converted), or the leaning rider's parameters (a
        rider-lean set converted).
    speed : float or None
        The file's ``v`` (m/s): the speed the set was made for; not a bicycle parameter.
    rider_included : bool
        Whether the rear frame holds a rider (``rider: true``; a principal set always does).
    label, description : str
        The file's ``parameters:`` (or ``name:``) and ``description:``.
    notes : tuple of str
        How every value beyond the set's own names was used.
    values : mapping
        Every value as read (SI), the principal ones included.
    source : str
        The file.
    measured : MeasuredParameters or None
        A benchmark set's standard deviations (a BicycleParameters text file's ``+/-`` values, a
        YAML file's ``uncertainty:`` block, or computed from measurements), else ``None``.

    See Also
    --------
    bikemass.load_parameter_set : Reads one.

    Examples
    --------
    >>> import json, os, tempfile
    >>> import bikemass as bm
    >>> path = os.path.join(tempfile.mkdtemp(), "benchmark.yml")
    >>> _ = open(path, "w").write(json.dumps(bm.parameters("benchmark").to_dict()))    # the flat form
    >>> found = bm.load_parameter_set(path)
    >>> found.parameterization, found.speed, found.parameters.mB
    ('benchmark', None, 85.0)
    """

    parameterization: str
    parameters: object
    speed: object
    rider_included: bool
    label: str
    description: str
    notes: tuple
    values: MappingProxyType
    source: str
    measured: object = None

    def __repr__(self):
        return f"ParameterSetFile({self.parameterization!r}, {self.label!r}, source={self.source!r})"


def kind_of(node):
    """The parameterization a YAML mapping holds (:data:`BENCHMARK`, :data:`PRINCIPAL`,
    :data:`RIDER_LEAN`), or ``None`` when it is not a parameter set; a ``parameterization:``
    key names it, else the names present do."""
    mapping = node.value
    if not isinstance(mapping, dict) or looks_measured(mapping):
        return None
    if "parameterization" in mapping:
        given = node["parameterization"]
        if not isinstance(given.value, str) or given.value not in PARAMETERIZATIONS:
            given.fail(f"one of {', '.join(PARAMETERIZATIONS)}, got {short(given.value)}")
        return PARAMETERIZATIONS[given.value]
    if any(k in mapping for k in PRINCIPAL_ONLY):
        return PRINCIPAL
    if any(k in mapping for k in RIDER_LEAN_NAMES if k not in ("g",)):
        return RIDER_LEAN
    if any(k in mapping for k in NAMES):
        return BENCHMARK
    return None


def read_parameter_set(node):
    """:class:`ParameterSetFile` of a YAML mapping ``node`` (flat, or ``parameterization:`` /
    ``values:``), or of BicycleParameters' measurements (their benchmark set); InputError naming the
    key on bad input."""
    if isinstance(node.value, dict) and looks_measured(node.value):
        return measured_parameter_set(benchmark_from_measured(measured_data_of_node(node)))
    kind = kind_of(node)
    if kind is None:
        node.fail("a parameter set: the 26 benchmark names, principal parameters or "
                  "parameterization: with values:")
    if node.has("parameterization"):
        node.check_keys(required=("parameterization", "values"), optional=SET_KEYS)
        values = node["values"]
        rider_given = node.get("rider")
        rider = False if rider_given.missing else rider_given.boolean()
        label = _text(node.get("parameters")) or _text(node.get("name"))
    else:
        values = node
        extra = FILE_KEYS if kind == BENCHMARK else ("name", "description", "source")
        values.check_keys(optional=_allowed(kind) + extra)
        rider = kind == BENCHMARK and node.get("rider_included", False).boolean()
        label = _text(node.get("name"))
    values.mapping()
    if node.has("units"):            # the member blocks' units (the 26 names': _benchmark)
        check_units(node["units"], member_units(ModelChoice(MEMBERS)))
    speed = values[SPEED_KEY].number("speed", nonnegative=True) if values.has(SPEED_KEY) else None
    description = _text(node.get("description"))
    measured = None
    if kind == BENCHMARK:
        measured = _benchmark(values, exclude=FILE_KEYS if values is node else (), uncertainty=node.get("uncertainty"))
        parameters, notes, read = measured.parameters, measured.notes, measured.parameters.to_dict()
        measured = measured if any(measured.std.values()) else None
    elif node.has("uncertainty"):
        node.fail("a benchmark parameter set with uncertainty: (standard deviations of the 26 names)", "uncertainty")
    elif kind == PRINCIPAL:
        read = _numbers(values, PRINCIPAL_NAMES, (*PRINCIPAL_IMPLIED, *PRINCIPAL_DRAWING), _principal_rule,
                        exclude=("name", "description", "source") if values is node else ())
        parameters, notes = _principal(read, values)
        check_parameter_file(parameters, str(values.source), f"{values.key}." if values.key else "")
        rider = True                                    # Moore and Hubbard's set always holds the rider
    else:
        read = _numbers(values, RIDER_LEAN_NAMES, (), _rider_lean_rule,
                        exclude=("name", "description", "source") if values is node else ())
        parameters, notes = from_moore_values(read, str(values.source)), ()
    return ParameterSetFile(kind, parameters, speed, bool(rider), label, description, tuple(notes),
                            MappingProxyType(dict(read)), str(node.source), measured)


def load_parameter_set(path: "str | os.PathLike") -> ParameterSetFile:
    """A parameter set from YAML (or JSON): a bikemass benchmark parameter file or a BicycleParameters
    parameter-set file (module docstring).

    Parameters
    ----------
    path : str or os.PathLike
        The file: flat (the 26 benchmark names at the top level) or BicycleParameters'
        ``ParameterSet.to_yaml`` form (``parameterization:``, ``values:``), parameterized as
        ``benchmark``/``Meijaard2007``, ``principal``/``Moore2019`` or ``MooreRiderLean2012``.

    Returns
    -------
    ParameterSetFile
        ``.parameters`` is a :class:`~bikemass.BenchmarkParameters` for the benchmark and
        principal parameterizations (a principal set converted), a
        :class:`~bikemass.RiderLeanParameters` for MooreRiderLean2012; ``.speed`` the file's ``v``
        (m/s) or None.

    Raises
    ------
    InputError
        Not a parameter set, or bad content (naming the file and the key).

    Warns
    -----
    ParameterFileWarning
        Values beside the set's own names that do not add up.

    See Also
    --------
    load_bicycle : Takes such a file as a bicycle.
    load_parameter_text : BicycleParameters' text files (``name = value+/-std``).

    Examples
    --------
    >>> import json, os, tempfile
    >>> import bikemass as bm
    >>> values = {**bm.parameters("benchmark").to_dict(), "v": 5.0}       # v: a speed, not a parameter
    >>> path = os.path.join(tempfile.mkdtemp(), "benchmark.yml")
    >>> _ = open(path, "w").write(json.dumps({"parameterization": "Meijaard2007", "values": values}))
    >>> found = bm.load_parameter_set(path)
    >>> print(found.parameterization, found.speed, found.parameters == bm.parameters("benchmark"))
    benchmark 5.0 True
    """
    if not isinstance(path, (str, os.PathLike)):
        raise wrong_type("path", path, "a parameter-set YAML file path")
    return read_parameter_set(load_yaml(path))


def read_parameter_set_text(path):
    """:class:`ParameterSetFile` of a BicycleParameters text file: a ``<Name>Benchmark.txt`` (a
    benchmark set, its notes, no speed) or a ``<Name>Measured.txt`` (its measurements' benchmark set)."""
    text = read_parameter_text(path)
    if looks_measured(text.nominal):
        return measured_parameter_set(benchmark_from_measured(measured_data(text.nominal, text.std, text.source)))
    measured = measured_parameters(text)
    return ParameterSetFile(BENCHMARK, measured.parameters, None, False, "", "", measured.notes,
                            MappingProxyType(measured.parameters.to_dict()), str(path),
                            measured if any(measured.std.values()) else None)


def measured_parameter_set(measured):
    """:class:`ParameterSetFile` of a :class:`~bikemass.bicycle.parameter_text.MeasuredParameters`
    (a benchmark set with standard deviations)."""
    return ParameterSetFile(BENCHMARK, measured.parameters, None, False, "", "", measured.notes,
                            MappingProxyType(measured.parameters.to_dict()), measured.source, measured)


def _text(node):
    return "" if node.missing else node.string()


def _allowed(kind):
    if kind == BENCHMARK:
        return (*NAMES, *BENCHMARK_EXTRAS, SPEED_KEY)
    if kind == PRINCIPAL:
        return (*PRINCIPAL_NAMES, *PRINCIPAL_IMPLIED, *PRINCIPAL_DRAWING, SPEED_KEY)
    return (*RIDER_LEAN_NAMES, SPEED_KEY)


def _numbers(values, required, optional, rule, exclude=()):
    """``{name: SI float}`` of the names in ``values`` (every ``required`` one, any ``optional``)."""
    values.check_keys(required=required, optional=(*optional, SPEED_KEY, *exclude))
    out = {}
    for name in (*required, *optional):
        if values.has(name):
            dim, positive, nonnegative = rule(name)
            out[name] = values[name].number(dim, positive=positive, nonnegative=nonnegative,
                                            bare_unit="rad" if dim == "angle" else None)
    return out


def _benchmark(values, exclude=(), uncertainty=None):
    """The :class:`~bikemass.bicycle.parameter_text.MeasuredParameters` of a benchmark mapping, read as a
    BicycleParameters text file would be (extra names checked and used the same way); ``uncertainty``:
    the file's ``uncertainty:`` block (``name: std``, SI or with a unit), or a missing Node."""
    values.check_keys(required=NAMES, optional=(*BENCHMARK_EXTRAS, SPEED_KEY, *exclude))
    if values.has("units"):
        check_units(values["units"])
    nominal, given = {}, {}
    for name in (*NAMES, *BENCHMARK_EXTRAS):
        if values.has(name):
            base = name if name in NAMES else name.replace("G", "H").replace("S", "H")
            dim = dimension(base) if not base.startswith("y") else "length"
            positive, nonnegative = sign_rule(base) if base in NAMES else (False, False)
            item = values[name]
            if isinstance(item.value, str) and ("+/-" in item.value or "±" in item.value):
                # BicycleParameters' value+/-std, bare SI (radians), as in its text files
                nominal[name], given[name], _ = _parse_value(item.value, str(values.source), item.key)
                item = Node(nominal[name], item.source, item.key)
            nominal[name] = item.number(dim, positive=positive, nonnegative=nonnegative,
                                        bare_unit="rad" if name == "lam" else None)
    std = {**dict.fromkeys(nominal, 0.0), **given}
    if uncertainty is not None and not uncertainty.missing:
        uncertainty.mapping()
        uncertainty.check_keys(optional=tuple(nominal))
        for name in nominal:
            if uncertainty.has(name):
                if name in given:
                    uncertainty[name].fail(f"the std of {name} once (its value gives one too: {values[name].value!r})")
                base = name if name in NAMES else name.replace("G", "H").replace("S", "H")
                dim = dimension(base) if not base.startswith("y") else "length"
                std[name] = uncertainty[name].number(dim, nonnegative=True,
                                                     bare_unit="rad" if name == "lam" else None)
    text = ParameterText(str(values.source), MappingProxyType(nominal),
                         MappingProxyType(std),
                         MappingProxyType({k: printed_resolution(repr(v)) for k, v in nominal.items()}),
                         MappingProxyType({}))
    return measured_parameters(text, values.key)


def _principal(p, values):
    """The benchmark set of the principal values ``p`` (SI) and the notes on the implied ones."""
    notes = []
    for name, implied in PRINCIPAL_IMPLIED.items():
        if name in p:
            expected = implied(p)
            tolerance = CHECK_RELATIVE * max(abs(p[name]), abs(expected)) + printed_resolution(repr(p[name]))
            if abs(p[name] - expected) > tolerance:
                where = f"{values.key}.{name}" if values.key else name
                message = (f"{values.source}: {where} = {p[name]:.6g} but the other principal parameters "
                           f"imply {expected:.6g}; not used")
                warnings.warn(message, ParameterFileWarning, stacklevel=4)
                notes.append(f"{name} differs from {expected:.6g} implied: not used")
            else:
                notes.append(f"{name} checked: as the other parameters imply")
    drawn = [n for n in PRINCIPAL_DRAWING if n in p]
    if drawn:
        notes.append(f"not used (the rider's drawing only): {', '.join(drawn)}")
    return principal_to_benchmark(p), tuple(notes)


def principal_inertia(mass, kaa, kyy, kbb, alpha):
    """The central inertia tensor (kg m^2, benchmark frame) of a body in the plane of symmetry
    with principal radii of gyration ``kaa``, ``kyy``, ``kbb`` (m) and its ``a`` axis at
    ``alpha`` (rad) from x about y: ``Ixx = m (kaa^2 cos^2 a + kbb^2 sin^2 a)``,
    ``Izz = m (kaa^2 sin^2 a + kbb^2 cos^2 a)``, ``Ixz = m (kbb^2 - kaa^2) sin a cos a``,
    ``Iyy = m kyy^2``."""
    ca, sa = np.cos(alpha), np.sin(alpha)
    Iaa, Ibb = mass * kaa ** 2, mass * kbb ** 2
    xz = (Ibb - Iaa) * sa * ca
    return np.array([[Iaa * ca ** 2 + Ibb * sa ** 2, 0.0, xz], [0.0, mass * kyy ** 2, 0.0],
                     [xz, 0.0, Iaa * sa ** 2 + Ibb * ca ** 2]])


def principal_to_benchmark(p):
    """:class:`~bikemass.models.parameters.BenchmarkParameters` of principal parameters ``p`` (SI
    mapping): the rear frame B is the rear frame D and the rider P combined (parallel-axis
    theorem), the front frame H and the wheels follow from their radii of gyration."""
    body = {b: MassProperties(p[f"m{b}"], [p[f"x{b}"], 0.0, p[f"z{b}"]],
                              principal_inertia(p[f"m{b}"], p[f"k{b}aa"], p[f"k{b}yy"], p[f"k{b}bb"],
                                                p[f"alpha{b}"]))
            for b in "DPH"}
    B, H = combine([body["D"], body["P"]]), body["H"]
    return BenchmarkParameters(
        w=p["w"], c=p["c"], lam=p["lam"], g=p["g"],
        rR=p["rR"], mR=p["mR"], IRxx=p["mR"] * p["kRaa"] ** 2, IRyy=p["mR"] * p["kRyy"] ** 2,
        xB=float(B.com[0]), zB=float(B.com[2]), mB=float(B.mass), IBxx=float(B.inertia[0, 0]),
        IByy=float(B.inertia[1, 1]), IBzz=float(B.inertia[2, 2]), IBxz=float(B.inertia[0, 2]),
        xH=p["xH"], zH=p["zH"], mH=p["mH"], IHxx=float(H.inertia[0, 0]), IHyy=float(H.inertia[1, 1]),
        IHzz=float(H.inertia[2, 2]), IHxz=float(H.inertia[0, 2]),
        rF=p["rF"], mF=p["mF"], IFxx=p["mF"] * p["kFaa"] ** 2, IFyy=p["mF"] * p["kFyy"] ** 2)


def whipple_parameters(parameter_set):
    """The benchmark parameters of a :class:`ParameterSetFile` (checked when read); InputError for
    a rider-lean set, which the Whipple model cannot take."""
    if parameter_set.parameterization == RIDER_LEAN:
        raise InputError(parameter_set.source, "parameterization",
                         "a Whipple parameter set (benchmark or principal); a MooreRiderLean2012 set is for the "
                         "rider-lean model (read it with bm.load_parameter_set)")
    return parameter_set.parameters
