"""The handling commands and API: the contract of issue 24 (keys, units, options), every bicycle
form, bad input as one line with exit status 2, typed read-only results, models larger than the
Whipple bicycle, and the docstring examples."""

import doctest
import importlib
import json
import math
import re
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import bikemass as bm
from bikemass.cli.main import main
from bikemass.models.linear import Signal, second_order_model
from bikemass.models.whipple import INPUTS, whipple_model
from bikemass.models.canonical import canonical_matrices

DATA = Path(__file__).parent / "data" / "handling"
SRC = Path(__file__).parents[1] / "src"


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def png_size(path):
    return struct.unpack(">II", Path(path).read_bytes()[16:24])


def test_tf_json_has_zeros_poles_gain_and_units(capsys):
    code, out, _ = run(capsys, "tf", "benchmark", "--speed", 5, "--input", "steer-torque", "--output", "steer-angle",
                       "--format", "json")
    d = json.loads(out)
    assert code == 0 and d["gain"] == pytest.approx(4.32384018, rel=1e-8)
    assert sorted(z[0] for z in d["zeros"]) == pytest.approx([-3.1346638, 3.1346638], rel=1e-7)
    assert len(d["poles"]) == 4 and all(len(p) == 2 for p in d["poles"])
    assert d["units"] == {"speed": "m/s", "zeros": "1/s (pairs: real, imaginary)",
                          "poles": "1/s (pairs: real, imaginary)", "gain": "rad/(N m s^2)"}
    G = d["gain"] * np.prod([2j - complex(*z) for z in d["zeros"]]) / np.prod([2j - complex(*p) for p in d["poles"]])
    fr = bm.frequency_response(bm.parameters("benchmark"), 5, "steer-torque", "steer-angle", [2.0])
    assert G == pytest.approx(fr.values[0], rel=1e-10)


@pytest.mark.parametrize("output, unit, poles", [("heading", "rad/(N m s^2)", 5), ("lateral", "m/(N m s^3)", 6),
                                                 ("roll-rate", "rad/(N m s^2)", 4)])
def test_tf_of_every_output_names_its_gain_unit(capsys, output, unit, poles):
    code, out, _ = run(capsys, "tf", "benchmark", "--speed", 5, "--input", "steer-torque", "--output", output,
                       "--format", "yaml")
    import yaml
    d = yaml.safe_load(out)
    assert code == 0 and d["units"]["gain"] == unit and len(d["poles"]) == poles


def test_tf_text_and_csv(capsys):
    code, out, _ = run(capsys, "tf", "benchmark", "--speed", 5, "--input", "roll-torque", "--output", "roll-angle")
    assert code == 0 and "(s^2 + 1.55068 s + 20.5362)" in out and out.startswith("Benchmark (Meijaard et al. 2007), rider in the parameter set, rigid frame")
    code, out, _ = run(capsys, "tf", "benchmark", "--speed", 5, "--input", "roll-torque", "--output", "roll-angle",
                       "--format", "csv")
    rows = [line.split(",") for line in out.splitlines()]
    assert rows[0] == ["part", "real", "imaginary", "unit"]
    assert [r[0] for r in rows[1:]] == ["zero"] * 2 + ["pole"] * 4 + ["gain"]


def test_bode_keys_frequencies_and_plot(capsys, tmp_path):
    png = tmp_path / "bode.png"
    code, out, _ = run(capsys, "bode", "benchmark", "--speed", 5, "--input", "steer-torque", "--output", "roll-angle",
                       "--frequencies", "0.1:100:1000", "--format", "json", "--plot", png, "--size", "4,3", "--dpi", 50)
    d = json.loads(out)
    assert code == 0 and {"frequencies", "magnitude", "phase", "units"} <= set(d)
    w = np.array(d["frequencies"])
    assert len(w) == 1000 and w[0] == pytest.approx(0.1) and w[-1] == pytest.approx(100)
    assert np.allclose(np.diff(np.log(w)), np.log(1000) / 999)
    assert d["units"]["frequencies"] == "rad/s" and d["units"]["phase"] == "deg"
    assert d["units"]["magnitude"].startswith("dB")
    assert png_size(png) == (200, 150)


