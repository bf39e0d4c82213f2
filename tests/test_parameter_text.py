"""BicycleParameters' parameter text files read as that package ships them.

Every ``<Name>Benchmark.txt`` that BicycleParameters installs gives BicycleParameters'
own ``Bicycle.eig`` eigenvalues to 1e-9 (1/s) at 601 speeds: both take the nominal
values of the same file, so the only difference left is the eigenvalue solver
(quartic here, LAPACK there), about 1e-13.
"""

import json
import warnings
from itertools import permutations
from pathlib import Path

import numpy as np
import pytest

import bicycleparameters as bp
from bikemass.bicycle import load_bicycle
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.cli.main import main
from bikemass.core.errors import InputError
from bikemass.bicycle.parameter_text import (ParameterFileWarning, combined_front_frame, load_parameter_text,
                                     parse_parameter_text)
from bikemass.analysis.engine.eigen import eigen_sweep
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.models.whipple import whipple_model

BP_DATA = Path(bp.__file__).parent / "app-data"
SHIPPED = sorted(p.parent.parent.name for p in BP_DATA.glob("bicycles/*/Parameters/*Benchmark.txt"))
PERMUTATIONS = np.array(list(permutations(range(4))))


def bp_file(name):
    return BP_DATA / "bicycles" / name / "Parameters" / f"{name}Benchmark.txt"


def test_ten_bicycles_are_shipped():
    assert len(SHIPPED) == 10 and "Rigid" in SHIPPED and "Silver" in SHIPPED


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_bicycle_gives_bicycleparameters_eigenvalues_to_1e_9(name, capsys):
    speeds = speed_grid()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")            # uncertainties: std 0; our H check on Rigid
        theirs, _ = bp.Bicycle(name, pathToData=str(BP_DATA)).eig(speeds)
        ours = eigen_sweep(whipple_model(load_parameter_text(bp_file(name)).parameters), speeds).eigenvalues
    capsys.readouterr()                             # BicycleParameters prints a note
    # best matching of the four roots at every speed, then the largest difference
    gap = np.abs(ours[:, PERMUTATIONS] - theirs[:, None, :]).max(axis=2).min(axis=1)
    assert gap.max() < 1e-9


def test_top_level_api_reads_nominal_values_and_standard_deviations():
    import bikemass as bm
    measured = bm.load_parameter_text(bp_file("Browser"))
    assert isinstance(measured, bm.MeasuredParameters)
    assert measured.parameters.c == 0.0686 and measured.std["c"] == 0.00169464113488
    assert measured.std["g"] == 0.01 and len(measured.std) == 26


def test_values_uncertainties_comments_and_averages():
    pt = parse_parameter_text("# a comment\nw = 1.02+/-0.01  # wheelbase\n\nc=0.08\n"
                              "lam = 0.3 ± 0.002\nt = 0.1+/-0.03, 0.12+/-0.04\n", "x.txt")
    assert pt.nominal["w"] == 1.02 and pt.std["w"] == 0.01 and pt.lines["w"] == 2
    assert pt.nominal["c"] == 0.08 and pt.std["c"] == 0.0
    assert pt.std["lam"] == 0.002
    assert pt.nominal["t"] == pytest.approx(0.11) and pt.std["t"] == pytest.approx(0.025)  # sqrt(.03^2+.04^2)/2
    assert pt.resolution["w"] == pytest.approx(0.005) and pt.resolution["c"] == pytest.approx(0.005)


@pytest.mark.parametrize("text, where, expected", [
    ("w 1.0\n", "line 1", "'name = value'"),
    ("w = 1.0\nw = 2.0\n", "line 2", "also on line 1"),
    ("w = abc\n", "line 1 (w)", "a number or number+/-std"),
    ("w = 1.0 +- 0.1\n", "line 1 (w)", "a number or number+/-std"),
    ("# only a comment\n", "(file)", "'name = value' lines"),
    ("w = nan\n", "line 1 (w)", "a number"),
])
def test_bad_lines_name_the_line(text, where, expected):
    with pytest.raises(InputError) as exc:
        parse_parameter_text(text, "bad.txt")
    assert exc.value.key == where and expected in exc.value.expected


def _replaced(path, changes, drop=()):
    lines = []
    for line in path.read_text().splitlines():
        name = line.split("=")[0].strip()
        if name in drop:
            continue
        lines.append(f"{name} = {changes[name]}" if name in changes else line)
    return "\n".join(lines) + "\n"


def test_split_front_frame_is_combined_when_h_is_missing_and_checked_when_given(tmp_path):
    # BicycleParameters' repository holds Rigid at full precision; its G and S (3.35 + 2.05 kg)
    # combine to its H.  The installed copy prints mG = 3.6 and mS = 2.1, which add to 5.7 kg,
    # not the 5.4 kg H it also prints: the check names it.
    with pytest.warns(ParameterFileWarning, match=r"mH 5.4 vs 5.7"):
        shipped = load_parameter_text(bp_file("Rigid"))
    assert shipped.parameters.mH == 5.4                          # the given H is used, as BP does
    assert any("differs" in n for n in shipped.notes)
    fixed = tmp_path / "RigidBenchmark.txt"
    fixed.write_text(_replaced(bp_file("Rigid"), {"mG": "3.35+/-0.01", "mS": "2.05+/-0.01"}))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        checked = load_parameter_text(fixed)
    assert any("agrees" in n for n in checked.notes)
    no_h = tmp_path / "NoHBenchmark.txt"
    no_h.write_text(_replaced(fixed, {}, drop=("mH", "xH", "zH", "IHxx", "IHyy", "IHzz", "IHxz")))
    combined = load_parameter_text(no_h)
    p = combined.parameters
    assert p.mH == pytest.approx(5.4, abs=1e-12)
    assert p.xH == pytest.approx((3.35 * 0.773 + 2.05 * 0.892) / 5.4, abs=1e-12)
    # H's standard deviation propagated from G and S: the mass's is sqrt(2) x 0.01
    assert combined.std["mH"] == pytest.approx(0.01 * np.sqrt(2), rel=1e-6)
    assert p.IHxx == pytest.approx(checked.parameters.IHxx, abs=2e-3)   # the file's H is rounded


