"""``bikemass stiffness`` / ``bikemass modes``: output schemas, options, bad input.

The bicycle loader is replaced by the thesis Jamis structure (tests/thesis_frames.py)
so these tests exercise the commands themselves.  The ``test_contract_*`` tests compare the shell
with the library it calls (the same code, so to round-off: what they hold is that the command
passes its options through and prints every digit); the library's accuracy is established
against peers and published values in tests/test_fe_jamis.py and tests/test_fe_peer.py.  A user
material is checked against linear elasticity (a frame's stiffness is proportional to E at a
given Poisson ratio), and the modes figure is decoded.
"""

import json

import numpy as np
import pytest

from bikemass.cli import main as cli
from bikemass.scenario import frame
from bikemass.fe import equivalent_stiffness, frame_modes
from bikemass.mass.materials import Material
from images import colour_mask, pixels, runs
from printed import numbers
from thesis_frames import jamis_structure


@pytest.fixture(autouse=True)
def jamis(monkeypatch):
    monkeypatch.setattr(frame, "frame_structure", lambda bike: jamis_structure())


def run(capsys, *argv):
    status = cli.main(list(argv))
    out, err = capsys.readouterr()
    return status, out, err


def test_contract_stiffness_json_is_the_librarys(capsys):
    status, out, _ = run(capsys, "stiffness", "jamis", "--material", "titanium", "--procedure", "thesis",
                         "--format", "json")
    data = json.loads(out)
    assert status == 0 and data["procedure"] == "thesis" and data["units"] == {"S": "N m/rad"}
    expected = equivalent_stiffness(jamis_structure("titanium"), procedure="thesis")
    np.testing.assert_allclose(data["S"], expected, rtol=1e-12)


def test_contract_stiffness_table_default_is_the_condensed_procedure(capsys):
    status, out, _ = run(capsys, "stiffness", "jamis")
    S = equivalent_stiffness(jamis_structure(), procedure="condensed")
    assert status == 0 and "condensed" in out
    shown = numbers(out)                                        # printed to 0.1 N m/rad
    assert all(any(abs(x - s) <= 0.05 + 1e-9 for x in shown) for s in (S[0, 0], S[1, 1]))


def test_contract_modes_json_is_the_librarys_and_the_plot_draws_each_mode(capsys, tmp_path):
    png = tmp_path / "modes.png"
    status, out, _ = run(capsys, "modes", "jamis", "--bc", "fix-rear", "-n", "4", "--format", "json",
                         "--plot", str(png))
    data = json.loads(out)
    assert status == 0 and data["units"] == {"frequencies": "Hz"} and data["support"] == "fix-rear"
    np.testing.assert_allclose(data["frequencies"], frame_modes(jamis_structure(), "fix-rear", 4).frequencies_hz)
    # decoded: 7.5 in wide and 0.9 + 1.9 in per mode at 150 dpi; the undeformed frame in grey and the
    # deformed one in blue in four bands of rows, one per mode (side and top view side by side)
    rgb = pixels(png)
    assert rgb.shape[:2] == (round((0.9 + 1.9 * 4) * 150), round(7.5 * 150))
    deformed, undeformed = colour_mask(rgb, "tab:blue"), colour_mask(rgb, "0.7")
    assert len(runs(deformed.any(axis=1), gap=20)) == 4
    assert deformed.mean() > 0.005 and undeformed.mean() > 0.002


def test_contract_modes_table_is_the_librarys(capsys):
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
    """A material file is read with its units (contract: the library's S of the same material) and,
    against linear elasticity, a frame of twice the modulus at the same Poisson ratio (and any
    density: stiffness takes no mass) is twice as stiff, to round-off (1e-12)."""
    path, stiffer = tmp_path / "mat.yaml", tmp_path / "stiffer.yaml"
    path.write_text("bronze:\n  E: 110 GPa\n  nu: 0.34\n  density: 8.8 g/cm^3\n")
    stiffer.write_text("bronze2:\n  E: 220000 MPa\n  nu: 0.34\n  density: 1 g/cm^3\n")
    status, out, _ = run(capsys, "stiffness", "jamis", "--material", str(path), "--format", "json")
    S = np.array(json.loads(out)["S"])
    bronze = Material("bronze", "bronze", 110e9, 0.34, 8800.0)
    np.testing.assert_allclose(S, equivalent_stiffness(jamis_structure(), bronze), rtol=1e-12)
    status, out, _ = run(capsys, "stiffness", "jamis", "--material", str(stiffer), "--format", "json")
    assert status == 0
    np.testing.assert_allclose(json.loads(out)["S"], 2 * S, rtol=1e-12, atol=1e-9 * np.abs(S).max())
