"""Hostile input to the analysis layer (sweep specs, uncertainty spreads and options, parameter
changes): refused with InputError before any work, or a row/draw refused instead of a
nonsense number."""

import math
import re

import pytest

from bikemass.scenario.scenario import Scenario
from bikemass.analysis.uncertainty import Spread, propagate, uncertainty
from bikemass.core.errors import InputError
from bikemass.sweep.run import run_sweep
from bikemass.sweep.spec import MAX_CONFIGURATIONS, read_spec

BENCHMARK_WEAVE = 4.292382536     # m/s, Meijaard et al. (2007); our crossings are exact to 1e-9


def _spec(tmp_path, text):
    path = tmp_path / "spec.yaml"
    path.write_text(text)
    return path


def test_grid_count_is_exact_beyond_64_bits(tmp_path):
    """8192^5 = 2^65 configurations: a fixed-width product wraps to 0 and let the grid through."""
    keys = "".join(f"  {k}: {{from: 0.01, to: 0.2, num: 8192}}\n" for k in ("c", "w", "rR", "rF", "xB"))
    with pytest.raises(InputError, match=f"at most {MAX_CONFIGURATIONS} configurations .*{2 ** 65}"):
        read_spec(_spec(tmp_path, "bike: benchmark\nvary:\n" + keys))


def test_saltelli_sample_counts_n_times_d_plus_2(tmp_path):
    """n = 400,000 base points of 4 keys is 2,400,000 configurations, not 400,000."""
    keys = "".join(f"  {k}: {{from: 0.01, to: 0.2}}\n" for k in ("c", "w", "rR", "rF"))
    text = f"bike: benchmark\nvary:\n{keys}global_sensitivity: true\nsample: {{method: sobol, n: 400000}}\n"
    with pytest.raises(InputError, match="this sample has 2400000"):
        read_spec(_spec(tmp_path, text))


def test_sample_seed_must_be_whole(tmp_path):
    text = "bike: benchmark\nvary:\n  c: {from: 0, to: 0.2}\nsample: {method: lhs, n: 4, seed: 1.5}\n"
    with pytest.raises(InputError, match="sample.seed: a whole number"):
        read_spec(_spec(tmp_path, text))


def test_changed_parameters_are_checked():
    scenario = Scenario("benchmark")
    for change, key in (({"mB": -85.0}, "mB"), ({"lam": 2.0}, "lam"), ({"lam": -1.6}, "lam"),
                        ({"rF": 0.0}, "IFyy"), ({"mF": 0.0}, "IFxx"), ({"IBxz": 50.0}, "IBxz")):
        with pytest.raises(InputError, match=f": {key}: "):
            scenario.build(change)
    p = scenario.build({"mB": 90.0}).parameters
    assert p.mB == 90.0


def test_sweep_rows_with_impossible_parameters_carry_an_error(tmp_path):
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  mB: [-85, 85]\n  lam: [2.0, 0.3141592653589793]\n")
    rows = run_sweep(spec, tmp_path / "out")
    assert len(rows) == 4
    by = {(r["mB"], r["lam"]): r for r in rows}
    for bad in ((-85.0, 2.0), (-85.0, 0.3141592653589793), (85.0, 2.0)):
        assert by[bad]["error"] and by[bad]["weave_speed"] is None and by[bad]["total_mass"] is None
    good = by[(85.0, 0.3141592653589793)]
    assert good["error"] is None
    assert good["weave_speed"] == pytest.approx(BENCHMARK_WEAVE, abs=1e-8)


def test_unreadable_scheduler_address_leaves_no_folder(tmp_path):
    pytest.importorskip("distributed")
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  c: [0.08]\n")
    with pytest.raises(InputError, match="--scheduler: nonsense: a running Dask scheduler"):
        run_sweep(spec, tmp_path / "out", scheduler="nonsense")
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("kwargs, match", [
    ({"method": "montecarlo", "samples": 0}, "samples: 0"),
    ({"method": "montecarlo", "samples": 2.5}, "samples: 2.5"),
    ({"method": "montecarlo", "samples": 10, "seed": -1}, "seed: -1"),
    ({"method": "montecarlo", "samples": 10, "seed": 1.5}, "seed: 1.5"),
    ({"method": "bayes"}, "method: bayes"),
])
def test_propagation_options_are_checked(kwargs, match):
    with pytest.raises(InputError, match=match):
        propagate(Scenario("benchmark"), {"c": Spread("normal", 0.002)}, **kwargs)


