"""The model family's Whipple member, derived with sympy.physics.mechanics and shipped as generated
code, against Meijaard et al. (2007) and models/whipple.py; the registry of model names."""

import numpy as np
import pytest

from bikemass.scenario.scenario import parameters
from bikemass.core.errors import InputError
from bikemass.models.family import build, coefficients, linear_model, state_coefficients, values
from bikemass.models.members.flexible.parameters import Compliances
from bikemass.models.registry import ModelChoice, parse_model
from bikemass.models.whipple import whipple_model
from test_stability import TABLE_3_13, TABLE_4_1

BENCHMARK = parameters("benchmark")


def _canonical(model):
    """M, C1, K0, K2 of a Whipple LinearModel's second-order form."""
    mech, g = model.mechanics, BENCHMARK.g
    assert not np.any(mech.C[0]) and not np.any(mech.K[1])
    return {"M": mech.M, "C1": mech.C[1], "K0": mech.K[0] / g, "K2": mech.K[2]}


def test_derived_whipple_matrices_are_meijaard_2007_to_1e_12():
    got = _canonical(build("whipple", BENCHMARK))
    for name, ref in TABLE_3_13.items():
        ref = np.array(ref)
        assert np.all(got[name][ref == 0] == 0), name
        np.testing.assert_allclose(got[name][ref != 0], ref[ref != 0], rtol=1e-12, atol=0, err_msg=name)
    assert np.array_equal(build("whipple", BENCHMARK).mechanics.F, np.eye(2))


def test_derived_whipple_eigenvalues_are_meijaard_2007_table_2_to_1e_12():
    model = build("whipple", BENCHMARK)
    at0 = np.sort(np.linalg.eigvals(model.dynamic_matrix(0.0)).real)
    np.testing.assert_allclose(at0, [-5.53094371765393, -3.13164324790656, 3.13164324790656, 5.53094371765393],
                               rtol=0, atol=1e-12)
    for v, re, im, capsize, castor in TABLE_4_1:
        ev = np.linalg.eigvals(model.dynamic_matrix(float(v)))
        for ref in (complex(re, im), complex(re, -im), capsize, castor):
            assert np.min(np.abs(ev - ref)) < 1e-12, (v, ref)


@pytest.mark.parametrize("seed", range(5))
def test_derived_whipple_equals_models_whipple_for_any_parameters(seed):
    """The generated code and the closed form of Meijaard's Appendix A (models/whipple.py) agree on
    every state-space coefficient, kinematics included, for parameter sets far from the benchmark."""
    rng = np.random.default_rng(seed)
    p = BENCHMARK.replace(**{k: v * rng.uniform(0.6, 1.4) for k, v in BENCHMARK.to_dict().items()})
    mine, ref = build("whipple", p), whipple_model(p)
    assert mine.state_names == ref.state_names and mine.input_names == ref.input_names
    np.testing.assert_allclose(mine.A, ref.A, rtol=0, atol=1e-11 * np.max(np.abs(ref.A)))
    np.testing.assert_allclose(mine.B, ref.B, rtol=0, atol=1e-12 * np.max(np.abs(ref.B)))
    np.testing.assert_allclose(mine.mechanics.M, ref.mechanics.M, rtol=1e-12)


def test_arrays_of_parameters_give_stacked_matrices():
    rng = np.random.default_rng(7)
    base = values("whipple", BENCHMARK)
    batch = {k: v * rng.uniform(0.8, 1.2, size=(4, 3)) for k, v in base.items()}
    batch["g"] = 9.81                                            # a float among arrays broadcasts
    E, A, B = coefficients("whipple", batch)
    As, Bs = state_coefficients("whipple", batch)
    assert E.shape == (4, 3, 6, 6) and A.shape[:2] == (4, 3) and As.shape == A.shape and Bs.shape == B.shape
    for i, j in ((0, 0), (3, 2), (1, 1)):
        one = linear_model("whipple", {k: float(np.broadcast_to(v, (4, 3))[i, j]) for k, v in batch.items()})
        np.testing.assert_allclose(As[i, j], one.A, rtol=1e-13, atol=1e-13)
        np.testing.assert_allclose(Bs[i, j], one.B, rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("text, members", [
    ("whipple", ()), ("rider-lean", ("rider-lean",)), ("tyre", ("tyre",)),
    ("rider-lean+tyre", ("rider-lean", "tyre")), ("tyre+rider-lean", ("rider-lean", "tyre")),
    (" tyre + whipple ", ("tyre",)), (ModelChoice(("tyre",)), ("tyre",)),
    ("flexible+rider-lean+tyre", ("rider-lean", "tyre", "flexible"))])
def test_model_names_in_any_order(text, members):
    assert parse_model(text).members == members


@pytest.mark.parametrize("text, message", [
    ("wobble", "unknown model 'wobble': one of whipple, rider-lean, tyre, flexible"),
    ("tyre+tyre", "'tyre' given twice"), ("", "a model name"), ("tyre+", "unknown model ''")])
def test_bad_model_names_are_one_line_naming_the_choices(text, message):
    with pytest.raises(InputError, match=message) as err:
        parse_model(text)
    assert "\n" not in str(err.value)


def test_a_model_gets_the_parameters_it_needs():
    with pytest.raises(InputError, match="the rider split at the hips for rider-lean"):
        build("rider-lean", BENCHMARK)
    with pytest.raises(InputError, match=r"no tyre parameters for the model whipple \(add the tyre member: tyre\)"):
        build("whipple", BENCHMARK, tyres=object())
    with pytest.raises(InputError, match="flexible model needs the frame's and the fork's compliances"):
        build("tyre+flexible", BENCHMARK)
    with pytest.raises(InputError, match=r"no flexible parameters for the model tyre \(add the flexible member: tyre\+flexible\)"):
        build("tyre", BENCHMARK, compliances=Compliances())
    with pytest.raises(ValueError, match="parameters missing: w"):
        coefficients("whipple", {k: v for k, v in values("whipple", BENCHMARK).items() if k != "w"})
