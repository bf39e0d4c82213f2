"""Results as tables (issue 36): ``to_frame()`` gives a pandas DataFrame of every result with rows,
units in ``frame.attrs["units"]``.

Independent references where the numbers come from outside the frame's own result: the
eigenvalues and frequency response of the state matrix assembled from Meijaard et al. (2007)'s
printed matrices (their Sec. 4, Table 1), the benchmark's published weave and capsize speeds, and
a sweep's ``results.csv`` read by pandas's own CSV reader. The others are contract tests: the
frame holds what the result holds, row by row.
"""

import sys

import numpy as np
import pytest

import bikemass as bm
from meijaard import CAPSIZE, WEAVE, mechanical_state_matrix, roll_per_steer_torque

pandas = pytest.importorskip("pandas")



def printed_eigenvalues(v):
    """The 4 eigenvalues (1/s) of the state matrix built from the printed M, C1, K0, K2."""
    return np.linalg.eigvals(mechanical_state_matrix(v))


P = bm.parameters("benchmark")
SPEEDS = bm.speeds(0, 10, 0.5)


@pytest.mark.parametrize("make", [lambda: bm.stability(P, speeds=SPEEDS), lambda: bm.eigenvalues(P, speeds=SPEEDS)],
                         ids=["stability", "eigenvalues"])
def test_eigenvalue_frames_hold_meijaards_eigenvalues(make):
    frame = make().to_frame()
    assert isinstance(frame, pandas.DataFrame) and len(frame) == len(SPEEDS)
    np.testing.assert_array_equal(frame["speed"], SPEEDS)
    labels = frame.attrs["labels"]
    assert labels == ("weave 1", "weave 2", "capsize", "caster")
    assert frame.attrs["units"]["speed"] == "m/s" and frame.attrs["units"]["capsize real"] == "1/s"
    for _, row in frame.iterrows():
        got = np.array([row[f"{label} real"] + 1j * row[f"{label} imaginary"] for label in labels])
        ref = printed_eigenvalues(row["speed"])
        # each printed eigenvalue is one of the frame's: the closest within 1e-9 1/s (the printed
        # digits' rounding moves them by under 1e-12)
        assert max(np.min(np.abs(got - z)) for z in ref) < 1e-9
        assert max(np.min(np.abs(ref - z)) for z in got) < 1e-9


def test_stability_frame_stable_between_the_published_speeds():
    result = bm.stability(P)
    frame = result.to_frame()
    stable = frame["speed"][frame["stable"]]
    assert stable.min() == pytest.approx(np.ceil(WEAVE / 0.05) * 0.05, abs=1e-12)      # 4.30, the first grid speed
    assert stable.max() == pytest.approx(np.floor(CAPSIZE / 0.05) * 0.05, abs=1e-12)   # 6.00
    assert np.all(np.diff(frame.index[frame["stable"]]) == 1)                            # one range
    assert frame.attrs["weave_speeds"][0] == pytest.approx(WEAVE, abs=1e-12)
    assert frame.attrs["capsize_speeds"][0] == pytest.approx(CAPSIZE, abs=1e-12)
    crossings = result.to_frame("crossings")
    assert list(crossings["kind"]) == ["oscillatory", "real"]
    np.testing.assert_allclose(crossings["speed"], [WEAVE, CAPSIZE], atol=1e-12)
    assert crossings.attrs["table"] == "crossings" and crossings.attrs["units"]["speed"] == "m/s"


def test_frequency_response_frame_is_the_printed_models():
    w = np.geomspace(0.1, 100, 50)
    frame = bm.frequency_response(P, 5.0, "steer-torque", "roll-angle", frequencies=w).to_frame()
    g = roll_per_steer_torque(5.0, w)
    np.testing.assert_allclose(frame["real"] + 1j * frame["imaginary"], g, rtol=1e-9)
    np.testing.assert_allclose(frame["magnitude"], 20 * np.log10(np.abs(g)), rtol=0, atol=1e-8)
    np.testing.assert_allclose(frame["frequency_hz"] * 2 * np.pi, w, rtol=1e-15)
    assert frame.attrs["units"]["frequency_hz"] == "Hz" and frame.attrs["units"]["phase"] == "deg"
    assert frame.attrs["speed"] == 5.0 and frame.attrs["input"] == "steer-torque"


