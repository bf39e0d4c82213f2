"""Issue 35: absurd values are warned about, impossible ones refused, and the API never raises a
raw exception.

* Tyres of relaxation length down to 1e-12 m keep their weave crossing (the limit: the same model
  at 1e-6 m, where the lag is still resolved by a plain eigensolver), checked on eigenvalues that
  mpmath computes in 60 digits; tyre coefficients no tyre has are warned about.
* Values the model computes but no bicycle has (gravity 1e9, a steer axis at 89.99 deg, a
  1e-12 kg front frame, S = 1e-300 I, ...) are warned about through the API as in a file;
  ``replace`` with an unknown name, a speed above 1000 m/s, tyres with the Whipple model, a
  repeated ``--initial`` or ``--input`` are refused in one line.
* A property test (hypothesis, derandomized) feeds hostile values to the facade's arguments:
  every call returns or raises :class:`bikemass.InputError`, nothing else.
"""

import math
import warnings

import mpmath
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import bikemass as bm
from bikemass.analysis.engine.crossings import separated_eigenvalues
from bikemass.cli.main import main

BENCHMARK = bm.parameters("benchmark")
FRAMES = ("benchmark", "jamis", "cargo", "cargo_loaded", "salsa_fargo@MD", "specialized_diverge@56", "bmc_roadmachine@56")


def tyres(relaxation=0.175, cornering=11.46, camber=0.573):
    tyre = {"cornering_coefficient": f"{cornering} 1/rad", "camber_coefficient": f"{camber} 1/rad",
            "relaxation_length": f"{relaxation} m"}
    return {"front": tyre, "rear": tyre}


def caught(call):
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        result = call()
    return result, [str(w.message) for w in seen if issubclass(w.category, bm.BikemassWarning)]


@pytest.mark.parametrize("relaxation", [1e-10, 1e-11, 1e-12])
def test_a_vanishing_relaxation_length_keeps_the_weave_crossing(relaxation):
    limit = caught(lambda: bm.stability(BENCHMARK, model="tyre", tyres=tyres(1e-6)))[0].weave_speeds
    result, said = caught(lambda: bm.stability(BENCHMARK, model="tyre", tyres=tyres(relaxation)))
    # the lag's effect is O(relaxation): at 1e-6 m already within 1e-6 m/s of the limit
    assert len(result.weave_speeds) == 1 and result.weave_speeds[0] == pytest.approx(limit[0], abs=1e-6)
    assert result.weave_speeds[0] == pytest.approx(4.3309, abs=1e-4)
    assert any("relaxation_length" in s for s in said)                    # implausible, and said so


def test_separated_eigenvalues_equal_60_digit_ones():
    model = bm.linear_model(BENCHMARK, model="tyre", tyres=tyres(1e-12))
    A = model.state_matrix(4.3309) if hasattr(model, "state_matrix") else None
    C = np.asarray(model.dynamic_coefficients, dtype=float)
    A = sum(4.3309 ** k * C[k] for k in range(len(C)))
    mpmath.mp.dps = 60
    exact = mpmath.eig(mpmath.matrix(A.tolist()), left=False, right=False)
    exact = np.array([complex(z) for z in exact])
    mine = separated_eigenvalues(A)
    slow = exact[np.abs(exact) < 1e6]
    for z in slow:                                                        # the weave, capsize and caster roots
        assert np.min(np.abs(mine - z)) <= 1e-8 * max(1.0, abs(z)), z
    plain = np.linalg.eigvals(A)
    weave = slow[np.argmax(slow.imag)]
    assert np.min(np.abs(plain - weave)) > 1e-4                           # what the plain eigensolver loses


@pytest.mark.parametrize("call, needle", [
    (lambda: BENCHMARK.replace(IFyy=1e9), "IFyy = 1e+09 kg m^2 breaks the triangle inequality"),
    (lambda: BENCHMARK.replace(mH=1e-12), "radius of gyration"),
    (lambda: BENCHMARK.replace(g=1e9), "g = 1e+09 m/s^2 is outside"),
    (lambda: BENCHMARK.replace(lam=1.5707), "lam = 1.5707 rad tilts the steer axis"),
    (lambda: bm.parameters({**BENCHMARK.to_dict(), "lam": 1.5707}), "tilts the steer axis"),
    (lambda: bm.stability(BENCHMARK, stiffness=[[1e-300, 0.0], [0.0, 1e-300]]), "frame stiffness S"),
    (lambda: bm.stability(BENCHMARK, model="tyre", tyres=tyres(1e6)), "relaxation_length = 1e+06 m"),
    (lambda: bm.stability(BENCHMARK, model="tyre", tyres=tyres(camber=573.0)), "camber_coefficient = 573"),
    (lambda: bm.stability(BENCHMARK, model="tyre", tyres=tyres(cornering=1e8)), "cornering_coefficient = 1e+08"),
])
def test_absurd_values_are_warned_about(call, needle):
    _, said = caught(call)
    assert any(needle in s for s in said), said


