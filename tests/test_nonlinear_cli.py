"""bikemass simulate --nonlinear and bikemass turn: the dialect (formats, units, figures, bad input
as one line with exit status 2) over the library, whose numbers tests/test_nonlinear_simulate.py
and tests/test_nonlinear_turn.py hold to references."""

import json

import numpy as np
import pytest

import bikemass as bm
from bikemass.cli.main import main

NONLINEAR = ["roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral", "forward-speed",
             "pitch-angle", "x", "energy"]


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_simulate_nonlinear_in_every_format(capsys):
    code, out, _ = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 4.6, "--initial", "roll-rate=0.5",
                       "--duration", 1, "--step", 0.25, "--format", "json")
    d = json.loads(out)
    assert code == 0 and list(d["states"]) == NONLINEAR and d["stopped"] == ""
    assert d["units"]["energy"] == "J" and d["units"]["forward-speed"] == "m/s" and d["units"]["x"] == "m"
    r = bm.simulate(bm.parameters("benchmark"), 4.6, {"roll-rate": 0.5}, duration=1.0, step=0.25, nonlinear=True)
    assert d["states"]["roll-rate"] == pytest.approx(r["roll-rate"].tolist(), rel=1e-12, abs=1e-15)
    code, out, _ = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 4.6, "--initial", "roll-rate=0.5",
                       "--duration", 1, "--step", 0.25, "--format", "csv")
    lines = out.splitlines()
    assert lines[0].split(",")[-4:] == ["forward-speed (m/s)", "pitch-angle (rad)", "x (m)", "energy (J)"]
    assert len(lines) == 6
    code, out, _ = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 4.6, "--duration", 0.5,
                       "--format", "yaml")
    assert code == 0 and "energy: J" in out
    code, out, _ = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 4.6, "--duration", 0.5)
    assert code == 0 and "energy (J)" in out.splitlines()[0]


def test_a_fall_is_one_warning_line_and_the_rows_so_far(capsys):
    code, out, err = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 0, "--initial",
                         "roll-angle=0.01", "--duration", 100, "--format", "csv")
    assert code == 0 and err.count("\n") == 1 and err.startswith("bikemass: warning: stopped at t = ")
    rows = np.array([[float(x) for x in line.split(",")] for line in out.splitlines()[1:]])
    assert 10 < len(rows) < 10001 and np.all(np.isfinite(rows))


def test_nonlinear_refuses_other_models_and_flexible_frames(capsys):
    code, _, err = run(capsys, "simulate", "benchmark", "--nonlinear", "--model", "tyre", "--speed", 4)
    assert code == 2 and err.count("\n") == 1 and "--model whipple" in err
    code, _, err = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 4, "--initial", "forward-speed=1")
    assert code == 2 and err.count("\n") == 1 and "--initial" in err


def test_the_figure_draws_the_nonlinear_run_beside_the_linear(capsys, tmp_path):
    mpimg = pytest.importorskip("matplotlib.image")
    png = tmp_path / "run.png"
    code, out, _ = run(capsys, "simulate", "benchmark", "--nonlinear", "--speed", 4.6, "--initial", "roll-rate=0.5",
                       "--duration", 3, "--plot", png, "--size", "6,6", "--dpi", 60)
    assert code == 0 and out == ""
    image = mpimg.imread(png)[:, :, :3]
    assert image.shape[:2] == (360, 360)

    def share(colour):
        rgb = np.array([int(colour[i:i + 2], 16) / 255 for i in (1, 3, 5)])
        return np.mean(np.all(np.abs(image - rgb) < 0.08, axis=2))

    for solid, light in [("#1f77b4", "#8fbbd9"), ("#9467bd", "#c9b3de")]:       # roll; forward speed
        assert share(solid) > 1e-4 and share(light) > 1e-4


def test_turn_json_and_table(capsys):
    code, out, _ = run(capsys, "turn", "benchmark", "--speed", 5, "--radius", 10, "--format", "json")
    d = json.loads(out)
    turn = bm.steady_turn(bm.parameters("benchmark"), 5.0, radius=10.0)
    assert code == 0 and d["roll"] == pytest.approx(turn.roll, rel=1e-12) and d["units"]["steer_torque"] == "N m"
    code, out, _ = run(capsys, "turn", "benchmark", "--speed", 5, "--steer", 0.05)
    assert code == 0 and out.splitlines()[0].split() == ["quantity", "nonlinear", "linear", "unit"]


def test_turn_hands_free_csv_and_plot(capsys, tmp_path):
    code, out, _ = run(capsys, "turn", "benchmark", "--hands-free", "--steers", "0.05:0.2:4", "--format", "csv")
    lines = out.splitlines()
    assert code == 0 and lines[0].startswith("steer (rad),speed (m/s)") and len(lines) == 5
    family = bm.hands_free_turns(bm.parameters("benchmark"), np.linspace(0.05, 0.2, 4))
    assert [float(line.split(",")[1]) for line in lines[1:]] == pytest.approx(family.speed.tolist(), rel=1e-12)
    png = tmp_path / "family.png"
    code, out, _ = run(capsys, "turn", "benchmark", "--hands-free", "--steers", "0.05:0.4:8", "--plot", png)
    assert code == 0 and png.stat().st_size > 1000


def test_turn_bad_input_is_one_line(capsys):
    for argv in (["--speed", 5, "--radius", 0.5], ["--radius", 10], ["--speed", 5, "--steer", 3.0],
                 ["--hands-free", "--steers", "a:b"], ["--speed", 5, "--radius", 10, "--plot", "x.png"]):
        code, _, err = run(capsys, "turn", "benchmark", *argv)
        assert code == 2 and err.count("\n") == 1 and err.startswith("bikemass: error:"), argv


def test_an_option_the_command_would_ignore_is_refused(capsys, tmp_path):
    """``turn --hands-free --speed 5`` ignored the speed (each circle's speed is the family's result), and
    ``uncertainty --samples 5`` / ``--seed`` with the linear method drew nothing: each is refused in one line
    naming the option and what it goes with."""
    assert main(["turn", "benchmark", "--hands-free", "--speed", "5"]) == 2
    assert main(["uncertainty", "benchmark", "--samples", "5"]) == 2
    assert main(["uncertainty", "benchmark", "--seed", "3"]) == 2
    std = tmp_path / "u.yaml"
    std.write_text("uncertainty:\n  w: 0.01\n")
    assert main(["uncertainty", "benchmark", "--std", str(std), "--method", "montecarlo", "--samples", "20",
                 "--seed", "3", "--quiet"]) == 0
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 3
    assert err[0].startswith("bikemass: error: --speed: 5") and "--hands-free" in err[0]
    assert "--samples: 5" in err[1] and "--method montecarlo" in err[1] and "--seed: 3" in err[2]