def test_simulate_json_csv_and_plot(capsys, tmp_path):
    code, out, _ = run(capsys, "simulate", "benchmark", "--speed", 4.6, "--initial", "roll-rate=0.5",
                       "--input", "steer-torque=step:1", "--duration", 1, "--step", 0.1, "--format", "json")
    d = json.loads(out)
    assert code == 0 and d["time"] == pytest.approx([0.1 * k for k in range(11)])
    assert list(d["states"]) == ["roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral"]
    assert all(len(v) == 11 for v in d["states"].values()) and d["states"]["roll-rate"][0] == 0.5
    assert d["units"]["lateral"] == "m" and d["units"]["time"] == "s"
    r = bm.simulate(bm.parameters("benchmark"), 4.6, {"roll-rate": 0.5}, {"steer-torque": ("step", 1.0)}, 1.0, 0.1)
    assert d["states"]["steer-angle"] == pytest.approx(r["steer-angle"].tolist(), rel=1e-12, abs=1e-15)
    code, out, _ = run(capsys, "simulate", "benchmark", "--speed", 4.6, "--initial", "roll-rate=0.5,steer-angle=0.1",
                       "--duration", 0.5, "--format", "csv")
    lines = out.splitlines()
    assert lines[0].split(",")[:3] == ["time (s)", "roll-angle (rad)", "steer-angle (rad)"] and len(lines) == 52
    assert float(lines[1].split(",")[2]) == 0.1
    png = tmp_path / "sim.png"
    code, out, _ = run(capsys, "simulate", "benchmark", "--speed", 4.6, "--initial", "roll-rate=0.5", "--plot", png,
                       "--size", "5,4", "--dpi", 40)
    assert code == 0 and out == "" and png_size(png) == (200, 160)


def test_handling_json_keys_and_plots(capsys, tmp_path):
    png, lane = tmp_path / "hqm.png", tmp_path / "lane.png"
    code, out, err = run(capsys, "handling", "benchmark", "--speeds", "4,5,6", "--format", "json", "--plot", png,
                         "--lane-change", lane, "--size", "6,3", "--dpi", 50)
    d = json.loads(out)
    assert code == 0 and d["speeds"] == [4.0, 5.0, 6.0]
    assert set(d["gains"]) == {"k_delta", "k_phi_dot", "k_phi", "k_psi", "k_y"}
    assert all(len(v) == 3 for v in d["gains"].values())
    assert d["closed_loop_stable"] == [True, True, True] and len(d["hqm_peak"]) == 3
    assert d["hqm_peak"][0] > d["hqm_peak"][1] > d["hqm_peak"][2]          # handling improves with speed
    assert d["units"]["k_delta"] == "N m/rad" and d["units"]["speeds"] == "m/s"
    assert png_size(png) == (300, 150) and png_size(lane) == (300, 150)


def test_handling_reads_a_gains_file_and_its_csv_reads_back(capsys, tmp_path):
    gains = DATA / "BenchmarkSteerGains.txt"
    code, out, _ = run(capsys, "handling", "benchmark", "--gains", gains, "--format", "csv")
    assert code == 0 and out.splitlines()[0].startswith("speed,kDelta,kPhiDot,kPhi,kPsi,kY,closed_loop_stable")
    written = tmp_path / "gains.csv"
    written.write_text(out)
    code, again, _ = run(capsys, "handling", "benchmark", "--gains", written, "--speeds", "5", "--format", "json")
    d = json.loads(again)
    assert code == 0 and d["gains"]["k_phi"] == [12.6611] and d["gain_source"] == ["given"]


FAMILY = ("whipple", "rider-lean", "tyre", "flexible", "rider-lean+tyre", "rider-lean+flexible", "tyre+flexible",
          "rider-lean+tyre+flexible")
"""Every model of the family (docs/models.md)."""


@pytest.fixture(scope="module")
def family_models():
    """``{model: LinearModel}``: every model of the family built for the Jamis with the Relaxed rider
    (the flexible member in steel), as the commands build them."""
    return {m: bm.Scenario("jamis", "relaxed", "steel" if "flexible" in m else "infinite", model=m).build().model
            for m in FAMILY}


def test_the_signals_read_from_the_code_are_the_built_models(family_models):
    from bikemass.scenario.scenario import model_signals
    for m, model in family_models.items():
        inputs, outputs = model_signals(m)
        assert tuple(n for n, _ in inputs) == model.input_names, m
        assert tuple(n for n, _ in outputs) == model.output_names, m
        assert [u for _, u in outputs] == [model.output_signal(n).unit for n in model.output_names], m