@pytest.mark.parametrize("std", [-0.01, math.nan, math.inf, "big", True])
def test_spreads_are_checked(std):
    with pytest.raises(InputError, match="spreads: c: a finite standard deviation >= 0"):
        uncertainty("benchmark", {"c": std})
    with pytest.raises(InputError, match="a finite standard deviation"):
        uncertainty("benchmark", {"c": Spread("uniform", std)})


def test_montecarlo_draw_off_the_model_is_refused():
    """A mass spread wider than the mass draws negative masses: refused, naming the draw."""
    with pytest.raises(InputError, match=r"mB: spreads whose Monte Carlo draws stay valid \(draw \d+ of 50: "
                                         "a positive number"):
        uncertainty("benchmark", {"mB": 200.0}, method="montecarlo", samples=50, seed=0)


def test_sweep_stiffness_choices_are_checked_once(tmp_path):
    for text, key in (("bike: benchmark\nstiffness: rubber\nvary:\n  c: [0.08]\n", "stiffness"),
                      ("bike: jamis\nvary:\n  stiffness: [steel, rubber]\n", "vary.stiffness")):
        with pytest.raises(InputError, match=f"spec.yaml: {key}: infinite, a material"):
            run_sweep(_spec(tmp_path, text), tmp_path / "out")
        assert not (tmp_path / "out").exists()


def _cli(capsys, *argv):
    from bikemass.cli.main import main
    status = main(list(argv))
    return status, capsys.readouterr().err.strip().splitlines()


def test_names_too_long_for_the_system_are_one_line(capsys, tmp_path):
    long = "x" * 5000
    for argv in (["params", long], ["rider", long], ["params", "benchmark", "-o", str(tmp_path / f"{long}.yaml")],
                 ["eig", "benchmark", "--plot", str(tmp_path / f"{long}.png")]):
        status, err = _cli(capsys, *argv)
        assert status == 2 and len(err) == 1 and "system accepts (File name too long)" in err[0]


def test_empty_sensitivity_inputs_are_refused(capsys):
    status, err = _cli(capsys, "sensitivity", "benchmark", "--inputs", ",")
    assert status == 2 and err == ["bikemass: error: --inputs: ',': a comma-separated list of at least one dotted path"]


@pytest.mark.parametrize("change, fragment", [({"rR": 300.0}, "wheel radius rR = 300 m"),
                                              ({"c": 5.0}, "trail c = 5 m is longer than the wheelbase"),
                                              ({"xB": 30.0}, "centre of mass [xB, zB] = [30, -0.9] m is far")])
def test_absurd_parameter_files_are_warned_about(change, fragment):
    import bikemass as bm
    from bikemass.core.errors import BikemassWarning
    values = {**bm.parameters("benchmark").to_dict(), **change, "name": "absurd"}
    with pytest.warns(BikemassWarning, match=re.escape(fragment)):
        bm.parameters(bm.load_bicycle(values))


@pytest.mark.parametrize("extra, key", [({"mass": "7500 kg"}, "body.mass"), ({"mass": "1 kg"}, "body.mass"),
                                        ({"arm_length": "5 m"}, "body.arm_length"),
                                        ({"shoulder_width": "3 m"}, "body.shoulder_width")])
def test_absurd_bodies_from_height_and_mass_are_refused(extra, key):
    import bikemass as bm
    body = {"height": "1.80 m", "mass": "75 kg", "sex": "male", **extra}
    with pytest.raises(InputError, match=f": {key}: .*between"):
        bm.load_rider({"body": body, "bike": "jamis", "chain": {"torso_lean": "45 deg", "hands": "tops"}})


