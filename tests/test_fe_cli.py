"""``bikemass stiffness`` / ``bikemass modes``: output schemas, options, bad input.

The bicycle loader is replaced by the thesis Jamis structure (tests/thesis_frames.py)
so these tests exercise the commands themselves; numbers are checked against
the library functions, whose accuracy tests/test_fe_jamis.py establishes.
"""

import json

import numpy as np
import pytest

from bikemass.cli import main as cli
from bikemass.scenario import frame
from bikemass.fe import equivalent_stiffness, frame_modes
from bikemass.mass.materials import Material
from printed import numbers
from thesis_frames import jamis_structure


@pytest.fixture(autouse=True)
def jamis(monkeypatch):
    monkeypatch.setattr(frame, "frame_structure", lambda bike: jamis_structure())


def run(capsys, *argv):
    status = cli.main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_stiffness_json_schema(capsys):
    status, out, _ = run(capsys, "stiffness", "jamis", "--material", "titanium", "--procedure", "thesis",
                         "--format", "json")
    data = json.loads(out)
    assert status == 0 and data["procedure"] == "thesis" and data["units"] == {"S": "N m/rad"}
    expected = equivalent_stiffness(jamis_structure("titanium"), procedure="thesis")
    np.testing.assert_allclose(data["S"], expected, rtol=1e-12)


def test_stiffness_table_default_is_condensed(capsys):
    status, out, _ = run(capsys, "stiffness", "jamis")
    S = equivalent_stiffness(jamis_structure(), procedure="condensed")
    assert status == 0 and "condensed" in out
    shown = numbers(out)                                        # printed to 0.1 N m/rad
    assert all(any(abs(x - s) <= 0.05 + 1e-9 for x in shown) for s in (S[0, 0], S[1, 1]))


def test_modes_json_schema_and_plot(capsys, tmp_path):
    png = tmp_path / "modes.png"
    status, out, _ = run(capsys, "modes", "jamis", "--bc", "fix-rear", "-n", "4", "--format", "json",
                         "--plot", str(png))
    data = json.loads(out)
    assert status == 0 and data["units"] == {"frequencies": "Hz"} and data["support"] == "fix-rear"
    np.testing.assert_allclose(data["frequencies"], frame_modes(jamis_structure(), "fix-rear", 4).frequencies_hz)
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_modes_table(capsys):
    status, out, _ = run(capsys, "modes", "jamis", "--bc", "fix-both", "-n", "3", "--beam", "euler-bernoulli")
    f = frame_modes(jamis_structure(), "fix-both", 3, timoshenko=False).frequencies_hz
    shown = numbers(out)[-5::2]                                 # mode, frequency (to 1e-3 Hz)
    assert status == 0 and shown == pytest.approx(list(f), abs=5e-4 + 1e-9)


@pytest.mark.parametrize("argv, words", [
    (["stiffness", "jamis", "--material", "unobtainium"], "unobtainium: (material): a material YAML file"),
    (["modes", "jamis", "-n", "0"], "argument -n: a number of modes (finite, at least 1"),
    (["modes", "jamis", "--element-size", "-1"], "argument --element-size: an element length in m (finite, above 0"),
    (["modes", "jamis", "-n", "5000", "--element-size", "1"], "-n: 5000: at most 200 modes (raise with --max-modes)"),
])
def test_bad_input_is_one_line_exit_2(capsys, argv, words):
    status, out, err = run(capsys, *argv)
    assert status == 2 and out == "" and words in err and err.count("\n") == 1


def test_user_material_file(capsys, tmp_path):
    path = tmp_path / "mat.yaml"
    path.write_text("bronze:\n  E: 110 GPa\n  nu: 0.34\n  density: 8.8 g/cm^3\n")
    status, out, _ = run(capsys, "stiffness", "jamis", "--material", str(path), "--format", "json")
    S = np.array(json.loads(out)["S"])
    bronze = Material("bronze", "bronze", 110e9, 0.34, 8800.0)
    np.testing.assert_allclose(S, equivalent_stiffness(jamis_structure(), bronze), rtol=1e-12)
