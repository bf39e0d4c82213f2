"""Every shipped example runs clean (issue 35): each sweep spec of ``examples/sweeps`` without a
refused row, the pose file it uses, and the uncertainty spreads under Monte Carlo for several
seeds (the draws of the 2 mm trail spread used to break the Jamis's own 2 mm keypoint check)."""

import csv
import json
from pathlib import Path

import pytest

from bikemass.cli.main import main
from bikemass.sweep import read_spec

EXAMPLES = Path(__file__).parents[1] / "examples" / "sweeps"
SPECS = sorted(p for p in EXAMPLES.glob("*.yaml") if "vary:" in p.read_text())


def test_every_example_file_is_run_here():
    """Contract: the examples are the sweep specs, the pose they use and the spreads file."""
    assert {p.name for p in EXAMPLES.glob("*.yaml")} == {p.name for p in SPECS} | {"hoods_chain.yaml",
                                                                                     "jamis_geometry_std.yaml"}


@pytest.mark.slow
@pytest.mark.parametrize("spec", SPECS, ids=[p.stem for p in SPECS])
def test_every_example_sweep_runs_without_a_refused_row(spec, tmp_path, capsys):
    out = tmp_path / "out"
    assert main(["sweep", str(spec), "--out", str(out), "--no-figures", "--quiet"]) == 0
    err = capsys.readouterr().err
    assert "refused" not in err and "error" not in err, err
    with open(out / "results.csv", newline="") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == read_spec(spec).count and not [r for r in rows if r["error"]]
    assert all(r["weave_speed"] or r["capsize_speed"] for r in rows)
    if read_spec(spec).global_sensitivity:
        assert set(json.loads((out / "sobol.json").read_text())) >= {"weave_speed", "capsize_speed"}


def test_the_chain_pose_example_seats_a_rider(capsys):
    assert main(["params", "jamis", "--rider", str(EXAMPLES / "hoods_chain.yaml")]) == 0
    assert "mB" in capsys.readouterr().out


@pytest.mark.slow
@pytest.mark.parametrize("seed", [0, 1, 7])
def test_monte_carlo_on_the_geometry_spreads_runs_for_every_seed(seed, capsys):
    """The Monte Carlo standard deviation of the weave speed agrees with first-order (linear)
    propagation, an independent estimate: with 300 draws the sampling error of a standard
    deviation is about 4 %, so 20 % is five of those."""
    code = main(["uncertainty", "jamis", "--rider", "relaxed", "--std", str(EXAMPLES / "jamis_geometry_std.yaml"),
                 "--method", "montecarlo", "--samples", "300", "--seed", str(seed), "--format", "json"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    weave = json.loads(captured.out)["weave_speed"]
    assert weave["fraction_without"] == 0.0
    assert weave["std"] == pytest.approx(weave["linear_std"], rel=0.2)


def test_a_changed_trail_is_not_refused_by_the_files_own_keypoints(tmp_path, capsys):
    """A sweep (or a draw) that moves the Jamis's trail or head angle asks for that bicycle: the
    head-tube keypoint check judges the file as written, not the change; a file whose own trail
    contradicts its keypoints is still refused, in every row."""
    spec = tmp_path / "trail.yaml"
    spec.write_text("bike: jamis\nvary:\n  geometry.trail: [0.05, 0.065]\n  geometry.head_angle: [72 deg, 74 deg]\n")
    assert main(["sweep", str(spec), "--out", str(tmp_path / "a"), "--no-figures", "--quiet"]) == 0
    with open(tmp_path / "a" / "results.csv", newline="") as fh:
        assert not [r for r in csv.DictReader(fh) if r["error"]]
    jamis = Path(__file__).parents[1] / "frames" / "jamis.yaml"
    (tmp_path / "bad.yaml").write_text(jamis.read_text().replace("\n  trail: 0.060", "\n  trail: 0.070", 1))
    spec.write_text("bike: bad.yaml\nvary:\n  geometry.trail: [0.055, 0.065]\n")
    assert main(["sweep", str(spec), "--out", str(tmp_path / "b"), "--no-figures", "--quiet"]) == 2
    assert "head-tube keypoints" in capsys.readouterr().err
