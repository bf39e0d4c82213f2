"""State spaces out (issue 36): ``bikemass state-space`` writes A, B, C, D with the names and units
of the states, inputs and outputs as .mat, .npz, JSON, YAML and CSV, and the second-order form;
``LinearModel.to_control`` and ``to_scipy`` give python-control's and scipy's objects.

References, independent of bikemass's model builder: the matrices Meijaard et al. (2007) print
(Sec. 4: M, C1, K0, K2 of the benchmark bicycle to 14-15 significant digits) with their Table 1
wheelbase, trail and steer-axis tilt, assembled into the state matrix here; python-control's and
scipy's own frequency responses of the exported systems.
"""

import csv
import io
import json

import numpy as np
import pytest
import scipy.io
import scipy.signal
import yaml

import bikemass as bm
from bikemass.cli.main import main
from meijaard import C1, G, K0, K2, M, roll_per_steer_torque, state_matrix

STATES = ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral")
TOL = 1e-12
"""A from the printed matrices against A exported: the printed digits (14-15 significant) round the
exact values by at most 5e-15 relative; through M^-1 that moves A's entries (at most 23 1/s^2 at
5 m/s) by under 1e-13."""


def in_order(A, names):
    """``A``'s rows and columns rearranged to :data:`STATES` by the names the file gives."""
    index = [list(names).index(s) for s in STATES]
    return A[np.ix_(index, index)]


def export(tmp_path, name, *options):
    path = tmp_path / name
    assert main(["state-space", "benchmark", "--speed", "5", "-o", str(path), *options]) == 0
    return path


def names(values):
    """Strings from a .mat cell array or an .npz string array."""
    return [str(np.asarray(v).ravel()[0]) if np.asarray(v).size else "" for v in np.asarray(values).ravel()]


def test_mat_A_is_meijaards_state_matrix(tmp_path):
    data = scipy.io.loadmat(export(tmp_path, "ss.mat"))
    states = names(data["states"])
    assert set(states) == set(STATES)
    np.testing.assert_allclose(in_order(data["A"], states), state_matrix(5.0), rtol=0, atol=TOL)
    assert names(data["inputs"]) == ["roll-torque", "steer-torque"]
    assert data["B"].shape == (6, 2) and data["C"].shape == (7, 6) and data["D"].shape == (7, 2)
    assert names(data["outputs"])[:6] == states and names(data["state_units"])[:2] == ["rad", "rad"]
    assert float(data["speed"].ravel()[0]) == 5.0
    units = data["units"][0, 0]
    assert str(units["speed"].ravel()[0]) == "m/s"


def test_npz_A_B_are_meijaards(tmp_path):
    data = np.load(export(tmp_path, "ss.npz"))                     # no pickled objects: allow_pickle stays off
    states = [str(s) for s in data["states"]]
    np.testing.assert_allclose(in_order(data["A"], states), state_matrix(5.0), rtol=0, atol=TOL)
    # B: M^-1 on the torques' rows (roll torque, steer torque act on roll and steer)
    index = [states.index(s) for s in ("roll-rate", "steer-rate")]
    np.testing.assert_allclose(data["B"][index], np.linalg.inv(M), rtol=0, atol=TOL)
    assert json.loads(str(data["units"]))["speed"] == "m/s"
    assert [str(s) for s in data["state_units"]] == ["rad", "rad", "rad/s", "rad/s", "rad", "m"]


@pytest.mark.parametrize("suffix", [".json", ".yaml"])
def test_json_yaml_carry_names_units_and_A(tmp_path, suffix):
    path = export(tmp_path, "ss" + suffix)
    doc = (json.loads if suffix == ".json" else yaml.safe_load)(path.read_text())
    np.testing.assert_allclose(in_order(np.array(doc["A"]), doc["states"]), state_matrix(5.0),
                               rtol=0, atol=TOL)
    assert doc["units"]["speed"] == "m/s" and set(doc["units"]) >= {"A", "B", "C", "D", "mechanics_M"}
    assert doc["inputs"] == ["roll-torque", "steer-torque"] and doc["outputs"][-1] == "front-lateral"


def test_mechanics_are_meijaards_M_C1_K0_K2(tmp_path):
    """The second-order form as polynomials in speed: C = v C1, K = g K0 + v^2 K2."""
    doc = json.loads(export(tmp_path, "ss.json").read_text())
    assert doc["coordinates"] == ["roll-angle", "steer-angle"]
    C, K = np.array(doc["mechanics_C"]), np.array(doc["mechanics_K"])
    scale = {"M": 81, "C": 34, "K": 800}                 # the largest entries: relative 1e-13 of them
    np.testing.assert_allclose(doc["mechanics_M"], M, rtol=0, atol=1e-13 * scale["M"])
    np.testing.assert_allclose(C[0], 0, atol=0)
    np.testing.assert_allclose(C[1], C1, rtol=0, atol=1e-13 * scale["C"])
    np.testing.assert_allclose(K[0], G * K0, rtol=0, atol=1e-13 * scale["K"])
    np.testing.assert_allclose(K[1], 0, atol=0)
    np.testing.assert_allclose(K[2], K2, rtol=0, atol=1e-13 * scale["K"])
    np.testing.assert_array_equal(doc["mechanics_F"], np.eye(2))


