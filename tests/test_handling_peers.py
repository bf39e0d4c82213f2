"""Handling against independent peers and closed forms.

* Frequency responses equal ``C (j w I - A)^-1 B`` formed here (numpy's LU solve, frequency by
  frequency) from BicycleParameters' own ``Bicycle.state_space`` for every bicycle it ships, at
  several speeds, every input and output (1e-6 dB, 1e-6 deg), and BicycleParameters' own
  ``plot_bode`` data.
* The benchmark at 4.6 m/s from a roll rate of 0.5 rad/s (Meijaard et al. 2007, Fig. 4) equals
  ``expm(A t) x0`` of Meijaard's printed matrices (their Sec. 4, 14-15 digits) and the kinematic
  rows from their Table 1, formed here (1e-8 rad, rad/s and m).
* Transfer functions evaluated from zeros, poles and gain equal the resolvent at complex
  frequencies; mode shapes are eigenvectors of the whole state matrix; the step response settles
  on the static gain and the impulse response is the step response's slope ``A x + B u``.
"""

import warnings
from pathlib import Path

import numpy as np
import pytest
import scipy.linalg

import bikemass as bm
from bikemass.models.whipple import whipple_model

bp = pytest.importorskip("bicycleparameters")

BP_DATA = Path(bp.__file__).parent / "app-data"
SHIPPED = sorted(p.parent.parent.name for p in BP_DATA.glob("bicycles/*/Parameters/*Benchmark.txt"))
SPEEDS = (0.5, 2.0, 4.6, 7.0, 12.0)
INPUTS = ("roll-torque", "steer-torque")
OUTPUTS = ("roll-angle", "steer-angle", "roll-rate", "steer-rate")
W = np.geomspace(0.01, 1000.0, 1000)


def resolvent(A, B, C, w):
    """``C (j w I - A)^-1 B`` at every frequency, one LU solve each (independent of bikemass)."""
    identity = np.eye(len(A))
    return np.array([C @ np.linalg.solve(1j * x * identity - A, B) for x in w])


def phase_gap(a, b):
    """Largest difference of two phase curves (deg), modulo 360."""
    return np.abs((np.asarray(a) - np.asarray(b) + 180.0) % 360.0 - 180.0).max()


def bp_bicycle(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return bp.Bicycle(name, pathToData=str(BP_DATA))


@pytest.mark.parametrize("name", SHIPPED)
def test_frequency_responses_equal_bicycleparameters_state_space(name, capsys):
    bike = bp_bicycle(name)
    params = bm.load_parameter_text(BP_DATA / "bicycles" / name / "Parameters" / f"{name}Benchmark.txt").parameters
    capsys.readouterr()
    for v in SPEEDS:
        A, B = bike.state_space(v, nominal=True)
        G = resolvent(np.asarray(A, float), np.asarray(B, float), np.eye(4), W)     # (n, 4, 2)
        for j, inp in enumerate(INPUTS):
            for i, out in enumerate(OUTPUTS):
                fr = bm.frequency_response(params, v, inp, out, W)
                theirs = G[:, i, j]
                assert np.abs(fr.magnitude - 20 * np.log10(np.abs(theirs))).max() < 1e-6, (v, inp, out)
                assert phase_gap(fr.phase, np.degrees(np.angle(theirs))) < 1e-6, (v, inp, out)


def test_bode_data_equal_bicycleparameters_plot_bode(capsys):
    """BicycleParameters' ``plot_bode`` (dtk's ``bode``: 1000 frequencies from 1 to 100 rad/s,
    phase unwrapped the same way)."""
    bike = bp_bicycle("Benchmark")
    params = bm.load_parameter_text(BP_DATA / "bicycles" / "Benchmark" / "Parameters" / "BenchmarkBenchmark.txt").parameters
    w = np.logspace(0, 2, 1000)
    for u, inp in enumerate(INPUTS):
        for y, out in enumerate(OUTPUTS):
            magnitude, phase, fig = bike.plot_bode(5.0, u, y)
            fr = bm.frequency_response(params, 5.0, inp, out, w)
            assert np.abs(fr.magnitude - magnitude).max() < 1e-6
            assert phase_gap(fr.phase, phase) < 1e-6
    capsys.readouterr()


# Meijaard et al. 2007, Sec. 4 (K0 without g), and Table 1 (w, c, lam)
M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
WHEELBASE, TRAIL, TILT, G = 1.02, 0.08, np.pi / 10, 9.81


def meijaard_state_matrix(v):
    """States roll, steer, roll rate, steer rate, heading, lateral (rear contact)."""
    A = np.zeros((6, 6))
    A[:2, 2:4] = np.eye(2)
    Minv = np.linalg.inv(M)
    A[2:4, :2] = -Minv @ (G * K0 + v ** 2 * K2)
    A[2:4, 2:4] = -Minv @ (v * C1)
    A[4, 1] = v * np.cos(TILT) / WHEELBASE
    A[4, 3] = TRAIL * np.cos(TILT) / WHEELBASE
    A[5, 4] = v
    return A


def test_benchmark_response_at_4_6_m_s_equals_the_matrix_exponential():
    r = bm.simulate(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5}, duration=5.0, step=0.01)
    A = meijaard_state_matrix(4.6)
    x0 = np.array([0, 0, 0.5, 0, 0, 0])
    exact = np.array([scipy.linalg.expm(A * t) @ x0 for t in r.time])
    assert r.names == ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral")
    assert np.abs(r.values - exact).max() < 1e-8
    assert len(r.time) == 501 and r.time[-1] == pytest.approx(5.0)
    # Meijaard's Fig. 4: the weave oscillation decays (the bicycle is self-stable at 4.6 m/s)
    assert abs(r["roll-rate"][-1]) < 0.2 * 0.5