def _listed(capsys, monkeypatch, command, options=("--input", "--output")):
    """``{option: names}`` as ``command --help`` lists them (``name (unit)``) for each of ``options``."""
    monkeypatch.setenv("COLUMNS", "100000")                  # one line per option: names never wrapped
    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = capsys.readouterr().out
    blocks = {}
    for option in options:                                   # the option's lines up to the next option's
        block = re.search(rf"^  {option} .*?(?=^  -)", text, flags=re.M | re.S).group(0)
        blocks[option] = set(re.findall(r"([a-z][a-z-]*) \(", block))
    return blocks


@pytest.mark.parametrize("command", ["tf", "bode"])
def test_the_help_lists_every_input_and_output_a_model_accepts(capsys, monkeypatch, family_models, command):
    """Every name some model of the family takes as --input or gives as --output is in the help, and
    nothing else: front-lateral (the Whipple bicycle's front contact) and the members' own."""
    listed = _listed(capsys, monkeypatch, command)
    assert listed["--input"] == {n for model in family_models.values() for n in model.input_names}
    assert listed["--output"] == {n for model in family_models.values() for n in model.output_names}
    assert {"front-lateral", "lean-angle", "yaw-rate", "frame-twist"} <= listed["--output"]
    assert "lean-torque" in listed["--input"]


def test_simulate_help_lists_every_input_a_model_accepts(capsys, monkeypatch, family_models):
    listed = _listed(capsys, monkeypatch, "simulate", ("--input",))
    assert listed["--input"] == {n for model in family_models.values() for n in model.input_names}


def test_front_lateral_is_the_front_contact(capsys):
    """``--output front-lateral`` (listed by --help) is accepted and is the front contact's lateral
    position ``y + w psi - c cos(lam) delta`` (Meijaard et al. 2007's geometry, linearised): its G(2j)
    is that combination of the rear contact's, the heading's and the steer angle's."""
    code, out, err = run(capsys, "tf", "benchmark", "--speed", 5, "--input", "steer-torque", "--output",
                         "front-lateral", "--format", "json")
    assert code == 0, err
    d = json.loads(out)
    G = d["gain"] * np.prod([2j - complex(*z) for z in d["zeros"]]) / np.prod([2j - complex(*p) for p in d["poles"]])
    p = bm.parameters("benchmark")
    y, psi, delta = (bm.frequency_response(p, 5, "steer-torque", o, [2.0]).values[0]
                     for o in ("lateral", "heading", "steer-angle"))
    assert G == pytest.approx(y + p.w * psi - p.c * math.cos(p.lam) * delta, rel=1e-9)


