"""Closed loops (``--control FILE``, ``control=``): a feedback from named signals to named inputs, each
gain scheduled in speed, against an independent closed-loop computation.

The reference: BicycleParameters' own canonical matrices and state-space form of the published
parameter table (``benchmark_par_to_canonical``, ``ab_matrix``: a peer's code, not bikemass's), the
published gain law written out here with numpy (``k(v)`` interpolated, ``A + B K``), and the lowest
self-stable speed found by brentq on the largest real part of its eigenvalues.
"""

import json
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml
from scipy.optimize import brentq

import bikemass as bm
from bikemass.cli.main import main
from bikemass.core.errors import InputError
from bikemass.core.paths import frames_dir

peer = pytest.importorskip("bicycleparameters.bicycle")

EXAMPLES = Path(__file__).resolve().parents[1] / "examples" / "control"
BENCHMARK = str(frames_dir() / "benchmark.yaml")
META = ("name", "rider_included", "source")
RAMP = (0.0, 1.5, 4.7)
"""The balance-assist law's speeds (m/s): k(v) = g (4.7 - v) from 1.5 to 4.7 m/s, ramped up from 0 at
standstill below 1.5 m/s, 0 from 4.7 m/s (Haitjema, Alizadehsaravi & Moore 2024, src/control.py)."""


def table(path):
    """The 26 published values of a parameter file, as the peer takes them."""
    return {k: v for k, v in yaml.safe_load(Path(path).read_text()).items() if k not in META}


def law(g):
    """The balance-assist law of model gain ``g`` as a control mapping (N m s/rad)."""
    return {"steer-torque": {"roll-rate": {"speeds": list(RAMP), "gains": [0.0, 3.2 * g, 0.0]}}}


def peer_closed_loop(par, gains):
    """``v -> A + B K`` (4x4) from the peer's matrices; ``gains(v)``: (2, 4) with u = K x added."""
    M, C1, K0, K2 = peer.benchmark_par_to_canonical(par)

    def A(v):
        a, b = peer.ab_matrix(M, C1, K0, K2, v, par["g"])
        return a + b @ gains(v)
    return A


def peer_crossings(A, lo=0.02, hi=10.0, n=500):
    """Every speed in (lo, hi) where the largest real part of A(v)'s eigenvalues changes sign."""
    f = lambda v: np.linalg.eigvals(A(v)).real.max()      # noqa: E731
    v = np.linspace(lo, hi, n)
    fv = np.array([f(x) for x in v])
    return [brentq(f, v[i], v[i + 1], xtol=1e-14) for i in np.flatnonzero(np.sign(fv[:-1]) != np.sign(fv[1:]))]


def roll_rate_gain(g):
    def K(v):
        out = np.zeros((2, 4))
        out[1, 2] = np.interp(v, RAMP, [0.0, 3.2 * g, 0.0])    # steer torque from roll rate
        return out
    return K


