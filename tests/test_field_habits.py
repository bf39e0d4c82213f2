"""The field's habits (issue 36): ``bode --hz`` (frequencies in Hz) and ``compare --models`` (members
of the model family side by side); ``export --up y`` is tests/test_export_up.py.

References: the frequency response of the state matrix assembled from Meijaard et al. (2007)'s
printed matrices (their Sec. 4) at f Hz = 2 pi f rad/s, and the benchmark's published weave and
capsize speeds; the other members' speeds against ``bm.stability`` of the same scenario (a
contract test: the command is a shell over it).
"""

import json

import numpy as np
import pytest

import bikemass as bm
from bikemass.cli.main import main
from meijaard import CAPSIZE, WEAVE, roll_per_steer_torque



def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert code == 0, err
    return out


def test_bode_hz_frequencies_in_hz(capsys):
    doc = json.loads(run(capsys, "bode", "benchmark", "--speed", 5, "--input", "steer-torque", "--output",
                         "roll-angle", "--hz", "--frequencies", "0.1:10:21", "--format", "json"))
    f = np.array(doc["frequencies"])
    np.testing.assert_allclose(f, np.geomspace(0.1, 10, 21), rtol=1e-14)
    assert doc["units"]["frequencies"] == "Hz"
    g = roll_per_steer_torque(5.0, 2 * np.pi * f)
    np.testing.assert_allclose(doc["magnitude"], 20 * np.log10(np.abs(g)), rtol=0, atol=1e-8)
    csv = run(capsys, "bode", "benchmark", "--speed", 5, "--input", "steer-torque", "--output", "roll-angle",
              "--hz", "--frequencies", "1:10:2", "--format", "csv")
    assert csv.splitlines()[0] == "frequency (Hz),magnitude (dB),phase (deg)"
    assert float(csv.splitlines()[1].split(",")[0]) == 1.0


def test_bode_hz_plot_axis_in_hz(capsys, tmp_path):
    fr = bm.frequency_response(bm.parameters("benchmark"), 5.0, "steer-torque", "roll-angle")
    fig = bm.plot_bode(fr, hz=True)
    np.testing.assert_allclose(fig.axes[0].lines[0].get_xdata(), fr.frequencies / (2 * np.pi), rtol=1e-15)
    assert fig.axes[1].get_xlabel() == "frequency, Hz"
    assert main(["bode", "benchmark", "--speed", "5", "--input", "steer-torque", "--output", "roll-angle",
                 "--hz", "--plot", str(tmp_path / "b.png")]) == 0
    from PIL import Image
    with Image.open(tmp_path / "b.png") as image:
        pixels = np.asarray(image.convert("L"))
    assert pixels.shape[0] > 200 and (pixels < 128).mean() > 0.005      # drawn: dark lines on white


def test_bode_hz_refuses_a_bad_range_in_hz(capsys):
    assert main(["bode", "benchmark", "--speed", "5", "--input", "steer-torque", "--output", "roll-angle",
                 "--hz", "--frequencies", "0:1:3"]) == 2
    assert "in Hz" in capsys.readouterr().err


def test_compare_models_side_by_side(capsys):
    doc = json.loads(run(capsys, "compare", "benchmark", "--models", "whipple,tyre", "--format", "json"))
    runs = doc["runs"]
    assert [r["model"] for r in runs] == ["whipple", "tyre"]
    assert runs[0]["weave_speeds"][0] == pytest.approx(WEAVE, abs=1e-9)      # Meijaard et al. 2007
    assert runs[0]["capsize_speeds"][0] == pytest.approx(CAPSIZE, abs=1e-9)
    # contract: the tyre member's speeds are bm.stability's of the same scenario
    tyre = bm.stability(bm.Scenario("benchmark", model="tyre"))
    assert runs[1]["weave_speeds"] == list(tyre.weave_speeds)
    table = run(capsys, "compare", "benchmark", "--models", "whipple,tyre")
    assert table.splitlines()[0].split()[:3] == ["rider", "model", "stiffness"]


def test_compare_models_refuses_an_unknown_model(capsys):
    assert main(["compare", "benchmark", "--models", "whipple,tyer"]) == 2
    err = capsys.readouterr().err
    assert err.startswith("bikemass: error: --models") and err.count("\n") == 1
