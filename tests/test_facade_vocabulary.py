"""One vocabulary on the facade: the analysed subject is ``system``, a speed limit is ``max_speed``; the old
names keep working for one release with a DeprecationWarning (contract tests of the signatures)."""

import inspect
import warnings

import pytest

import bikemass as bm

ANALYSES = ("linear_model", "eigenvalues", "stability", "sensitivity", "state_space", "transfer_function",
            "frequency_response", "simulate", "mode_shapes", "lane_change", "handling", "steady_turn",
            "hands_free_turns")
"""Facade functions that analyse a bicycle (a parameter set, a Scenario, a built scenario or a model)."""


@pytest.mark.parametrize("name", ANALYSES)
def test_the_analysed_subject_is_called_system(name):
    parameters = list(inspect.signature(getattr(bm, name)).parameters)
    assert parameters[0] == "system"


def test_no_facade_function_names_a_speed_limit_otherwise():
    for name in dir(bm):
        function = getattr(bm, name)
        if inspect.isfunction(function):
            assert not {"vmax", "hi", "speed_max", "v_max"} & set(inspect.signature(function).parameters), name


@pytest.mark.parametrize("call", [
    lambda: bm.stability(params=bm.parameters("benchmark")),
    lambda: bm.sensitivity(bm.parameters("benchmark"), vmax=10.0),
    lambda: bm.steady_turn(parameters=bm.parameters("benchmark"), speed=5.0, radius=10.0),
])
def test_the_old_names_still_work_and_warn(call):
    with pytest.warns(DeprecationWarning, match="is deprecated; use"):
        call()


def test_the_old_and_the_new_name_give_the_same_answer():
    p = bm.parameters("benchmark")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        old = bm.sensitivity(params=p, vmax=10.0)
    new = bm.sensitivity(system=p, max_speed=10.0)
    assert (old.weave_speed, old.capsize_speed) == (new.weave_speed, new.capsize_speed)
    assert dict(old.d_weave_speed) == dict(new.d_weave_speed)


def test_contract_every_analysis_takes_a_scenario_as_its_subject():
    """The nonlinear steady turn of a Scenario is that of its benchmark set (the one door into the analyses)."""
    scenario = bm.Scenario("benchmark")
    by_set = bm.steady_turn(bm.parameters("benchmark"), 5.0, radius=10.0)
    by_scenario = bm.steady_turn(scenario, 5.0, radius=10.0)
    assert by_scenario.roll == by_set.roll and by_scenario.steer_torque == by_set.steer_torque
    with pytest.raises(TypeError, match="system"):
        bm.steady_turn("benchmark", 5.0, radius=10.0)


def test_every_returned_type_is_exported():
    """Each bikemass class a facade function is annotated to return is a name of the facade itself."""
    import typing
    exported = {id(getattr(bm, name)) for name in bm.__all__ if name != "__version__"}
    missing = []
    for name in bm.__all__:
        function = getattr(bm, name, None)
        if inspect.isfunction(function):
            returned = typing.get_type_hints(function).get("return")
            for kind in typing.get_args(returned) or (returned,):
                if isinstance(kind, type) and kind.__module__.startswith("bikemass") and id(kind) not in exported:
                    missing.append(f"{name} -> {kind.__module__}.{kind.__name__}")
    assert missing == []