def test_sweep_frame_equals_results_csv(tmp_path):
    spec = tmp_path / "trail.yaml"
    spec.write_text("{bike: benchmark, vary: {c: [0.04, 0.08, 0.12]}}")
    rows = bm.sweep(str(spec), str(tmp_path / "out"))
    frame = rows.to_frame()
    csv = pandas.read_csv(tmp_path / "out" / "results.csv")
    assert list(frame.columns) == list(csv.columns)
    for column in ("c", "weave_speed", "capsize_speed", "total_mass"):
        np.testing.assert_array_equal(frame[column].to_numpy(float), csv[column].to_numpy(float))
    assert frame.attrs["units"]["weave_speed"] == "m/s" and frame.attrs["units"]["total_mass"] == "kg"
    assert frame["weave_speed"][1] == pytest.approx(WEAVE, abs=1e-9)          # c = 0.08 m: the benchmark


# ---------------------------------------------------------------- contract tests: the frame is its result


def test_contract_every_handling_frame_holds_its_result():
    fr = bm.frequency_response(P, 5.0, "steer-torque", "roll-angle")
    np.testing.assert_array_equal(fr.to_frame()["phase"], fr.phase)
    sim = bm.simulate(P, 4.6, {"roll-rate": 0.5}, duration=1.0, step=0.1)
    frame = sim.to_frame()
    assert list(frame.columns) == ["time", *sim.names]
    np.testing.assert_array_equal(frame[list(sim.names)].to_numpy(), sim.values)
    assert frame.attrs["units"]["lateral"] == "m" and frame.attrs["units"]["time"] == "s"
    run = bm.simulate(P, 4.6, {"roll-rate": 0.5}, duration=0.5, step=0.1, nonlinear=True)
    frame = run.to_frame()                       # a nonlinear run's frame too: its ten outputs
    np.testing.assert_array_equal(frame[list(run.names)].to_numpy(), run.values)
    assert frame.attrs["units"]["energy"] == "J" and frame.attrs["units"]["forward-speed"] == "m/s"
    shapes = bm.mode_shapes(P, 5.0)
    frame = shapes.to_frame()
    assert len(frame) == len(shapes.labels) * len(shapes.coordinates)
    row = frame[(frame["mode"] == "capsize") & (frame["coordinate"] == "steer-angle")].iloc[0]
    assert (row["amplitude"], row["phase"]) == shapes.shape("capsize")["steer-angle"]
    tf = bm.transfer_function(P, 5.0, "steer-torque", "roll-angle")
    frame = tf.to_frame()
    np.testing.assert_array_equal(frame["real"][frame["part"] == "pole"], tf.poles.real)
    assert frame.attrs["gain"] == tf.gain
    h = bm.handling(P, [4.0, 6.0])
    frame = h.to_frame()
    np.testing.assert_array_equal(frame["hqm_peak"], h.hqm_peak)
    np.testing.assert_array_equal(frame["k_delta"], h.gain("k_delta"))
    assert frame.attrs["units"]["k_delta"] == "N m/rad"
    hqm = h.to_frame("hqm")
    np.testing.assert_array_equal(hqm["6"], h.hqm[1])
    lane = bm.lane_change(P, 5.0)
    np.testing.assert_array_equal(lane.to_frame()["road"], lane.road)


def test_contract_analysis_frames_hold_their_results():
    s = bm.sensitivity(P)
    frame = s.to_frame().set_index("parameter")
    assert frame.loc["c", "d_weave_speed"] == s.d_weave_speed["c"] and frame.loc["c", "unit"] == "m"
    assert frame.attrs["weave_speed"] == s.weave_speed
    flexible = bm.sensitivity(P, stiffness=[[6000.0, 1000.0], [1000.0, 3000.0]]).to_frame("stiffness")
    assert len(flexible) == 6 and flexible.attrs["units"]["derivative"] == "m/s per N m/rad"
    u = bm.uncertainty("benchmark", {"c": 0.005, "mB": 1.0})
    frame = u.to_frame().set_index("output")
    assert frame.loc["weave_speed", "std"] == u.speeds["weave_speed"].std
    bands = u.to_frame("eigenvalues")
    np.testing.assert_array_equal(bands["capsize std real"], u.eigen["modes"]["capsize"]["std_re"])
    frame = P.to_frame().set_index("name")
    assert frame.loc["w", "value"] == 1.02 and frame.loc["lam", "unit"] == "rad" and len(frame) == 26
    modes = bm.frame_modes(bm.load_bicycle("jamis"), count=2)
    np.testing.assert_array_equal(modes.to_frame()["frequency"], modes.frequencies_hz)


def test_no_rows_no_frame_and_pandas_missing(monkeypatch):
    with pytest.raises(TypeError, match="no rows"):
        bm.matrices(P).to_frame()
    with pytest.raises(bm.InputError, match="tables: eigenvalues, crossings"):
        bm.stability(P).to_frame("nope")
    monkeypatch.setitem(sys.modules, "pandas", None)
    with pytest.raises(ImportError, match=r"bikemass\[pandas\]"):
        bm.stability(P).to_frame()
