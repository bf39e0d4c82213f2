"""A member's own parameters as inputs of a scenario (each member's ``INPUTS``): changed by name through
``Scenario.build``, checked by the member's typed value, read back by ``Scenario.value``."""

import importlib
import math

import numpy as np
import pytest

import bikemass as bm
from bikemass.models.members import PACKAGES

CASES = [("tyre", "benchmark", None, None), ("arms", "jamis", "relaxed", None),
         ("rider-lean", "jamis", "relaxed", None), ("flexible", "jamis", "relaxed", "steel")]


def inputs_of(model):
    package = PACKAGES[[m.replace("_", "-") for m in PACKAGES].index(model)]
    return importlib.import_module(f"bikemass.models.members.{package}.runtime").INPUTS


@pytest.mark.parametrize("model, bike, rider, stiffness", CASES)
def test_contract_each_input_is_the_code_value_the_model_is_built_from(model, bike, rider, stiffness):
    """Each input changed by 10 % (or set to 1 where it is 0) is that parameter of the model's code and
    nothing else, and the model equals the base model evaluated at those values (the generated code
    called with them directly, without the member's typed value: a contract test of the ``INPUTS``
    mapping against the code's own, to rounding)."""
    scenario = bm.Scenario(bike, rider, stiffness, model=model)
    base = scenario.build()
    values = base.values()
    for name in inputs_of(model):
        x = 1.1 * values[name] if values[name] else 1.0
        changed = scenario.build({name: x})
        assert scenario.value(name) == pytest.approx(values[name], rel=1e-15)
        got = changed.values()
        assert got[name] == pytest.approx(x, rel=1e-15), name
        others = [k for k in values if k != name and not (model == "flexible" and k.startswith("c"))]
        assert all(got[k] == values[k] for k in others), name        # (a frame's damping follows its stiffness)
        direct = base.with_values({**values, **{k: got[k] for k in got}})
        np.testing.assert_allclose(changed.model.dynamic_coefficients, direct.dynamic_coefficients,
                                   rtol=1e-13, atol=1e-9)


def test_an_input_takes_a_unit_and_is_checked_by_its_member():
    """A value with a unit is converted to the code's (0.2 1/deg is 11.459 1/rad); a value the member refuses
    (a negative relaxation length, a negative mass), a value of the wrong dimension, and a parameter of the
    code that follows from other data (the flexible frame's modal mass) are refused in one line each."""
    tyre = bm.Scenario("benchmark", model="tyre")
    assert tyre.build({"CaF": "0.2 1/deg"}).values()["CaF"] == pytest.approx(0.2 * 180 / math.pi, rel=1e-15)
    assert tyre.build({"sigmaR": "200 mm"}).values()["sigmaR"] == pytest.approx(0.2, rel=1e-15)
    for change, words in [({"sigmaF": -0.1}, "sigmaF: a positive number"),
                          ({"CaF": "3 kg"}, "CaF: a number in 1/rad"),
                          ({"CaF": float("nan")}, "CaF: a finite number")]:
        with pytest.raises(bm.InputError, match=words):
            tyre.build(change)
    with pytest.raises(bm.InputError, match="mU: a positive number"):
        bm.Scenario("jamis", "relaxed", model="rider-lean").build({"mU": -1.0})
    with pytest.raises(bm.InputError, match="mtr: one of the flexible model's inputs"):
        bm.Scenario("jamis", "relaxed", "steel", model="flexible").build({"mtr": 1.0})


def test_a_sweep_and_an_optimisation_over_a_members_input(tmp_path):
    """A sweep spec varies the front tyre's cornering coefficient in 1/deg and its relaxation length: each row's
    weave speed is ``bm.stability`` of the scenario built with those values (1e-9 m/s), a negative relaxation
    length is a refused row naming the key; an optimisation over ``CaF`` (bounds in 1/deg) hits a weave-speed
    target at the coefficient a brentq on ``bm.stability`` finds (1e-6 relative)."""
    from scipy.optimize import brentq
    scenario = bm.Scenario("benchmark", model="tyre")
    spec = tmp_path / "sweep.yaml"
    spec.write_text("bike: benchmark\nmodel: tyre\nvary:\n  CaF: {from: 0.15 1/deg, to: 0.25 1/deg, num: 3}\n"
                    "  sigmaF: [-0.1, 0.2]\n")
    with pytest.warns(bm.BikemassWarning, match="3 of 6 configurations were refused"):
        rows = list(bm.sweep(str(spec), tmp_path / "out"))
    assert len(rows) == 6
    for row in rows:
        if row["sigmaF"] < 0:
            assert "sigmaF: a positive number" in row["error"]
            continue
        built = scenario.build({"CaF": f"{row['CaF']} 1/deg", "sigmaF": row["sigmaF"]})
        assert row["error"] is None
        assert row["weave_speed"] == pytest.approx(bm.stability(built).weave_speeds[0], abs=1e-9)
    target = tmp_path / "opt.yaml"
    target.write_text("bike: benchmark\nmodel: tyre\nvariables:\n  CaF: {min: 0.1 1/deg, max: 0.35 1/deg}\n"
                      "target: {weave-speed: 4.31}\n")
    result = bm.optimise(str(target))

    def weave(caf):
        return bm.stability(scenario.build({"CaF": caf})).weave_speeds[0]
    root = brentq(lambda caf: weave(caf) - 4.31, 0.1 * 180 / math.pi, 0.35 * 180 / math.pi, xtol=1e-12)
    assert result.converged and result.variables["CaF"] == pytest.approx(root, rel=1e-6)
    assert result.variable_units["CaF"] == "1/rad"


