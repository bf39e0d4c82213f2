"""bikemass: bicycle and rider geometry in YAML -> benchmark parameters, stiffness, stability.

The Python API (docs/api.md)::

    import bikemass as bm
    bike = bm.load_bicycle("jamis")                 # a name, a YAML file or a mapping
    rider = bm.load_rider("relaxed")                # a pose name, a pose file or a mapping
    p = bm.parameters(bike, rider)                  # the 26 Meijaard (2007) parameters
    S = bm.stiffness(bike, "steel")                 # 2x2 rear-frame stiffness, N m/rad
    result = bm.stability(p, stiffness=S)           # result.weave_speeds, .capsize_speeds
    lean = bm.stability(bm.Scenario(bike, rider, model="rider-lean"))   # any member of the family
    fig = bm.plot_eigenvalues(result)               # a matplotlib Figure

All quantities are SI (m, kg, s, rad, N) in the Meijaard et al. (2007) benchmark frame;
see :mod:`bikemass.core.convention`.  The API reference of every name is the documentation
site's (README.md, "Documentation"); each docstring's Examples run in the test suite
(tests/test_docstrings.py).  The names below are imported on first use, so
``import bikemass`` itself loads neither numpy nor scipy.
"""

import importlib
import sys
import types

__version__ = "0.2.0"
"""The version of bikemass (PEP 440); ``pyproject.toml`` reads it from here, ``bikemass --version`` prints it."""

_API = {
    "load_bicycle": "scenario.loading", "load_rider": "scenario.loading", "parameters": "scenario.scenario",
    "Scenario": "scenario.scenario", "Built": "scenario.scenario",
    "Modes": "analysis.engine.modes", "CanonicalMatrices": "models.canonical", "Sensitivity": "analysis.sensitivity",
    "SweepResult": "sweep.result", "Structure": "mass.tubes", "Figure": "plots.figure", "FrameModes": "scenario.frame",
    "stiffness": "scenario.catalog",
    "stability": "analysis.results", "eigenvalues": "analysis.results", "matrices": "analysis.results",
    "speeds": "analysis.results", "linear_model": "analysis.results",
    "state_space": "analysis.state_space", "StateSpace": "analysis.state_space",
    "StabilityResult": "analysis.engine.stability", "LinearModel": "models.linear",
    "frame_modes": "scenario.frame", "frame_stiffness": "scenario.frame", "frame_structure": "scenario.frame",
    "pose_rider": "scenario.posing", "PosedRider": "scenario.posing", "seated_rider": "scenario.catalog",
    "plot_eigenvalues": "plots.stability", "plot_critical_speeds": "plots.critical_speeds",
    "plot_side_view": "scenario.views", "plot_pose": "scenario.views", "plot_frame_modes": "plots.frame_modes",
    "save_figure": "plots.figure", "geometry_chart": "scenario.catalog", "plot_chart": "scenario.views",
    "sensitivity": "analysis.sensitivity", "geometry_sensitivity": "analysis.sensitivity",
    "uncertainty": "analysis.uncertainty", "sweep": "sweep",
    "transfer_function": "analysis.handling.transfer", "frequency_response": "analysis.handling.frequency",
    "simulate": "analysis.handling.time_response", "mode_shapes": "analysis.handling.mode_shapes",
    "handling": "analysis.handling.survey", "lane_change": "analysis.handling.lane_change",
    "Gains": "analysis.handling.gains", "TransferFunction": "analysis.handling.transfer",
    "FrequencyResponse": "analysis.handling.frequency", "TimeResponse": "analysis.handling.time_response",
    "ModeShapes": "analysis.handling.mode_shapes", "HandlingResult": "analysis.handling.survey",
    "LaneChange": "analysis.handling.lane_change", "Propagation": "analysis.uncertainty",
    "Estimate": "analysis.uncertainty", "Spread": "analysis.uncertainty", "Distribution": "analysis.uncertainty",
    "PropagationMethod": "analysis.uncertainty", "Excitation": "analysis.sampled", "Applied": "analysis.sampled",
    "Manoeuvre": "analysis.handling.lane_change", "Dynamics": "analysis.handling.lane_change",
    "plot_bode": "analysis.handling.figures", "plot_time_response": "analysis.handling.figures",
    "plot_nonlinear_response": "analysis.nonlinear.figures", "NonlinearResponse": "analysis.nonlinear.response",
    "steady_turn": "analysis.nonlinear.turn", "hands_free_turns": "analysis.nonlinear.turn",
    "SteadyTurn": "analysis.nonlinear.turn", "HandsFreeTurns": "analysis.nonlinear.turn",
    "plot_hands_free_turns": "analysis.nonlinear.figures", "plot_mode_shapes": "analysis.handling.figures",
    "plot_handling": "analysis.handling.figures", "plot_lane_change": "analysis.handling.figures",
    "Combine": "core.choices", "Method": "core.choices", "Overlap": "core.choices",
    "Procedure": "core.choices", "Beam": "core.choices", "Source": "core.choices", "Support": "core.choices",
    "MaterialName": "core.choices", "Grip": "core.choices", "EigenPart": "core.choices", "Format": "core.choices",
    "Tuning": "core.choices",
    "Bicycle": "bicycle", "Rider": "rider", "BenchmarkParameters": "models.parameters",
    "PARAMETER_NAMES": "models.parameters", "InputError": "core.errors", "InputTypeError": "core.errors",
    "BikemassWarning": "core.errors",
    "load_parameter_text": "bicycle.parameter_text", "MeasuredParameters": "bicycle.parameter_text",
    "ParameterFileWarning": "bicycle.parameter_text",
    "read_measured_data": "bicycle.measured", "MeasuredData": "bicycle.measured",
    "benchmark_from_measured": "bicycle.measured", "load_measured": "bicycle.measured",
    "load_parameter_set": "bicycle.parameter_sets", "ParameterSetFile": "bicycle.parameter_sets",
    "RiderLeanParameters": "models.members.rider_lean.parameters",
    "optimise": "design.optimise", "OptimiseResult": "design.optimise", "plot_optimisation": "design.figures",
    "Control": "models.control", "load_control": "models.control", "ScheduledModel": "models.control",
}
"""Public name -> the module (under ``bikemass``) that defines it."""

_RENAMED = {"PARAMETER_NAMES": "NAMES", "sweep": "run_sweep", "FrameModes": "Modes"}

__all__ = ["__version__", *_API]


def __getattr__(name):
    if name not in _API:
        raise AttributeError(f"module 'bikemass' has no attribute {name!r}")
    module = importlib.import_module(f"bikemass.{_API[name]}")
    value = getattr(module, _RENAMED.get(name, name))
    globals()[name] = value
    return value


def __dir__():
    return sorted(set(globals()) | set(__all__))


class _Package(types.ModuleType):
    """``bikemass`` keeps ``bm.sweep`` the API function even after the subpackage of the same
    name (``bikemass.sweep``) is imported: it stays importable as a module
    (``from bikemass.sweep import ...``)."""

    def __setattr__(self, name, value):
        if name in _API and isinstance(value, types.ModuleType):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package
