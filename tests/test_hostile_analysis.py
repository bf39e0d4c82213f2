"""Hostile input to the analysis layer (sweep specs, uncertainty spreads and options, parameter
changes): refused with InputError before any work, or a row/draw refused instead of a
nonsense number."""

import math
import re

import pytest

from bikemass.scenario.inputs import Model
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
    """n = 4,000,000 base points of 4 keys is 24,000,000 configurations, not 4,000,000."""
    keys = "".join(f"  {k}: {{from: 0.01, to: 0.2}}\n" for k in ("c", "w", "rR", "rF"))
    text = f"bike: benchmark\nvary:\n{keys}global_sensitivity: true\nsample: {{method: sobol, n: 4000000}}\n"
    with pytest.raises(InputError, match="this sample has 24000000"):
        read_spec(_spec(tmp_path, text))


def test_sample_seed_must_be_whole(tmp_path):
    text = "bike: benchmark\nvary:\n  c: {from: 0, to: 0.2}\nsample: {method: lhs, n: 4, seed: 1.5}\n"
    with pytest.raises(InputError, match="sample.seed: a whole number"):
        read_spec(_spec(tmp_path, text))


def test_changed_parameters_are_checked():
    model = Model("benchmark")
    for change, key in (({"mB": -85.0}, "mB"), ({"lam": 2.0}, "lam"), ({"lam": 0.0}, "lam"),
                        ({"rF": 0.0}, "rF"), ({"IBxz": 50.0}, "IBxz")):
        with pytest.raises(InputError, match=f": {key}: "):
            model.build(change)
    p, _ = model.build({"mB": 90.0})
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
        propagate(Model("benchmark"), {"c": Spread("normal", 0.002)}, **kwargs)


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