# ---------------------------------------------------------------- issue 23: one outcome, folders, limits
def test_a_sweep_whose_every_row_fails_is_an_error_and_leaves_no_folder(tmp_path):
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  mB: [-1.0, -2.0]\n")
    with pytest.raises(InputError, match=r"vary: configurations the model accepts; all 2 were refused, the first: .*mB"):
        run_sweep(spec, tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_a_sweep_with_some_rows_refused_warns_and_keeps_them(tmp_path):
    from bikemass.core.errors import BikemassWarning
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  mB: [85.0, -1.0]\n")
    with pytest.warns(BikemassWarning, match="1 of 2 configurations were refused by the model"):
        rows = run_sweep(spec, tmp_path / "out")
    assert rows[0]["error"] is None and rows[0]["weave_speed"] == pytest.approx(BENCHMARK_WEAVE, abs=1e-9)
    assert "mB: a positive number" in rows[1]["error"]


def test_a_resumed_sweep_recomputes_a_damaged_chunk_to_the_same_rows(tmp_path, capsys):
    from bikemass.cli.main import main
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  c: [0.07, 0.08, 0.09]\nchunk: 1\n")
    fresh = list(run_sweep(spec, tmp_path / "out"))
    first = tmp_path / "out" / "chunks" / "000000000-000000001.csv"
    first.write_text(first.read_text()[:15])                            # cut short, as by a full disk
    second = tmp_path / "out" / "chunks" / "000000001-000000002.csv"
    second.write_text(second.read_text().replace(",", ",x", 2))         # a number that is not one
    assert main(["sweep", str(spec), "--out", str(tmp_path / "out"), "--quiet"]) == 0   # its own folder: resumed
    again = run_sweep(spec, tmp_path / "out")
    assert again == fresh


def test_a_folder_with_chunks_but_no_record_is_not_resumed_from_python(tmp_path):
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  c: [0.08]\n")
    (tmp_path / "out" / "chunks").mkdir(parents=True)
    (tmp_path / "out" / "chunks" / "000000000-000000001.csv").write_text("")
    with pytest.raises(InputError, match="no sweep.json, so its chunks could be another sweep's"):
        run_sweep(spec, tmp_path / "out")


def test_varied_values_with_units_reach_the_model_with_them(tmp_path):
    """lam given in degrees is the same sweep as lam given in radians (SI) to 1e-12."""
    degrees = run_sweep(_spec(tmp_path, "bike: benchmark\nvary:\n  lam: [\"17 deg\", \"18 deg\"]\n"), tmp_path / "a")
    radians = run_sweep(_spec(tmp_path, f"bike: benchmark\nvary:\n  lam: [{math.radians(17)!r}, {math.radians(18)!r}]\n"),
                        tmp_path / "b")
    for d, r in zip(degrees, radians):
        assert d["lam"] == pytest.approx(r["lam"], rel=1e-15)
        assert d["weave_speed"] == pytest.approx(r["weave_speed"], abs=1e-12)


def test_a_dotted_value_with_a_unit_is_that_value(tmp_path):
    """The chain stays' wall swept as "1.5 mm" and "0.07 in" (listed in the first's unit: 1.778 mm)
    gives the weave speeds of Jamis files whose wall is written so, to 1e-9 m/s."""
    import yaml

    import bikemass as bm
    from bikemass.core.paths import frames_dir
    spec = "bike: jamis\nvary:\n  sections.chain_stay.wall: [\"1.5 mm\", \"0.07 in\"]\n"
    rows = run_sweep(_spec(tmp_path, spec), tmp_path / "o")
    assert [r["sections.chain_stay.wall"] for r in rows] == [1.5, pytest.approx(1.778, rel=1e-12)]
    jamis = yaml.safe_load((frames_dir() / "jamis.yaml").read_text())
    for row, wall in zip(rows, ("1.5 mm", "0.07 in")):
        sections = {**jamis["sections"], "chain_stay": {**jamis["sections"]["chain_stay"], "wall": wall}}
        f = tmp_path / "jamis.yaml"
        f.write_text(yaml.safe_dump({**jamis, "sections": sections}))
        p = bm.parameters(str(f))
        assert row["error"] is None and row["weave_speed"] == pytest.approx(bm.stability(p).weave_speeds[0], abs=1e-9)
        assert row["total_mass"] == pytest.approx(p.mR + p.mB + p.mH + p.mF, rel=1e-12)
    assert rows[1]["total_mass"] - rows[0]["total_mass"] > 1e-3       # 0.28 mm more wall: grams of steel


def test_a_speed_grid_never_goes_past_its_stop(capsys):
    import bikemass as bm
    from bikemass.cli.main import main
    assert list(bm.speeds(0, 10, 6)) == [0.0, 6.0]
    assert main(["eig", "benchmark", "--speeds", "0:10:6", "--format", "csv"]) == 0
    assert [line.split(",")[0] for line in capsys.readouterr().out.splitlines()[1:]] == ["0.0", "6.0"]
    assert len(bm.speeds(0, 30, 0.05)) == 601 and len(bm.speeds(0, 10, 0.1)) == 101


@pytest.mark.parametrize("start, stop, step, count", [
    (0, 10, 6, 2), (0, 10, 10, 2), (2.5, 1000, 997.5, 2), (0, 0.001, 1e-6, 1001),
    (0, 10, 20, None), (0, 1001, 1, None), (0, 1, 1e-7, None), (-1, 10, 1, None), (5, 5, 1, None),
    (0, 1000, 0.001, None)])            # the last: 1_000_001 speeds, over the default limit
def test_the_api_and_the_command_line_take_the_same_speed_grids(capsys, start, stop, step, count):
    """``bm.speeds(start, stop, step)`` and ``--speeds START:STOP:STEP`` accept the same grids (the
    limits of core.limits: 0 <= START < STOP <= 1000 m/s, 1e-6 <= STEP <= STOP - START, at most
    --max-speeds speeds), and a grid accepted has floor((stop - start) / step) + 1 speeds."""
    import bikemass as bm
    from bikemass.cli.main import main
    text = f"{start}:{stop}:{step}"
    status = main(["eig", "benchmark", "--speeds", text, "--format", "csv", "--quiet"])
    err = capsys.readouterr().err
    if count is None:
        assert status == 2 and "--speeds" in err, err
        with pytest.raises(InputError, match="START:STOP:STEP|at most 100000 speeds"):
            bm.speeds(start, stop, step)
        return
    grid = bm.speeds(start, stop, step)
    assert status == 0 and len(grid) == count == math.floor((stop - start) / step + 1e-9) + 1
    assert grid[0] == start and grid[-1] <= stop


def test_the_api_bounds_speed_grids_before_allocating():
    import numpy as np

    import bikemass as bm
    params = bm.parameters("benchmark")
    with pytest.raises(InputError, match="at most 100000 speeds"):
        bm.stability(params, speeds=range(10 ** 12))                  # refused before any array is made
    with pytest.raises(InputError, match="at most 100000 speeds"):
        bm.eigenvalues(params, speeds=np.linspace(0, 10, 100_001))
    with pytest.raises(InputError, match="at most 100000 speeds"):
        uncertainty("benchmark", {"c": 0.001}, speeds=np.linspace(0, 10, 100_001))
    assert len(bm.stability(params, speeds=np.linspace(0, 10, 100_001), max_speeds=100_001).speeds) == 100_001
    with pytest.raises(InputError, match="samples x speeds"):
        uncertainty("benchmark", {"c": 0.001}, method="montecarlo", samples=200_000, speeds=np.linspace(0, 10, 101))


@pytest.mark.slow     # waits out a scheduler's connect timeout (~20 s)
def test_a_scheduler_that_never_answers_is_one_line(tmp_path, capsys):
    """A listener that accepts the connection and never speaks: distributed (2026.8) does not end the
    wait; the sweep gives up after bikemass.sweep.run.CONNECT_DEADLINE seconds."""
    pytest.importorskip("distributed")
    import socket
    import threading

    from bikemass.cli.main import main
    listener = socket.socket()
    listener.bind(("127.0.0.1", 0))
    listener.listen(8)
    held = []
    stop = threading.Event()

    def accept():
        listener.settimeout(0.5)
        while not stop.is_set():
            try:
                held.append(listener.accept()[0])
            except OSError:
                pass
    thread = threading.Thread(target=accept, daemon=True)
    thread.start()
    try:
        spec = _spec(tmp_path, "bike: benchmark\nvary:\n  c: [0.08]\n")
        address = f"tcp://127.0.0.1:{listener.getsockname()[1]}"
        assert main(["sweep", str(spec), "--out", str(tmp_path / "out"), "--scheduler", address]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--scheduler" in err and "a running Dask scheduler (" in err   # distributed's
        assert "internal error" not in err                         # own timeout, or ours after 20 s: one line
        assert not (tmp_path / "out").exists()
    finally:
        stop.set()
        thread.join()
        for conn in held:
            conn.close()
        listener.close()