def test_zeros_poles_gain_give_the_resolvent():
    model = whipple_model(bm.parameters("jamis", "relaxed"))
    s = np.array([0.3 + 2.1j, -1.0 + 7.0j, 5.0 + 0.5j, 40.0j])
    for inp in INPUTS:
        for out in model.output_names:
            tf = bm.transfer_function(model, 6.0, inp, out)
            A, B, C, _ = model.state_space(6.0, [out])
            direct = np.array([(C @ np.linalg.solve(x * np.eye(len(A)) - A, B))[0, model.input_index(inp)] for x in s])
            assert np.allclose(tf(s), direct, rtol=1e-9, atol=0), (inp, out)
            assert len(tf.poles) - len(tf.zeros) == tf.relative_degree >= 1


def test_mode_shapes_are_eigenvectors_of_the_whole_model():
    model = whipple_model(bm.parameters("benchmark"), stiffness=[[6000.0, 1200.0], [1200.0, 3600.0]])
    shapes = bm.mode_shapes(model, 5.5)
    A = model.state_matrix(5.5)
    for i, value in enumerate(shapes.eigenvalues):
        q = dict(zip(shapes.coordinates, shapes.shapes[i]))
        x = np.array([q["roll-angle"], q["steer-angle"], value * q["roll-angle"], value * q["steer-angle"],
                      q["heading"], q["lateral"]])
        assert np.abs(A @ x - value * x).max() < 1e-9 * np.abs(x).max()
        assert np.abs(shapes.shapes[i, :2]).max() == pytest.approx(1.0)


def test_step_settles_on_the_static_gain_and_the_impulse_is_its_slope():
    params = bm.parameters("benchmark")
    step = bm.simulate(params, 5.0, inputs={"steer-torque": ("step", 0.2)}, duration=100.0, step=0.005)
    A = meijaard_state_matrix(5.0)[:4, :4]
    B = np.linalg.inv(np.block([[np.eye(2), np.zeros((2, 2))], [np.zeros((2, 2)), M]]))[:, 3]
    static = -np.linalg.solve(A, B * 0.2)
    assert np.abs(step.values[-1, :4] - static).max() < 1e-8
    impulse = bm.simulate(params, 5.0, inputs={"steer-torque": ("impulse", 0.2)}, duration=2.0, step=0.005)
    slope = step.values[:401, :4] @ A.T + B * 0.2          # x' = A x + B u along the step response
    assert np.abs(impulse.values[:, :4] - slope).max() < 1e-9 * np.abs(slope).max()
