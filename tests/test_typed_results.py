"""Typed values to the bottom (issue 32, item 3): every facade function's result, walked
recursively (dataclass fields, ``__slots__``/instance attributes, public properties, tuples,
mappings, numpy arrays, nested results), holds no writable numpy array, no ``dict``, ``list``,
``set`` (or other mutable container) and no attribute that can be set.

This is a structural check of the returned values, not of any number: it holds that a user
cannot change a result they were handed (or a result shared by a cache) in place.

The functions not walked are listed with the reason in ``NOT_WALKED`` (they draw or write
files: a matplotlib Figure is mutable by design), and ``NOT_YET`` names results that still hold
mutable parts (empty now: a result that regains one fails).  ``NOT_RESULTS`` names the types
returned that are not :class:`~bikemass.core.results.Result` s, each with why: inputs and
models, and plain read-only arrays and mappings; every other facade result is a ``Result``.
"""

import dataclasses
import enum
import inspect
import types
import warnings
from collections.abc import Mapping, MutableMapping, MutableSequence, MutableSet
from pathlib import Path

import numpy as np
import pytest

import bikemass as bm

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data"

NOT_WALKED = {
    # matplotlib Figures are mutable by design (a user adds to them); what they draw is walked
    # through the result they draw
    **{name: "returns a matplotlib Figure" for name in (
        "plot_eigenvalues", "plot_critical_speeds", "plot_side_view", "plot_pose", "plot_frame_modes",
        "plot_chart", "plot_bode", "plot_time_response", "plot_nonlinear_response", "plot_hands_free_turns",
        "plot_mode_shapes", "plot_handling", "plot_lane_change", "plot_optimisation")},
    "save_figure": "writes a file and returns None",
    "sweep": "writes its result folder (and runs many configurations); its rows are read back from files",
    "optimise": "runs a design optimisation (minutes); its OptimiseResult is not walked here",
}
"""Facade functions this test does not call, with why."""

NOT_YET = {}
"""Facade functions whose results still hold something mutable: ``{name: what is left}``."""

LEAVES = (type(None), bool, int, float, complex, str, bytes, np.generic, enum.Enum, Path, range, type,
          types.FunctionType, types.BuiltinFunctionType, types.MethodType, types.ModuleType, frozenset)
MUTABLE = (dict, list, set, bytearray, MutableMapping, MutableSequence, MutableSet)
_PROBE = "_typed_results_probe"


def _settable(obj, name):
    """Whether ``obj.name = ...`` succeeds (undone at once if it did)."""
    try:
        had = name in getattr(obj, "__dict__", {})
        old = getattr(obj, name, None)
        setattr(obj, name, old)
    except (AttributeError, TypeError, dataclasses.FrozenInstanceError):
        return False
    if not had and name == _PROBE:
        try:
            delattr(obj, name)
        except AttributeError:
            pass
    return True


def _attributes(obj):
    """``{name: value}`` of what a user reads on ``obj``: dataclass fields, instance and slot
    attributes, and public properties."""
    out = {}
    if dataclasses.is_dataclass(obj):
        out.update({f.name: getattr(obj, f.name) for f in dataclasses.fields(obj)})
    out.update({k: v for k, v in getattr(obj, "__dict__", {}).items()})
    for cls in type(obj).__mro__:
        for slot in getattr(cls, "__slots__", ()):
            if hasattr(obj, slot):
                out.setdefault(slot, getattr(obj, slot))
        for name, member in vars(cls).items():
            if isinstance(member, property) and not name.startswith("_") and name not in out:
                try:
                    with warnings.catch_warnings():
                        warnings.simplefilter("ignore")
                        out[name] = getattr(obj, name)
                except Exception:                  # a property that refuses this value: nothing held
                    pass
    return out


def mutable_parts(value, where="result", seen=None):
    """``[(path, what)]`` of every mutable part of ``value``."""
    seen = set() if seen is None else seen
    if isinstance(value, LEAVES) or callable(value) and not hasattr(value, "__dict__") \
            and not hasattr(type(value), "__slots__"):
        return []
    if id(value) in seen:
        return []
    seen.add(id(value))
    found = []
    if isinstance(value, np.ndarray):
        if value.flags.writeable:
            found.append((where, f"writable array {value.shape}"))
        if value.dtype == object:
            for i, item in enumerate(value.flat):
                found += mutable_parts(item, f"{where}.flat[{i}]", seen)
        return found
    if isinstance(value, MUTABLE):
        found.append((where, f"a {type(value).__name__}"))
    if isinstance(value, Mapping):
        for k, v in value.items():
            found += mutable_parts(k, f"{where}[{k!r}] key", seen)
            found += mutable_parts(v, f"{where}[{k!r}]", seen)
        return found
    if isinstance(value, (tuple, list, set)):
        for i, v in enumerate(value):
            found += mutable_parts(v, f"{where}[{i}]", seen)
        return found
    if inspect.isroutine(value) or inspect.isclass(value):
        return found
    attributes = _attributes(value)
    for name in (*attributes, _PROBE):
        if _settable(value, name):
            found.append((where, f"settable attribute {name!r} of {type(value).__name__}"))
    for name, v in attributes.items():
        found += mutable_parts(v, f"{where}.{name}", seen)
    return found