@pytest.mark.parametrize("name", FRAMES)
def test_shipped_bicycles_raise_no_absurdity_warning(name):
    _, said = caught(lambda: bm.parameters(name))
    assert not [s for s in said if any(k in s for k in ("radius of gyration", "m/s^2 is outside", "tilts the steer"))]
    _, said = caught(lambda: bm.stability(BENCHMARK, model="tyre"))       # the default tyres
    assert said == []


@pytest.mark.parametrize("call, needle", [
    (lambda: BENCHMARK.replace(trail=0.08), "replace: trail: one of the 26 benchmark parameter names"),
    (lambda: bm.stability(BENCHMARK, speeds=[0, 1e6]), "speeds of at most 1000 m/s"),
    (lambda: bm.eigenvalues(BENCHMARK, speeds=[0, 1000.5]), "speeds of at most 1000 m/s"),
    (lambda: bm.linear_model(BENCHMARK, model="whipple", tyres=tyres()), "a model with the tyre member"),
    (lambda: bm.stability(BENCHMARK, tyres=tyres()), "a model with the tyre member"),
    (lambda: bm.lane_change(BENCHMARK, 5.0, step=0.0), "step: 0.0: a time step in s"),
    (lambda: bm.lane_change(BENCHMARK, 5.0, step=1e-12), "a time step of at least"),
    (lambda: bm.handling(BENCHMARK, speeds=[5.0], gains={"kDelta": "x"}), "a speed as each key"),
    (lambda: bm.handling(BENCHMARK, speeds=[5.0], gains={}), "at least one speed"),
    (lambda: bm.Gains(None, 1, 2, 3, 4), "gains: k_delta: a finite number"),
    (lambda: bm.stability(BENCHMARK, marginal=1e300), "marginal"),
    (lambda: bm.stability(BENCHMARK, speeds=[10 ** 400]), "speeds"),
    (lambda: bm.sensitivity(BENCHMARK, None, 10 ** 400), "vmax"),
    (lambda: bm.uncertainty("jamis", {"mB": 10 ** 400}), "a finite standard deviation"),
    (lambda: bm.load_bicycle({}, 1e300), "a name is a string"),
    (lambda: bm.plot_handling(bm.handling(BENCHMARK, [5.0]), stable_speeds=[1.0]), "stable_speeds"),
])
def test_the_api_refuses_in_one_input_error(call, needle):
    with pytest.raises(bm.InputError, match=None) as info:
        call()
    assert needle in str(info.value) and "\n" not in str(info.value)


def test_gains_that_overflow_the_loop_get_no_level():
    r, said = caught(lambda: bm.handling(BENCHMARK, [5.0], gains=bm.Gains(*(1e300,) * 5)))
    assert r.levels == (None,) and "not computable" in r.gain_source[0] and said


@pytest.mark.parametrize("argv", [
    ["--initial", "roll-rate=0.5", "--initial", "roll-rate=1"],
    ["--initial", "roll-rate=0.5,roll-rate=1"],
    ["--input", "steer-torque=step:1", "--input", "steer-torque=impulse:2"],
])
def test_a_repeated_initial_or_input_is_refused(capsys, argv):
    assert main(["simulate", "benchmark", "--speed", "5", *argv]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "each name once" in err


HOSTILE = st.sampled_from([None, 0, -1, 0.0, -0.0, 1e-300, 1e300, math.nan, math.inf, -math.inf, True, "x", "",
                           "5", [], [1], [1, 2], [[1, 2], [3, 4]], {}, {"a": 1}, (1, 2, 3, 4, 5), ("a",) * 5,
                           b"x", 5.0, 1e6, -5.0, 10 ** 400, complex(1, 1), {"kDelta": "x"}, {5.0: (1, 2, 3, 4, 5)},
                           [0, 1e6], "steer-torque", "roll-angle", "double", "whipple", "tyre", "flexible"]) \
    | st.floats(allow_nan=True, allow_infinity=True) | st.integers(min_value=-10 ** 30, max_value=10 ** 30) \
    | st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=3)