def test_front_frame_combination_is_the_parallel_axis_theorem():
    values = {"mG": 2.0, "xG": 0.8, "zG": -1.0, "IGxx": 0.1, "IGyy": 0.2, "IGzz": 0.05, "IGxz": 0.01,
              "mS": 2.0, "xS": 1.0, "zS": -0.6, "ISxx": 0.1, "ISyy": 0.2, "ISzz": 0.05, "ISxz": 0.01}
    H = combined_front_frame(values)
    # two equal masses 0.2 m apart in x and 0.4 m in z about their midpoint: d = (+-0.1, +-0.2)
    assert (H["mH"], H["xH"], H["zH"]) == (4.0, pytest.approx(0.9), pytest.approx(-0.8))
    assert H["IHxx"] == pytest.approx(0.2 + 4.0 * 0.2 ** 2)
    assert H["IHzz"] == pytest.approx(0.1 + 4.0 * 0.1 ** 2)
    assert H["IHyy"] == pytest.approx(0.4 + 4.0 * (0.1 ** 2 + 0.2 ** 2))
    assert H["IHxz"] == pytest.approx(0.02 - 4.0 * 0.1 * 0.2)    # tensor element: -sum m x z


def test_extra_keys_are_checked_or_reported(tmp_path):
    silver = load_parameter_text(bp_file("Silver"))              # IRzz, IFzz, yB, yH: all consistent
    assert sum("checked" in n for n in silver.notes) == 4
    odd = tmp_path / "OddBenchmark.txt"
    odd.write_text(bp_file("Silver").read_text().replace("IRzz = 0.078", "IRzz = 0.09")
                   .replace("yB = 0.0", "yB = 0.02") + "mD = 1.0\nIDyy = 0.2\n")
    with pytest.warns(ParameterFileWarning) as record:
        p = load_parameter_text(odd)
    messages = " | ".join(str(w.message) for w in record)
    assert "IRzz" in messages and "yB" in messages and "mD, IDyy" in messages
    assert p.parameters.IRxx == 0.078


def test_incomplete_files_name_the_missing_key(tmp_path):
    f = tmp_path / "AB.txt"
    f.write_text(_replaced(bp_file("Rigid"), {}, drop=("zS",)))
    with pytest.raises(InputError, match="zS: every handlebar G and fork S"):
        load_parameter_text(f)
    f.write_text(_replaced(bp_file("Browser"), {}, drop=("IHxz",)))
    with pytest.raises(InputError, match="IHxz: a required key"):
        load_parameter_text(f)
    f.write_text(bp_file("Browser").read_text().replace("mR = 3.1", "mR = -3.1"))
    with pytest.raises(InputError, match="mR: a number >= 0"):
        load_parameter_text(f)


def test_command_line_reads_the_file_and_refuses_bad_ones(tmp_path, capsys):
    assert main(["stability", str(bp_file("Browser")), "--format", "json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert len(d["weave_speeds"]) == 1 and 3 < d["weave_speeds"][0] < 6
    bad = tmp_path / "BadBenchmark.txt"
    bad.write_text("w = 1.0\nc = 0.08 +/-\n")
    assert main(["stability", str(bad)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "BadBenchmark.txt: line 2 (c)" in err[0]


def test_measured_bicycle_companion_poses_a_chain_rider(tmp_path, capsys):
    companion = tmp_path / "browser.yaml"
    companion.write_text(f"name: Browser\nparameters: {bp_file('Browser')}\n"
                         "contacts:\n  saddle: [0.30, 0, -0.98]\n  bottom_bracket: [0.44, 0, -0.28]\n"
                         "  crank_length: 0.17\n  grips: {tops: [0.93, 0, -1.05]}\n")
    bike = load_bicycle(companion)
    assert bike.contacts is not None and bike.published.mB == 9.9
    pose = tmp_path / "ride.yaml"
    pose.write_text(f"name: ride\nbody: thesis_rider\nbike: {companion}\nchain: {{hands: tops, torso_lean: 30 deg}}\n")
    assert main(["stability", str(companion), "--rider", str(pose), "--format", "json"]) == 0
    ridden = json.loads(capsys.readouterr().out)
    assert main(["stability", str(companion), "--format", "json"]) == 0
    empty = json.loads(capsys.readouterr().out)
    assert ridden["weave_speeds"] != empty["weave_speeds"]
    missing = tmp_path / "missing.yaml"
    missing.write_text("parameters: nowhere.txt\n")
    assert main(["stability", str(missing)]) == 2
    assert "parameters: an existing parameter file" in capsys.readouterr().err


def test_bikemass_export_reads_back_bit_for_bit(tmp_path):
    from bikemass.models.parameter_export import format_parameters
    params = scenario_parameters("jamis-thesis", "relaxed-thesis")
    f = tmp_path / "JamisBenchmark.txt"
    f.write_text(format_parameters(params, "bicycleparameters", "Jamis"))
    back = load_parameter_text(f)
    assert back.parameters == params and set(back.std.values()) == {0.0} and back.notes == ()