@pytest.fixture(scope="module")
def meijaard_benchmark():
    return bm.parameters("benchmark")


def _calls(p):
    """``{facade name: [(label, call)]}``: each facade function on the benchmark (and a member model
    or a second input kind where the result's type differs)."""
    scenario = bm.Scenario("jamis", "relaxed")
    return {
        "load_bicycle": [("jamis", lambda: bm.load_bicycle("jamis"))],
        "load_rider": [("relaxed", lambda: bm.load_rider("relaxed"))],
        "parameters": [("benchmark", lambda: p), ("jamis+relaxed", lambda: bm.parameters("jamis", "relaxed"))],
        "stiffness": [("jamis steel", lambda: bm.stiffness("jamis", "steel"))],
        "stability": [("benchmark", lambda: bm.stability(p)),
                      ("tyre", lambda: bm.stability(p, model="tyre", speeds=np.linspace(0, 10, 41)))],
        "eigenvalues": [("benchmark", lambda: bm.eigenvalues(p))],
        "matrices": [("benchmark", lambda: bm.matrices(p))],
        "speeds": [("default", lambda: bm.speeds())],
        "linear_model": [("benchmark", lambda: bm.linear_model(p)),
                         ("rider-lean", lambda: bm.linear_model(scenario.with_model("rider-lean"))
                          if hasattr(scenario, "with_model") else bm.linear_model(
                              bm.Scenario("jamis", "relaxed", model="rider-lean")))],
        "state_space": [("benchmark", lambda: bm.state_space(p, 5.0))],
        "frame_modes": [("jamis", lambda: bm.frame_modes("jamis", count=4))],
        "frame_stiffness": [("jamis", lambda: bm.frame_stiffness("jamis", "steel"))],
        "frame_structure": [("jamis", lambda: bm.frame_structure("jamis"))],
        "pose_rider": [("jamis", lambda: bm.pose_rider("jamis"))],
        "seated_rider": [("jamis relaxed", lambda: bm.seated_rider("jamis", "relaxed"))],
        "geometry_chart": [("jamis", lambda: bm.geometry_chart("jamis"))],
        "sensitivity": [("benchmark", lambda: bm.sensitivity(p, names=("c", "lam"))),
                        ("steel frame", lambda: bm.sensitivity(p, stiffness=bm.stiffness("jamis", "steel"),
                                                               names=("c",)))],
        "geometry_sensitivity": [("jamis trail", lambda: bm.geometry_sensitivity(scenario, ["geometry.trail"]))],
        "uncertainty": [("benchmark", lambda: bm.uncertainty("benchmark", {"c": 0.001},
                                                              speeds=np.arange(1.0, 8.0))),
                        ("montecarlo", lambda: bm.uncertainty("benchmark", {"c": 0.001}, method="montecarlo",
                                                               samples=20, seed=1, speeds=np.arange(1.0, 8.0)))],
        "transfer_function": [("benchmark", lambda: bm.transfer_function(p, 5.0, "steer-torque", "roll-angle"))],
        "frequency_response": [("benchmark", lambda: bm.frequency_response(p, 5.0, "steer-torque", "roll-angle"))],
        "simulate": [("linear", lambda: bm.simulate(p, 4.6, initial={"roll-rate": 0.5}, duration=1.0)),
                     ("nonlinear", lambda: bm.simulate(p, 4.6, initial={"roll-rate": 0.5}, duration=0.5,
                                                       nonlinear=True))],
        "mode_shapes": [("benchmark", lambda: bm.mode_shapes(p, 5.0))],
        "handling": [("benchmark", lambda: bm.handling(p, [4.0, 6.0]))],
        "lane_change": [("benchmark", lambda: bm.lane_change(p, 5.0))],
        "steady_turn": [("benchmark", lambda: bm.steady_turn(p, 5.0, radius=20.0))],
        "hands_free_turns": [("benchmark", lambda: bm.hands_free_turns(p, [0.05, 0.1]))],
        "load_parameter_text": [("Tms", lambda: bm.load_parameter_text(DATA / "bicycleparameters" / "TmsBenchmark.txt"))],
        "read_measured_data": [("Rigid", lambda: bm.read_measured_data(
            DATA / "bicycleparameters" / "measured" / "RigidMeasured.txt"))],
        "benchmark_from_measured": [("Rigid", lambda: bm.benchmark_from_measured(bm.read_measured_data(
            DATA / "bicycleparameters" / "measured" / "RigidMeasured.txt")))],
        "load_measured": [("Rigid", lambda: bm.load_measured(
            DATA / "bicycleparameters" / "measured" / "RigidMeasured.txt"))],
        "load_parameter_set": [("browser-jason", lambda: bm.load_parameter_set(
            DATA / "bicycleparameters" / "to_yaml-MooreRiderLean2012-browserjason.yml"))],
        "load_control": [("balance assist", lambda: bm.load_control(ROOT / "examples" / "control"
                                                                    / "balance-assist-5.4.yaml"))],
    }