CALLS = {
    "stability speeds, marginal": lambda a, b: bm.stability(BENCHMARK, speeds=a, marginal=b),
    "stability model, tyres": lambda a, b: bm.stability(BENCHMARK, model=a, tyres=b),
    "stability stiffness": lambda a, b: bm.stability(BENCHMARK, stiffness=a),
    "eigenvalues speeds, max_speeds": lambda a, b: bm.eigenvalues(BENCHMARK, speeds=a, max_speeds=b),
    "handling speeds, gains": lambda a, b: bm.handling(BENCHMARK, speeds=a, gains=b),
    "lane_change speed, gains": lambda a, b: bm.lane_change(BENCHMARK, a, gains=b),
    "lane_change kind, step": lambda a, b: bm.lane_change(BENCHMARK, 5.0, kind=a, step=b),
    "transfer_function speed, input": lambda a, b: bm.transfer_function(BENCHMARK, a, b, "roll-angle"),
    "frequency_response frequencies": lambda a, b: bm.frequency_response(BENCHMARK, 5.0, "steer-torque",
                                                                          "roll-angle", frequencies=a),
    "mode_shapes speed": lambda a, b: bm.mode_shapes(BENCHMARK, a),
    "linear_model stiffness, model": lambda a, b: bm.linear_model(BENCHMARK, stiffness=a, model=b),
    "replace": lambda a, b: BENCHMARK.replace(c=a, w=b),
    "parameters": lambda a, b: bm.parameters(a, b),
    "matrices": lambda a, b: bm.matrices(BENCHMARK, a),
    "speeds": lambda a, b: bm.speeds(a, b),
    "Gains": lambda a, b: bm.handling(BENCHMARK, [5.0], gains=bm.Gains(a, b, 12.66, 0.18, 0.1)),
    "sensitivity stiffness, vmax": lambda a, b: bm.sensitivity(BENCHMARK, a, b),
    "uncertainty spreads, method": lambda a, b: bm.uncertainty(BENCHMARK, {"mB": a}, method=b),
    "load_bicycle name, size": lambda a, b: bm.load_bicycle("jamis", a, b),
    "Scenario rider, stiffness": lambda a, b: bm.Scenario("benchmark", a, b).build(),
}


@pytest.mark.slow
@settings(max_examples=80, derandomize=True, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(name=st.sampled_from(sorted(CALLS)), a=HOSTILE, b=HOSTILE)
def test_the_facade_returns_or_raises_input_error(name, a, b):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            CALLS[name](a, b)
        except bm.InputError as exc:
            assert str(exc) and "\n" not in str(exc)


def test_the_names_module_lists_the_parameter_fields():
    """Contract: models.names.NAMES (read by the plausibility checks) is BenchmarkParameters' fields."""
    import dataclasses

    from bikemass.models import names
    assert names.NAMES == tuple(f.name for f in dataclasses.fields(bm.BenchmarkParameters)) == bm.PARAMETER_NAMES


@pytest.mark.parametrize("call", [
    lambda p: bm.simulate(p, 5.0, step=10 ** 400),
    lambda p: bm.simulate(p, 5.0, duration=10 ** 400),
    lambda p: bm.simulate(p, 5.0, initial={"roll-rate": 10 ** 400}),
    lambda p: bm.simulate(p, 5.0, inputs={"steer-torque": ("step", 10 ** 400)}),
    lambda p: bm.simulate(p, 5.0, nonlinear=True, step=10 ** 400),
    lambda p: bm.simulate(p, 5.0, nonlinear=True, initial={"roll-rate": 10 ** 400}),
    lambda p: bm.simulate(p, 10 ** 400, nonlinear=True),
    lambda p: bm.steady_turn(p, 5.0, radius=10 ** 400),
], ids=["step", "duration", "initial", "input", "nonlinear-step", "nonlinear-initial", "nonlinear-speed", "turn-radius"])
def test_an_integer_beyond_the_float_range_is_refused_not_raised(call):
    """An integer of 10^400 (no float holds it: math.isfinite raises OverflowError on it) is one InputError."""
    with pytest.raises(bm.InputError):
        call(bm.parameters("benchmark"))