def test_a_member_input_set_by_name_is_refused_where_the_model_lacks_it_and_quiets_the_default():
    """``CaF`` on the Whipple bicycle names the model that has it; the flexible frame's ``mtr`` (no input) names the
    inputs, through ``build`` and ``value`` alike; the arms' stiffness set by name does not warn that none was
    given (the default's warning)."""
    import warnings
    for scenario, key, words in [(bm.Scenario("benchmark"), "CaF", "CaF is the tyre member.s \\(model: tyre"),
                                 (bm.Scenario("jamis", "relaxed", "steel", model="flexible"), "mtr",
                                  "one of the flexible model.s inputs \\(cs, kr, kf\\)")]:
        with pytest.raises(bm.InputError, match=words):
            scenario.build({key: 1.0})
        with pytest.raises(bm.InputError, match=words):
            scenario.value(key)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        built = bm.Scenario("jamis", "relaxed", model="arms").build({"k_arms": 20.0})
    assert built.arms.stiffness == 20.0
    assert not [w for w in caught if "no stiffness or damping given" in str(w.message)]


def test_a_member_input_at_its_bound_is_differenced_on_its_one_side(tmp_path):
    """The front tyre's pneumatic trail and the arms' stiffness are 0 by default, the least they take: the central
    difference stepped to -1e-4 and was refused ("tpF: a number >= 0, got -0.0001", a value never given). Where
    one side cannot be built the difference is one-sided: ``--inputs tpF`` then equals its exact sensitivity row
    to 1e-3 relative (a forward difference of step 1e-4 m; the capsize speed's curvature in the trail makes the
    rest), and an optimisation whose box starts at that bound converges there."""
    scenario = bm.Scenario("benchmark", model="tyre")
    exact = bm.sensitivity(scenario, names=("tpF",))
    chained = bm.geometry_sensitivity(scenario, ["tpF"])["tpF"]
    assert chained["weave_speed"] == pytest.approx(exact.d_weave_speed["tpF"], rel=1e-3)
    assert chained["capsize_speed"] == pytest.approx(exact.d_capsize_speed["tpF"], rel=1e-3)
    spec = tmp_path / "o.yaml"
    spec.write_text("bike: benchmark\nmodel: tyre\nvariables:\n  tpF: {min: 0, max: 30 mm}\nmaximise: capsize-speed\n")
    result = bm.optimise(str(spec))
    assert exact.d_capsize_speed["tpF"] < 0 and result.converged and result.variables["tpF"] == 0.0


@pytest.mark.parametrize("model, bike, rider, stiffness, change, words", [
    ("rider-lean", "jamis", "relaxed", None, {"zU": 1.0}, "upper body: z = 1 m is below the ground"),
    ("rider-lean", "jamis", "relaxed", None, {"zhip": -5.0}, "hip_z = -5 m is more than 3 m above the ground"),
    ("rider-lean", "jamis", "relaxed", None, {"xU": 100.0}, "x = 100 m is more than 3 m from the rear contact"),
    ("rider-lean", "jamis", "relaxed", None, {"mU": 1e6}, "mass = 1e\\+06 kg is outside 5..300 kg"),
    ("flexible", "jamis", "relaxed", "steel", {"kf": 1e20}, "fork bending: stiffness = 1e\\+20 N m/rad is outside"),
    ("flexible", "jamis", "relaxed", "steel", {"cs": 1e9}, "steer_damping = 1e\\+09 N m s/rad is above 1000"),
    ("tyre", "benchmark", None, None, {"tpF": 5.0}, "pneumatic_trail = 5 m is above 0.1 m"),
])
def test_a_member_input_no_rider_or_bicycle_has_is_warned(model, bike, rider, stiffness, change, words):
    """Values no rider, frame or tyre has, given by name (as a sweep or an optimisation gives them), are warned about
    as the bicycle's are: an upper body below the ground or far from the bicycle, a fork stiffer than any, a
    pneumatic trail of metres."""
    with pytest.warns(bm.BikemassWarning, match=words):
        bm.Scenario(bike, rider, stiffness, model=model).build(change)


def test_an_upper_body_inertia_that_is_no_inertia_is_refused():
    """``IUxz = 100`` makes the upper body's inertia tensor indefinite (a principal moment of -97.8 kg m^2): refused
    in one line, as the bicycle's bodies' are."""
    with pytest.raises(bm.InputError, match="IUxz: an inertia tensor with principal moments >= 0"):
        bm.Scenario("jamis", "relaxed", model="rider-lean").build({"IUxz": 100.0})


def test_changes_to_one_part_are_made_together():
    """``IUzz = 10`` and ``IUxz = 3`` make a positive definite upper-body inertia, but set one at a time the part
    passed through ``IUxz = 3`` with the old ``IUzz`` (indefinite) and was refused: a part's changes are made at
    once, so its checks see it as asked for."""
    built = bm.Scenario("jamis", "relaxed", model="rider-lean").build({"IUzz": 10.0, "IUxz": 3.0})
    assert (built.values()["IUzz"], built.values()["IUxz"]) == (10.0, 3.0)


def test_arms_on_a_parameter_set_with_a_seated_rider_have_no_grips_to_check():
    """A parameter set (no contacts: section) with a rider seated and the arms member crashed looking for its
    grips ("internal error AttributeError"); where the hands are is not known there, and a stiffness says so."""
    with pytest.warns(bm.BikemassWarning, match="not known to be on a grip"):
        built = bm.Scenario("kooijman2008", "relaxed", model="arms", arms={"stiffness": 10.0}).build()
    assert built.arms.stiffness == 10.0