def test_building_the_parser_loads_no_library():
    """The late helps (the signal lists read from the models) wait for a command's --help."""
    code = ("import sys; from bikemass.cli.main import build_parser; build_parser().format_help(); "
            "print(sorted(m for m in ('numpy', 'scipy', 'matplotlib') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


@pytest.mark.parametrize("argv, needle", [
    (["handling", "benchmark", "--speeds", "4,5", "--gains", DATA / "BenchmarkSteerGains.txt"], "speed 4"),
    (["handling", "benchmark"], "--speeds"),
    (["handling", "benchmark", "--speeds", "5,4"], "increasing"),
    (["tf", "benchmark", "--speed", 5, "--input", "steer-torque", "--output", "roll"], "did you mean"),
    (["bode", "benchmark", "--speed", 5, "--input", "steer-torque", "--output", "roll-angle", "--frequencies", "10:1:5"],
     "--frequencies"),
    (["simulate", "benchmark", "--speed", 5, "--initial", "yaw=1"], "--initial"),
    (["simulate", "benchmark", "--speed", 5, "--input", "steer-torque=stp:1"], "did you mean 'step'"),
    (["simulate", "benchmark", "--speed", 5, "--step", 1e-9], "--step"),
    (["tf", "nosuchbike", "--speed", 5, "--input", "steer-torque", "--output", "roll-angle"], "nosuchbike"),
])
def test_bad_input_is_one_line_and_status_2(capsys, argv, needle):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and needle in err and "Traceback" not in err


def test_a_bad_gains_file_names_its_line(capsys, tmp_path):
    bad = tmp_path / "g.csv"
    bad.write_text("speed,kDelta,kPhiDot,kPhi,kPsi,kY\n5,46,-0.05,x,0.18,0.09\n")
    code, _, err = run(capsys, "handling", "benchmark", "--gains", bad)
    assert code == 2 and "line 2" in err and "g.csv" in err
    bad.write_text("speed,kdelta\n5,46\n")
    code, _, err = run(capsys, "handling", "benchmark", "--gains", bad)
    assert code == 2 and "line 1" in err and "speed,kDelta,kPhiDot,kPhi,kPsi,kY" in err


def test_every_bicycle_form(capsys, tmp_path):
    """A shipped name, a rider and a frame stiffness, a benchmark parameter YAML written by
    ``bikemass params``, and BicycleParameters' parameter text give the same numbers for the same set."""
    args = ["--speed", 5, "--input", "steer-torque", "--output", "roll-angle", "--format", "json"]
    _, out, _ = run(capsys, "tf", "jamis", "--rider", "relaxed", "--stiffness", "steel", *args)
    flexible = json.loads(out)
    _, out, _ = run(capsys, "tf", "jamis", "--rider", "relaxed", *args)
    rigid = json.loads(out)
    assert flexible["poles"] != rigid["poles"]
    for fmt, name in (("yaml", "set.yaml"), ("bicycleparameters", "JamisBenchmark.txt")):
        path = tmp_path / name
        assert run(capsys, "params", "jamis", "--rider", "relaxed", "--format", fmt, "-o", path)[0] == 0
        _, out, _ = run(capsys, "tf", path, *args)
        d = json.loads(out)
        assert d["gain"] == pytest.approx(rigid["gain"], rel=1e-12)
        assert np.allclose(d["poles"], rigid["poles"], rtol=1e-9, atol=1e-12)


def test_results_are_typed_frozen_and_plain(tmp_path):
    p = bm.parameters("benchmark")
    tf = bm.transfer_function(p, 5.0, "steer-torque", "steer-angle")
    fr = bm.frequency_response(p, 5.0, "steer-torque", "steer-angle")
    r = bm.simulate(p, 5.0, initial={"roll-angle": 0.01})
    shapes = bm.mode_shapes(p, 5.0)
    for array in (tf.zeros, tf.poles, fr.frequencies, fr.magnitude, fr.values, r.time, r.values, r["heading"],
                  shapes.shapes, shapes.amplitude):
        with pytest.raises(ValueError):
            array[0] = 0
    for result in (tf, fr, r, shapes):
        json.dumps(result.to_dict())
        with pytest.raises(AttributeError):
            result.speed = 1.0
    assert len(fr.frequencies) == 1000 and "1000" in repr(fr)


@pytest.mark.parametrize("call, key", [
    (lambda p: bm.transfer_function(p, -1.0, "steer-torque", "roll-angle"), "speed"),
    (lambda p: bm.transfer_function(p, float("nan"), "steer-torque", "roll-angle"), "speed"),
    (lambda p: bm.transfer_function(p, 5.0, "lean-torque", "roll-angle"), "input"),
    (lambda p: bm.frequency_response(p, 5.0, "steer-torque", "roll-angle", [2.0, 1.0]), "frequencies"),
    (lambda p: bm.simulate(p, 5.0, initial={"roll-angle": "x"}), "initial"),
    (lambda p: bm.simulate(p, 5.0, inputs={"steer-torque": ("ramp", 1.0)}), "inputs"),
    (lambda p: bm.simulate(p, 5.0, duration=-1.0), "duration"),
    (lambda p: bm.handling(p, [5.0], gains=(1.0, 2.0)), "gains"),
    (lambda p: bm.handling(p), "speeds"),
    (lambda p: bm.transfer_function("benchmark", 5.0, "steer-torque", "roll-angle"), "system"),
])
def test_bad_arguments_raise_input_error(call, key):
    with pytest.raises(bm.InputError) as exc:
        call(bm.parameters("benchmark"))
    assert exc.value.source == key


def rider_lean_model(params):
    """A model with three coordinates (roll, steer and a rider's lean on a torsion spring): not the
    Whipple bicycle's four dynamic states."""
    m = canonical_matrices(params)
    M = np.zeros((3, 3))
    M[:2, :2], M[2, 2] = m.M, 2.0
    M[0, 2] = M[2, 0] = 0.5
    K0 = np.zeros((3, 3))
    K0[:2, :2], K0[2, 2] = m.gK0, 400.0
    C1, K2 = np.zeros((3, 3)), np.zeros((3, 3))
    C1[:2, :2], K2[:2, :2] = m.C1, m.K2
    C0 = np.zeros((3, 3))
    C0[2, 2] = 20.0
    cl = np.cos(params.lam)
    coordinates = (Signal("roll-angle", "rad"), Signal("steer-angle", "rad"), Signal("lean-angle", "rad"))
    rates = (Signal("roll-rate", "rad/s"), Signal("steer-rate", "rad/s"), Signal("lean-rate", "rad/s"))
    heading = [np.array([0, 0, 0, 0, params.c * cl / params.w, 0, 0, 0]),
               np.array([0, cl / params.w, 0, 0, 0, 0, 0, 0])]
    lateral = [None, np.array([0, 0, 0, 0, 0, 0, 1.0, 0])]
    return second_order_model("lean", coordinates, rates, M, [C0, C1], [K0, None, K2],
                              np.array([[1.0, 0], [0, 1.0], [0, 0]]), INPUTS,
                              kinematics=[(Signal("heading", "rad"), heading), (Signal("lateral", "m"), lateral)],
                              families={"bicycle": (0, 1), "lean": (2,)})


def test_a_model_with_more_states_gets_everything():
    params = bm.parameters("benchmark")
    model = rider_lean_model(params)
    assert model.n_dynamic == 6 and len(model.states) == 8
    tf = bm.transfer_function(model, 5.0, "steer-torque", "lean-angle")
    assert len(tf.poles) == 6
    fr = bm.frequency_response(model, 5.0, "steer-torque", "lean-angle", [1.0, 3.0])
    assert fr.values == pytest.approx(tf(1j * np.array([1.0, 3.0])), rel=1e-10)
    r = bm.simulate(model, 5.0, initial={"lean-rate": 0.2}, duration=0.5)
    assert r.values.shape == (51, 8) and r["lean-rate"][0] == 0.2
    shapes = bm.mode_shapes(model, 5.0)
    assert shapes.coordinates == ("roll-angle", "steer-angle", "lean-angle", "heading", "lateral")
    assert len(shapes.labels) == 6 and shapes.n_mechanical == 3
    result = bm.handling(model, [5.0])
    assert result.lateral == "lateral" and np.isfinite(result.hqm_peak[0])
    # the Whipple bicycle is the limit of a stiff, light lean: its handling is close to the bicycle's
    assert result.hqm_peak[0] == pytest.approx(bm.handling(whipple_model(params), [5.0]).hqm_peak[0], rel=0.3)


def test_figures_are_figures_and_leave_pyplot_alone():
    code = """
import sys, matplotlib
matplotlib.use("svg")
from matplotlib.figure import Figure
import bikemass as bm
p = bm.parameters("benchmark")
figures = [bm.plot_bode([bm.frequency_response(p, v, "steer-torque", "roll-angle") for v in (3.0, 5.0)]),
           bm.plot_time_response(bm.simulate(p, 4.6, initial={"roll-rate": 0.5})),
           bm.plot_mode_shapes(bm.mode_shapes(p, 5.0)),
           bm.plot_handling(bm.handling(p, [4.0, 5.0]), stable_speeds=[(4.29, 6.02)]),
           bm.plot_lane_change(bm.lane_change(p, 5.0))]
assert all(isinstance(f, Figure) and f._repr_png_().startswith(b"\\x89PNG") for f in figures)   # Jupyter shows them
assert matplotlib.get_backend() == "svg" and "matplotlib.pyplot" not in sys.modules
print("ok")
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={"PYTHONPATH": str(SRC), "PATH": "/usr/bin:/bin"},
                          timeout=300)
    assert done.stdout.strip() == "ok", done.stderr[-2000:]


@pytest.mark.parametrize("module", ["transfer", "frequency", "time_response", "mode_shapes", "survey", "lane_change"])
def test_docstring_examples_run(module):
    mod = importlib.import_module(f"bikemass.analysis.handling.{module}")
    failed, attempted = doctest.testmod(mod, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert attempted and not failed


def test_handling_table_names_a_tuning_other_than_the_default(capsys):
    """The gains column says "tuned" for either tuning, so the title names bmd2016 (the default's title is
    as docs/handling.md shows it)."""
    code, out, _ = run(capsys, "handling", "benchmark", "--speeds", 5, "--tuning", "bmd2016")
    assert code == 0 and "rigid frame, gains tuned by bmd2016: Hess, Moore & Hubbard" in out.splitlines()[0]
    code, out, _ = run(capsys, "handling", "benchmark", "--speeds", 5)
    assert code == 0 and "tuned by" not in out.splitlines()[0]
