"""bikemass: bicycle and rider geometry in YAML -> benchmark parameters, stiffness, stability.

The Python API (docs/api.md)::

    import bikemass as bm
    bike = bm.load_bicycle("jamis")                 # a name, a YAML file or a mapping
    rider = bm.load_rider("relaxed")                # a pose name, a pose file or a mapping
    p = bm.parameters(bike, rider)                  # the 26 Meijaard (2007) parameters
    S = bm.stiffness(bike, "steel")                 # 2x2 rear-frame stiffness, N m/rad
    result = bm.stability(p, stiffness=S)           # result.weave_speeds, .capsize_speeds
    fig = bm.plot_eigenvalues(result)               # a matplotlib Figure

All quantities are SI (m, kg, s, rad, N) in the Meijaard et al. (2007) benchmark frame;
see :mod:`bikemass.convention`.  The names below are imported on first use, so
``import bikemass`` itself loads neither numpy nor scipy.
"""

import importlib
import sys
import types

__version__ = "0.1.0"

_API = {
    "load_bicycle": "catalog", "load_rider": "catalog", "parameters": "catalog", "stiffness": "catalog",
    "stability": "dynamics", "eigenvalues": "dynamics", "matrices": "dynamics", "speeds": "dynamics",
    "StabilityResult": "dynamics",
    "frame_modes": "frame", "frame_stiffness": "frame", "frame_structure": "frame",
    "pose_rider": "posing", "PosedRider": "posing", "seated_rider": "catalog",
    "plot_eigenvalues": "plots.stability", "plot_critical_speeds": "plots.critical_speeds",
    "plot_side_view": "bicycle.drawing", "plot_pose": "plots.pose", "plot_frame_modes": "fe.plot",
    "save_figure": "plots.figure", "geometry_chart": "bicycle.derived_chart", "plot_chart": "bicycle.chart_drawing",
    "sensitivity": "analysis.sensitivity", "geometry_sensitivity": "analysis.sensitivity",
    "uncertainty": "analysis.uncertainty", "sweep": "sweep",
    "Combine": "choices", "Method": "choices", "Overlap": "choices", "Procedure": "choices",
    "Beam": "choices", "Source": "choices", "Support": "choices", "MaterialName": "choices",
    "Grip": "choices", "EigenPart": "choices", "Format": "choices",
    "Bicycle": "bicycle", "Rider": "rider", "BenchmarkParameters": "parameters",
    "PARAMETER_NAMES": "parameters", "InputError": "errors", "BikemassWarning": "errors",
    "load_parameter_text": "parameter_text", "MeasuredParameters": "parameter_text",
    "ParameterFileWarning": "parameter_text",
    "load_parameter_set": "parameter_sets", "ParameterSetFile": "parameter_sets",
    "RiderLeanParameters": "parameter_sets",
}
"""Public name -> the module (under ``bikemass``) that defines it."""

_RENAMED = {"PARAMETER_NAMES": "NAMES", "sweep": "run_sweep"}

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
    """``bikemass`` keeps ``bm.stability`` and ``bm.parameters`` the API functions even after
    the subpackages of the same names (``bikemass.stability``, ``bikemass.parameters``) are
    imported: those stay importable as modules (``from bikemass.stability import ...``)."""

    def __setattr__(self, name, value):
        if name in _API and isinstance(value, types.ModuleType):
            return
        super().__setattr__(name, value)


sys.modules[__name__].__class__ = _Package