def test_csv_layout_rebuilds_A(tmp_path):
    rows = list(csv.DictReader(io.StringIO(export(tmp_path, "ss.csv").read_text())))
    assert list(rows[0]) == ["matrix", "power", "row", "column", "value", "row unit", "column unit"]
    A = np.zeros((6, 6))
    for r in rows:
        if r["matrix"] == "A":
            A[STATES.index(r["row"]), STATES.index(r["column"])] = float(r["value"])
    np.testing.assert_allclose(A, state_matrix(5.0), rtol=0, atol=TOL)
    roll_rate = next(r for r in rows if r["matrix"] == "A" and r["row"] == "roll-rate" and r["column"] == "steer-angle")
    assert (roll_rate["row unit"], roll_rate["column unit"]) == ("rad/s^2", "rad")
    k2 = [r for r in rows if r["matrix"] == "mechanics_K" and r["power"] == "2"]
    assert len(k2) == 4 and float(k2[1]["value"]) == pytest.approx(K2[0, 1], rel=1e-13)


def test_tyre_model_exports_a_larger_state(tmp_path):
    data = scipy.io.loadmat(export(tmp_path, "tyre.mat", "--model", "tyre"))
    assert data["A"].shape[0] > 4 and data["A"].shape == (len(names(data["states"])),) * 2
    assert "rear-lateral-force" in names(data["states"]) and "mechanics_M" not in data   # tyre forces lag


def test_outputs_option_and_refusals(tmp_path, capsys):
    path = export(tmp_path, "two.json", "--outputs", "roll-angle,front-lateral")
    doc = json.loads(path.read_text())
    assert doc["outputs"] == ["roll-angle", "front-lateral"] and np.array(doc["C"]).shape == (2, 6)
    capsys.readouterr()
    assert main(["state-space", "benchmark", "--speed", "5", "--format", "mat"]) == 2
    assert "-o FILE.mat" in capsys.readouterr().err
    assert main(["state-space", "benchmark", "--speed", "5", "--outputs", "roll-angel", "-o",
                 str(tmp_path / "x.json")]) == 2
    assert "did you mean 'roll-angle'" in capsys.readouterr().err and not (tmp_path / "x.json").exists()
    assert main(["state-space", "benchmark", "--speed", "5", "--outputs", "lateral,roll-angle,lateral", "-o",
                 str(tmp_path / "x.json")]) == 2         # two rows of C named alike: refused
    assert "--outputs: lateral: each output once" in capsys.readouterr().err and not (tmp_path / "x.json").exists()


def test_to_control_frequency_response_equals_bikemass():
    """python-control's own frequency response of the exported system (its evaluation, not bikemass's),
    and for roll angle / steer torque that of Meijaard et al.'s printed matrices (1e-9 relative: the
    printed digits move the response by under 1e-12)."""
    control = pytest.importorskip("control")
    p = bm.parameters("benchmark")
    sys = bm.linear_model(p).to_control(5.0)
    assert sys.state_labels == list(STATES) and sys.input_labels == ["roll-torque", "steer-torque"]
    w = np.geomspace(0.1, 100, 400)
    for inp in ("roll-torque", "steer-torque"):
        for out in ("roll-angle", "steer-angle", "lateral", "front-lateral"):
            fr = bm.frequency_response(p, 5.0, inp, out, frequencies=w)
            siso = sys[sys.output_labels.index(out), sys.input_labels.index(inp)]
            g = np.asarray(control.frequency_response(siso, w).complex).ravel()
            np.testing.assert_allclose(g, fr.values, rtol=1e-9, atol=0)
            if (inp, out) == ("steer-torque", "roll-angle"):
                np.testing.assert_allclose(g, roll_per_steer_torque(5.0, w), rtol=1e-9, atol=0)


def test_to_scipy_frequency_response_equals_bikemass():
    p = bm.parameters("benchmark")
    model = bm.linear_model(p)
    w = np.geomspace(0.1, 100, 50)
    sys = model.to_scipy(4.0, outputs=["steer-angle"])
    for j, inp in enumerate(model.input_names):
        _, g = scipy.signal.freqresp(scipy.signal.StateSpace(sys.A, sys.B[:, [j]], sys.C, sys.D[:, [j]]), w)
        np.testing.assert_allclose(g, bm.frequency_response(p, 4.0, inp, "steer-angle", frequencies=w).values,
                                   rtol=1e-9, atol=0)


def test_richer_model_to_control_keeps_names():
    pytest.importorskip("control")
    model = bm.Scenario("benchmark", model="tyre").build().model
    sys = model.to_control(5.0)
    assert sys.nstates == len(model.states) > 4 and sys.state_labels == list(model.state_names)
    np.testing.assert_array_equal(sys.A, model.state_matrix(5.0))


@pytest.mark.parametrize("call, key", [
    (lambda m: m.to_scipy(float("nan")), "speed"), (lambda m: m.to_scipy(-1.0), "speed"),
    (lambda m: m.to_scipy("5"), "speed"), (lambda m: m.to_scipy(5.0, outputs=["yaw"]), "outputs"),
])
def test_exports_refuse_a_bad_speed_or_output_naming_it(call, key):
    """A speed the analyses refuse (not finite, negative, not a number) is refused by the exports too,
    not turned into a state space of NaN; an unknown output names the model's outputs."""
    with pytest.raises(bm.InputError, match=rf"^{key}: "):
        call(bm.linear_model(bm.parameters("benchmark")))