FUNCTIONS = [n for n in bm._API if inspect.isfunction(getattr(bm, n))]


def test_every_facade_function_is_walked_or_excluded_with_a_reason(meijaard_benchmark):
    covered = set(_calls(meijaard_benchmark))
    assert set(FUNCTIONS) == covered | set(NOT_WALKED), set(FUNCTIONS) ^ (covered | set(NOT_WALKED))
    assert not covered & set(NOT_WALKED)
    assert set(NOT_YET) <= covered


@pytest.mark.parametrize("name", [n for n in FUNCTIONS if n not in NOT_WALKED])
def test_the_result_holds_nothing_mutable(name, meijaard_benchmark):
    for label, call in _calls(meijaard_benchmark)[name]:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            result = call()
        found = mutable_parts(result, f"bm.{name}({label})")
        if name in NOT_YET:
            assert found, f"bm.{name} holds nothing mutable now: take it out of NOT_YET"
            continue
        assert not found, "\n".join(f"{where}: {what}" for where, what in found[:40]) + f"\n({len(found)} in all)"


@pytest.mark.parametrize("model", [None, "tyre"])
def test_a_built_scenario_holds_nothing_mutable(model):
    """``bm.Scenario(...).build()`` (a :class:`~bikemass.Built`, what every analysis runs on) is a
    result too; the :class:`~bikemass.Scenario` itself is an input description that keeps build
    caches, and is not walked (issue 32 item 5, typed edits, reworks it)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        built = bm.Scenario("jamis", "relaxed", model=model).build()
    found = mutable_parts(built, f"Scenario(model={model}).build()")
    assert not found, "\n".join(f"{where}: {what}" for where, what in found[:40])


NOT_RESULTS = {
    # inputs and models: typed and frozen, but not results (no units block of their own)
    "bicycle.model.Bicycle": "an input: a bicycle's parts and geometry",
    "rider.Rider": "an input: a posed rider's parts",
    "models.parameters.BenchmarkParameters": "the 26 parameters; their units are parameter_units()",
    "models.linear.LinearModel": "a model, not a result",
    "mass.tubes.Structure": "an input: the frame's tubes",
    "models.control.Control": "an input: a controller",
    "bicycle.parameter_sets.ParameterSetFile": "an input file as read",
    "bicycle.parameter_text.MeasuredParameters": "an input file as read",
    "bicycle.measured.MeasuredData": "an input file as read",
    # the value itself: a read-only array or a read-only mapping
    "numpy.ndarray": "bm.stiffness, bm.frame_stiffness, bm.speeds: a read-only array",
    "core.frozen.FrozenMap": "bm.geometry_chart, bm.geometry_sensitivity: a read-only mapping",
}
"""Types (module under ``bikemass`` and name) returned by facade functions that are not
:class:`~bikemass.core.results.Result` s, with why."""


def _kind(value):
    return f"{type(value).__module__.removeprefix('bikemass.')}.{type(value).__name__}"


def test_every_result_is_a_result_or_named_with_a_reason(meijaard_benchmark):
    from bikemass.core.results import Result
    seen = set()
    for name, items in _calls(meijaard_benchmark).items():
        for label, call in items:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                value = call()
            kind = _kind(value)
            seen.add(kind)
            if isinstance(value, Result):
                assert kind not in NOT_RESULTS, f"bm.{name}: {kind} is a Result now: take it out of NOT_RESULTS"
            else:
                assert kind in NOT_RESULTS, f"bm.{name}({label}) returns a {kind}, not a Result"
    assert set(NOT_RESULTS) <= seen, set(NOT_RESULTS) - seen


def test_an_estimate_is_typed_and_its_old_dict_access_warns():
    """A propagation's critical speeds are :class:`~bikemass.analysis.uncertainty.Estimate` values
    (nominal, std in m/s, declared once); the dict access of 0.2 still reads them for one release,
    with a DeprecationWarning."""
    u = bm.uncertainty("benchmark", {"c": 0.001}, speeds=np.arange(1.0, 4.0))
    w = u.speeds["weave_speed"]
    assert type(w).__name__ == "Estimate" and w.units()["nominal"] == w.units()["std"] == "m/s"
    with pytest.warns(DeprecationWarning, match=r"read \.std"):
        assert w["std"] == w.std
    with pytest.warns(DeprecationWarning):
        assert w.get("q025", "absent") == "absent"        # a linear estimate has no quantiles
    assert u.to_dict()["weave_speed"] == {"nominal": w.nominal, "std": w.std}


def test_the_walker_finds_what_it_looks_for():
    @dataclasses.dataclass
    class Loose:
        a: object

    @dataclasses.dataclass(frozen=True)
    class Tight:
        a: object

    writable = np.zeros(2)
    assert [w for _, w in mutable_parts(Tight((1, writable)))] == ["writable array (2,)"]
    assert any("settable" in w for _, w in mutable_parts(Loose(1)))
    assert [w for _, w in mutable_parts(Tight({"k": 1}))] == ["a dict"]
    assert [w for _, w in mutable_parts(Tight((1, [2])))] == ["a list"]
    assert [w for _, w in mutable_parts(Tight(frozenset({1})))] == []
    assert mutable_parts(Tight((1.0, "s", None))) == []
    frozen = np.zeros(2)
    frozen.setflags(write=False)
    assert mutable_parts(Tight(frozen)) == []


def test_a_renamed_units_field_still_reads_with_a_warning_and_units_is_the_block(meijaard_benchmark):
    """A time response's ``units`` field (each state's unit) is ``signal_units`` in 0.3: ``units()``
    is its units block as on every result (speed in m/s, time in s, each state in the model's unit),
    and ``units`` read as the old tuple still works for one release, with a DeprecationWarning."""
    r = bm.simulate(meijaard_benchmark, 4.6, initial={"roll-rate": 0.5}, duration=0.1)
    assert r.signal_units == ("rad", "rad", "rad/s", "rad/s", "rad", "m")     # the Whipple model's states
    block = r.units()
    assert block["speed"] == "m/s" and block["time"] == "s" and block["roll-rate"] == "rad/s"
    assert r.document()["units"] == block
    with pytest.warns(DeprecationWarning, match="signal_units"):
        assert r.units[2] == "rad/s"
    with pytest.warns(DeprecationWarning):
        assert list(r.units) == list(r.signal_units)
    lane = bm.lane_change(meijaard_benchmark, 5.0)
    with pytest.warns(DeprecationWarning):
        assert lane.units["steer-torque"] == "N m"
    assert lane.units()["steer-torque"] == lane.signal_units["steer-torque"] == "N m"
    assert lane.model == "linear" and isinstance(lane.model, enum.Enum)


def test_the_other_renamed_fields_and_the_string_enums(meijaard_benchmark):
    """A mode shape's ``units`` is ``coordinate_units`` and a posed rider's ``document`` is
    ``placement`` in 0.3 (the old names read as values warn; called, they are every result's
    methods); kinds are string enums equal to the old strings, written as those strings."""
    shapes = bm.mode_shapes(meijaard_benchmark, 5.0)
    assert shapes.coordinate_units == ("rad", "rad", "rad", "m")        # roll, steer, heading, lateral
    with pytest.warns(DeprecationWarning, match="coordinate_units"):
        assert tuple(shapes.units) == shapes.coordinate_units
    assert shapes.units()["phase"] == "deg" and shapes.units()["speed"] == "m/s"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        posed = bm.pose_rider("jamis", hands="drops")
    with pytest.warns(DeprecationWarning, match="placement"):
        assert posed.document["name"] == posed.placement["name"]
    document = posed.document()
    assert document["hands"] == "drops" and type(document["hands"]) is str
    assert document["units"]["crank"] == "deg" and document["units"]["gaps"] == "m"
    assert posed.hands == bm.Grip.DROPS == "drops"
    r = bm.simulate(meijaard_benchmark, 4.6, inputs={"steer-torque": ("impulse", 0.1)}, duration=0.1)
    kind, size = r.inputs["steer-torque"]
    assert kind == "impulse" and isinstance(kind, enum.Enum) and r.inputs["steer-torque"].unit == "N m s"
    u = bm.uncertainty("benchmark", {"c": 0.001}, speeds=np.arange(1.0, 3.0))
    assert u.method == "linear" and isinstance(u.method, enum.Enum)
    assert u.to_dict()["method"] == "linear" and type(u.to_dict()["method"]) is str
    assert u.to_dict()["inputs"]["c"] == {"distribution": "normal", "std": 0.001}
    assert type(u.to_dict()["inputs"]["c"]["distribution"]) is str