def load(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")                # the riderless table's B inertia (a published set)
        return bm.parameters(str(EXAMPLES / f"{name}.yaml"))


@pytest.mark.parametrize("bike", ["browser", "browser-jason"])
@pytest.mark.parametrize("g", [3.9, 5.4, 8.0, 10.0])
def test_balance_assist_lowest_self_stable_speed_equals_an_independent_closed_loop(bike, g):
    """Riderless and ridden balance-assist bicycle, the two model gains the paper fitted (3.9, 5.4) and
    the two controller settings it rode (8, 10): the stable ranges' ends equal the peer's closed loop to
    1e-4 m/s (measured: 1e-12; the tolerance is the brief's, the remaining difference brentq's)."""
    result = bm.stability(load(bike), control=law(g), speeds=bm.speeds(0, 10, 0.01))
    reference = peer_crossings(peer_closed_loop(table(EXAMPLES / f"{bike}.yaml"), roll_rate_gain(g)))
    ends = [x for r in result.stable_speeds for x in r if 0 < x < 10]
    assert ends == pytest.approx(reference, abs=1e-4)
    assert result.stable_speeds[0][0] == pytest.approx(reference[0], abs=1e-4)


def test_the_control_files_hold_the_published_law():
    """The shipped control files are the law with the paper's fitted model gains 3.9 and 5.4."""
    for g in (3.9, 5.4):
        control = bm.load_control(EXAMPLES / f"balance-assist-{g}.yaml")
        for v in (0.0, 0.7, 1.5, 3.0, 4.7, 6.0):
            expected = 3.2 * g * v / 1.5 if v < 1.5 else max(g * (4.7 - v), 0.0)
            assert control.gain("steer-torque", "roll-rate", v) == pytest.approx(expected, abs=1e-12)


def test_the_balance_assist_stabilises_the_riderless_bicycle_below_its_open_loop_weave_speed():
    """A limit the law must meet: without control the riderless bicycle is stable only from its weave
    speed; with it, from a lower speed (the law's purpose), up to the same capsize speed (the gain is
    0 there)."""
    p = load("browser")
    open_loop = bm.stability(p, speeds=bm.speeds(0, 10, 0.01)).stable_speeds[0]
    closed = bm.stability(p, control=EXAMPLES / "balance-assist-5.4.yaml", speeds=bm.speeds(0, 10, 0.01))
    assert closed.stable_speeds[0][0] < open_loop[0] - 1.0
    assert closed.stable_speeds[0][1] == pytest.approx(open_loop[1], abs=1e-9)


def test_cli_stability_benchmark_with_control_equals_an_independent_closed_loop(capsys):
    """``bikemass stability benchmark --control FILE``: its critical speeds are the peer's closed-loop
    sign changes (1e-4 m/s asked; measured 1e-12)."""
    code = main(["stability", "benchmark", "--control", str(EXAMPLES / "balance-assist-5.4.yaml"),
                 "--speeds", "0:10:0.01", "--format", "json"])
    d = json.loads(capsys.readouterr().out)
    assert code == 0
    reference = peer_crossings(peer_closed_loop(table(BENCHMARK), roll_rate_gain(5.4)))
    speeds = sorted([*d["weave_speeds"], *d["capsize_speeds"]])
    assert speeds == pytest.approx(reference, abs=1e-4)
    assert [x for r in d["ranges"]["strict"]["exact"] for x in r if 0 < x < 10] == pytest.approx(reference, abs=1e-4)


def test_a_steer_rate_gain_is_a_steering_damper():
    """A constant steer-rate -> steer-torque gain of -c is a damper of c N m s/rad on the steer: the
    closed loop's eigenvalues are the roots of det(M s^2 + (v C1 + diag(0, c)) s + g K0 + v^2 K2),
    from the peer's matrices and numpy's polynomial roots (1e-9 relative)."""
    c = 0.8
    M, C1, K0, K2 = peer.benchmark_par_to_canonical(table(BENCHMARK))
    model = bm.linear_model(bm.parameters("benchmark"), control={"steer-torque": {"steer-rate": -c}})
    for v in (0.5, 3.0, 7.0):
        D = v * C1 + np.diag([0.0, c])
        K = 9.81 * K0 + v * v * K2
        # det of the 2x2 polynomial matrix, coefficients of s^4..s^0
        p = [np.poly1d([M[i, j], D[i, j], K[i, j]]) for i in range(2) for j in range(2)]
        roots = np.sort_complex((p[0] * p[3] - p[1] * p[2]).roots)
        ours = np.sort_complex(np.linalg.eigvals(model.dynamic_matrix(v)))
        assert ours == pytest.approx(roots, rel=1e-9, abs=1e-9)


def test_cli_tf_with_control_has_the_closed_loop_poles(capsys):
    """``bikemass tf --control``: the poles are the peer's closed-loop eigenvalues at that speed (plus the
    kinematic integrators' zeros cancelled out of roll angle / steer torque)."""
    v = 3.0
    code = main(["tf", "benchmark", "--speed", str(v), "--input", "steer-torque", "--output", "roll-angle",
                 "--control", str(EXAMPLES / "balance-assist-3.9.yaml"), "--format", "json"])
    d = json.loads(capsys.readouterr().out)
    assert code == 0
    poles = np.sort_complex([complex(re, im) for re, im in d["poles"]])
    expected = np.sort_complex(np.linalg.eigvals(peer_closed_loop(table(BENCHMARK), roll_rate_gain(3.9))(v)))
    assert poles == pytest.approx(expected, abs=1e-8)


def test_simulate_and_eig_take_a_control(capsys):
    law_file = str(EXAMPLES / "balance-assist-3.9.yaml")
    assert main(["simulate", "benchmark", "--speed", "2", "--initial", "roll-rate=0.5", "--control", law_file,
                 "--duration", "1", "--format", "json"]) == 0
    assert main(["bode", "benchmark", "--speed", "2", "--input", "steer-torque", "--output", "roll-rate",
                 "--control", law_file, "--frequencies", "1:10:3", "--format", "json"]) == 0
    assert main(["eig", "benchmark", "--speeds", "0:4:1", "--control", law_file, "--format", "json"]) == 0
    capsys.readouterr()
    modes = bm.eigenvalues(bm.parameters("benchmark"), speeds=[3.0], control=law_file)
    expected = np.linalg.eigvals(peer_closed_loop(table(BENCHMARK), roll_rate_gain(3.9))(3.0))
    assert np.sort_complex(modes.eigenvalues[0]) == pytest.approx(np.sort_complex(expected), abs=1e-9)


def test_a_scheduled_closed_loop_is_continuous_and_each_piece_a_polynomial():
    """Contract test: each piece of the closed loop equals A(v) + B(v) K(v) C at speeds inside it and at
    its ends (the schedule is continuous), for a schedule on two signals with different speeds."""
    control = {"steer-torque": {"roll-rate": {"speeds": [1.0, 3.0], "gains": [2.0, -1.0]},
                                "steer-angle": {"speeds": [0.0, 2.0, 5.0], "gains": [0.0, 4.0, 1.0]}},
               "roll-torque": {"roll-angle": 3.0}}
    open_loop = bm.linear_model(bm.parameters("benchmark"))
    closed = bm.linear_model(open_loop, control=control)
    assert closed.breaks == (0.0, 1.0, 2.0, 3.0, 5.0)
    for v in (0.0, 0.5, 1.0, 1.7, 2.0, 2.5, 3.0, 4.0, 5.0, 8.0):
        K = np.zeros((2, 6))
        K[1, 2] = np.interp(v, [1.0, 3.0], [2.0, -1.0])
        K[1, 1] = np.interp(v, [0.0, 2.0, 5.0], [0.0, 4.0, 1.0])
        K[0, 0] = 3.0
        expected = open_loop.state_matrix(v) + open_loop.input_matrix(v) @ K
        for piece in {id(p): p for p in (closed.at(v), closed.at(max(v - 1e-12, 0)))}.values():
            assert piece.state_matrix(v) == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize("control, key", [
    ({"yaw-torque": {"roll-rate": 1.0}}, "yaw-torque"),
    ({"steer-torque": {"roll-acceleration": 1.0}}, "steer-torque.roll-acceleration"),
    ({"steer-torque": {"heading": 1.0}}, "steer-torque.heading"),
    ({"steer-torque": {"roll-rate": {"speeds": [2.0, 1.0], "gains": [1.0, 2.0]}}}, "steer-torque.roll-rate.speeds"),
    ({"steer-torque": {"roll-rate": {"speeds": [1.0], "gains": [1.0, 2.0]}}}, "steer-torque.roll-rate"),
    ({"steer-torque": {"roll-rate": "fast"}}, "steer-torque.roll-rate"),
    ({}, "(top)"),
])
def test_bad_controls_are_refused_naming_the_key(control, key):
    with pytest.raises(InputError) as info:
        bm.stability(bm.parameters("benchmark"), control=control)
    assert info.value.key == key


def test_cli_bad_control_file_is_one_line_and_exit_2(tmp_path, capsys):
    bad = tmp_path / "law.yaml"
    bad.write_text("steer-torque:\n  yaw: 3.0\n")
    assert main(["stability", "benchmark", "--control", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert "steer-torque.yaw" in err and "roll-rate" in err and len(err.splitlines()) == 1


@pytest.mark.parametrize("control", [
    {"steer-torque": {"roll-rate": {"speeds": [0, 1.5, 4.7], "gains": [0, 12.48, 0]}}},
    {"steer-torque": {"steer-rate": -0.8, "roll-angle": 3.0}},
    {"roll-torque": {"steer-angle": {"speeds": [0, 5], "gains": [1, 4]}}},
])
def test_contract_each_piece_keeps_its_mechanics(control):
    """Where the feedback reads coordinates and rates, each piece keeps ``M, C(v), K(v)`` with the
    feedback moved into ``C`` and ``K``: its first-order form is the piece's ``A(v)`` (1e-12), and the
    mode shapes scale by the coordinates."""
    closed = bm.linear_model(bm.parameters("benchmark"), control=control)
    for v in (0.7, 3.1, 6.0):
        piece = closed.at(v)
        mech = piece.mechanics
        M, C, K = mech.M, mech.damping(v), mech.stiffness(v)
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
        assert piece.dynamic_matrix(v) == pytest.approx(A, abs=1e-12 * np.abs(A).max())


def test_a_feedback_of_a_tyre_force_has_no_mechanics():
    model = bm.linear_model(bm.parameters("benchmark"), model="tyre",
                            control={"steer-torque": {"front-lateral-force": 0.001}})
    assert model.at(2.0).mechanics is None
    assert bm.stability(model, speeds=bm.speeds(0, 5, 0.5)).speeds[-1] == 5.0
