"""``bm.simulate`` against scipy's matrix exponential at every sample, and its refusals and its stop
where an unstable model's response grows without bound (issue 35)."""

import math
import warnings

import numpy as np
import pytest
import scipy.linalg

import bikemass as bm
from bikemass.analysis.handling.time_response import DIVERGED, LIMITS
from bikemass.cli.main import main
from bikemass.core.errors import BikemassWarning, InputError

P = bm.parameters("benchmark")


def reference(model, v, x0, u, t):
    """``x(t)`` of ``x' = A x + B u`` (u held) by scipy's expm of the augmented matrix at each time."""
    A, B = model.state_matrix(v), model.input_matrix(v)
    n, m = B.shape
    M = np.zeros((n + m, n + m))
    M[:n, :n], M[:n, n:] = A, B
    z0 = np.concatenate([x0, u])
    return np.array([(scipy.linalg.expm(M * tk) @ z0)[:n] for tk in t])


@pytest.mark.parametrize("speed", [3.0, 4.6, 8.0])
def test_every_sample_is_the_matrix_exponentials(speed):
    """Initial roll rate and a steer-torque step: every sample to 1e-10 of the largest state
    (the doubling's rounding grows with log2 of the samples)."""
    r = bm.simulate(P, speed, {"roll-rate": 0.5}, {"steer-torque": ("step", 0.3)}, duration=5.0, step=0.01)
    model = bm.linear_model(P)
    want = reference(model, speed, np.array([0, 0, 0.5, 0, 0, 0.0]), np.array([0, 0.3]), r.time)
    assert len(r.time) == 501
    assert np.max(np.abs(r.values - want)) <= 1e-10 * max(1.0, np.abs(want).max())


def test_an_impulse_is_the_jump_of_the_state():
    r = bm.simulate(P, 5.0, inputs={"steer-torque": ("impulse", 0.2)}, duration=1.0, step=0.05)
    model = bm.linear_model(P)
    x0 = model.input_matrix(5.0)[:, 1] * 0.2
    assert np.max(np.abs(r.values - reference(model, 5.0, x0, np.zeros(2), r.time))) <= 1e-12


def test_a_growing_response_stops_with_a_warning_before_it_overflows():
    """At 1 m/s the weave grows: 1000 s would overflow (1e300 and NaN); the response stops at the last
    sample where every state is within DIVERGED times its bound, every sample finite and exact."""
    with pytest.warns(BikemassWarning, match="grows without bound"):
        r = bm.simulate(P, 1.0, {"roll-angle": 0.01}, duration=1000.0, step=0.01)
    assert 2 < r.time[-1] < 1000 and np.all(np.isfinite(r.values))
    bound = np.array([DIVERGED * LIMITS[s] for s in r.signal_units])
    assert np.all(np.abs(r.values) <= bound)
    want = reference(bm.linear_model(P), 1.0, np.array([0.01, 0, 0, 0, 0, 0]), np.zeros(2), r.time[-1:])
    assert np.allclose(r.values[-1], want[0], rtol=1e-8)
    with pytest.warns(BikemassWarning):                    # at standstill the bicycle falls
        r = bm.simulate(P, 0.0, {"roll-angle": 0.01}, duration=60.0)
    assert r.time[-1] < 10 and np.all(np.abs(r.values) <= bound)


def test_a_stable_response_gives_no_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error", BikemassWarning)
        r = bm.simulate(P, 5.0, {"roll-angle": 0.01}, duration=100.0)
    assert len(r.time) == 10001


@pytest.mark.parametrize("initial, inputs", [({"roll-angle": 1e300}, None), ({"roll-rate": 1e3}, None),
                                             ({"lateral": -1e9}, None), (None, {"steer-torque": ("step", 1e6)}),
                                             (None, {"roll-torque": ("impulse", -1e300)})])
def test_absurd_initial_values_and_inputs_are_refused(initial, inputs):
    with pytest.raises(InputError, match="at most"):
        bm.simulate(P, 5.0, initial, inputs)
    assert bm.simulate(P, 5.0, {"roll-angle": math.pi / 2}, duration=0.1).values[0, 0] == math.pi / 2


def test_the_command_line_prints_no_nan(capsys):
    code = main(["simulate", "benchmark", "--speed", "1", "--initial", "roll-angle=0.01", "--duration", "1000",
                 "--format", "csv"])
    out, err = capsys.readouterr()
    assert code == 0 and "nan" not in out.lower() and "inf" not in out.lower()
    assert err.count("\n") == 1 and "grows without bound" in err
    assert main(["simulate", "benchmark", "--speed", "5", "--initial", "roll-angle=1e300"]) == 2
    assert "--initial" in capsys.readouterr().err


def test_the_taylor_exponential_is_scipys():
    """The hold matrices' exponential (Taylor below norm 1, scipy's Pade above) against scipy's expm on
    random matrices of 1-norm 1e-4 to 3, to 1e-14 of the largest entry (seeded)."""
    from bikemass.analysis.handling.discrete import expm
    rng = np.random.default_rng(5)
    for norm in np.geomspace(1e-4, 3.0, 60):
        M = rng.normal(size=(8, 8))
        M *= norm / np.abs(M).sum(axis=0).max()
        want = scipy.linalg.expm(M)
        assert np.abs(expm(M) - want).max() <= 1e-14 * np.abs(want).max()
