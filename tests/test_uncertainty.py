"""Uncertainty propagation: linear against BicycleParameters' own (the `uncertainties` package),
Monte Carlo against linear where both should agree."""

import json
from pathlib import Path

import bicycleparameters
import numpy as np
import pytest
from images import is_drawn
from uncertainties import unumpy

from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.scenario.scenario import Scenario
from bikemass.analysis.uncertainty import Spread, propagate
from bikemass.cli.main import main
import bikemass as bm

BP_DATA = Path(bicycleparameters.__file__).parent / "app-data"
BROWSER = BP_DATA / "bicycles" / "Browser" / "Parameters" / "BrowserBenchmark.txt"


PEER_BROWSER = bicycleparameters.Bicycle("Browser", pathToData=str(BP_DATA)).parameters["Benchmark"]
"""The Browser's benchmark parameters as BicycleParameters reads them (ufloats: value +/- std)."""


def _peer_weave_speed(values):
    """The weave speed (m/s) of the Whipple model on BicycleParameters' canonical matrices of ``values``."""
    from bicycleparameters.bicycle import benchmark_par_to_canonical
    from scipy.optimize import brentq
    M, C1, K0, K2 = (np.asarray(x, dtype=float) for x in benchmark_par_to_canonical(values))
    inverse = np.linalg.inv(M)

    def growth(v):
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-inverse @ (values["g"] * K0 + v * v * K2), -v * inverse @ C1]])
        return max(z.real for z in np.linalg.eigvals(A) if abs(z.imag) > 1e-6)
    return brentq(growth, 3.5, 5.0, xtol=1e-14)


def test_linear_matrix_std_equals_bicycleparameters(capsys):
    """`bikemass uncertainty BrowserBenchmark.txt --method linear --format json` (the file as
    BicycleParameters ships it, +/- values read): std of M, C1, K0, K2 equal BicycleParameters'
    own propagation (Bicycle.canonical(), the `uncertainties` package) to 1e-6 relative."""
    peer = bicycleparameters.Bicycle("Browser", pathToData=str(BP_DATA)).canonical()
    capsys.readouterr()
    assert main(["uncertainty", str(BROWSER), "--method", "linear", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    for name, U in zip(("M", "C1", "K0", "K2"), peer):
        ref = unumpy.std_devs(U)
        np.testing.assert_allclose(doc["matrices"][name]["std"], ref, rtol=1e-6, atol=1e-15)
        np.testing.assert_allclose(doc["matrices"][name]["nominal"], unumpy.nominal_values(U), rtol=1e-12)
    assert len(doc["inputs"]) == 26 and doc["inputs"]["g"]["std"] == 0.01
    # the weave speed against the peer's own matrices: BicycleParameters' benchmark_par_to_canonical of
    # the file's nominal values, its crossing by brentq (1e-14 m/s); the std by first-order
    # propagation of central differences of that crossing (steps 1e-3 std: truncation ~1e-7)
    nominal = {k: getattr(v, "nominal_value", v) for k, v in PEER_BROWSER.items()}
    std = {k: getattr(v, "std_dev", 0.0) for k, v in PEER_BROWSER.items()}
    assert doc["weave_speed"]["nominal"] == pytest.approx(_peer_weave_speed(nominal), rel=1e-10)
    rss = np.sqrt(sum((s * (_peer_weave_speed({**nominal, k: nominal[k] + 1e-3 * s})
                            - _peer_weave_speed({**nominal, k: nominal[k] - 1e-3 * s})) / (2e-3 * s)) ** 2
                      for k, s in std.items() if s > 0))
    assert doc["weave_speed"]["std"] == pytest.approx(rss, rel=1e-6)


def test_montecarlo_agrees_with_linear_for_small_spreads():
    """Seeded; with the Browser's small spreads the outputs are near-linear: MC std within about
    3 times its sampling error (~4 % at 300 samples) of the linear std; the MC mean within 3
    standard errors of the nominal value plus 5 % of a std for the second-order bias."""
    model = Scenario(str(BROWSER))
    spreads = {k: Spread("normal", v) for k, v in model.file_std.items()}
    mc = propagate(model, spreads, "montecarlo", samples=300, seed=7, speeds=np.linspace(0, 8, 9))
    for name in ("weave_speed", "capsize_speed"):
        s = mc.speeds[name]
        assert s.std == pytest.approx(s.linear_std, rel=0.14)
        assert abs(s.mean - s.nominal) < (3 / np.sqrt(300) + 0.05) * s.linear_std
        assert s.fraction_without == 0
    for m in ("M", "C1", "K2"):
        np.testing.assert_allclose(mc.matrices[m]["std"], mc.matrices[m]["linear_std"], rtol=0.14, atol=1e-12)


def test_linear_eigenvalue_std_equals_differences():
    """Eigenvalue std at 5 m/s (weave pair and capsize, away from any double root) from the
    eigenvector derivatives equals the root-sum-square of central differences."""
    p = scenario_parameters("benchmark")
    spreads = {"c": Spread("normal", 0.002), "lam": Spread("normal", 0.004), "mB": Spread("normal", 0.3)}
    r = propagate(Scenario("benchmark"), spreads, speeds=np.array([3.0, 5.0, 8.0]))
    from bikemass.analysis.engine.modes import follow_modes
    from bikemass.models.whipple import whipple_model
    speeds = np.concatenate([np.linspace(0, 3, 61), [5.0, 8.0]])
    fd = {}
    for k, s in spreads.items():
        x = getattr(p, k)
        h = 1e-6 * abs(x)
        a = follow_modes(whipple_model(p.replace(**{k: x + h})), speeds).eigenvalues[-3:]
        b = follow_modes(whipple_model(p.replace(**{k: x - h})), speeds).eigenvalues[-3:]
        fd[k] = (a - b) / (2 * h) * s.std
    rss_re = np.sqrt(sum(d.real ** 2 for d in fd.values()))
    for i, label in enumerate(("weave 1", "weave 2", "capsize", "caster")):
        np.testing.assert_allclose(r.eigen["modes"][label]["std_re"], rss_re[:, i], rtol=1e-5)


def test_geometry_level_input_and_bad_files(tmp_path, capsys):
    """A tube wall of the Jamis as an input: its std reaches the mass matrix; bad spreads: one line."""
    spec = tmp_path / "u.yaml"
    spec.write_text("uncertainty:\n  sections.seat_stay.wall: 0.004\n")
    assert main(["uncertainty", "jamis", "--std", str(spec), "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["matrices"]["M"]["std"][0][0] > 0 and doc["weave_speed"]["std"] > 0
    for text in ("uncertainty:\n  c: -1\n", "uncertainty:\n  c: {distribution: cauchy, std: 1}\n",
                 "uncertainty:\n  sections.nope.wall: 0.1\n", "nothing: 1\n",
                 "uncertainty:\n  c: {distribution: uniform}\n"):
        spec.write_text(text)
        assert main(["uncertainty", "jamis", "--std", str(spec)]) == 2
    assert main(["uncertainty", "benchmark"]) == 2
    assert main(["uncertainty", "benchmark", "--std", str(spec), "--samples", "1", "--method", "montecarlo"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 7 and all(line.startswith("bikemass: error:") for line in err)


def test_uncertainty_speaks_the_dialect(tmp_path, capsys):
    """--plot alone: the figure and nothing on stdout; --format csv: the 16 matrix entries and two
    critical speeds with the JSON's nominal values and stds; -o FILE.csv: CSV by the suffix."""
    import csv
    import io
    spec = tmp_path / "u.yaml"
    spec.write_text("uncertainty:\n  c: 0.002\n  lam: 0.01\n")
    base = ["uncertainty", "benchmark", "--std", str(spec), "--speeds", "0:8:0.5"]
    fig = tmp_path / "bands.png"
    assert main(base + ["--plot", str(fig)]) == 0
    assert capsys.readouterr().out == "" and is_drawn(fig)
    assert main(base + ["--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert main(base + ["--format", "csv"]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert [r["quantity"] for r in rows][-2:] == ["weave_speed", "capsize_speed"] and len(rows) == 18
    by_name = {r["quantity"]: r for r in rows}
    for m in ("M", "C1", "K0", "K2"):
        for i in range(2):
            for j in range(2):
                row = by_name[f"{m}[{i},{j}]"]
                assert float(row["std"]) == pytest.approx(doc["matrices"][m]["std"][i][j], rel=1e-15, abs=1e-300)
                assert float(row["nominal"]) == pytest.approx(doc["matrices"][m]["nominal"][i][j], rel=1e-15)
    assert float(by_name["weave_speed"]["std"]) == pytest.approx(doc["weave_speed"]["std"], rel=1e-15)
    assert by_name["weave_speed"]["unit"] == "m/s" and by_name["M[0,1]"]["unit"] == "kg m^2"
    assert main(base + ["-o", str(tmp_path / "u.csv")]) == 0
    assert capsys.readouterr().out == ""
    assert (tmp_path / "u.csv").read_text().startswith("quantity,unit,nominal,std")


def test_a_members_matrices_spread_as_a_high_precision_difference_says():
    """A member's propagation reports its state matrix's coefficients A0, A1, A2 (the dynamic block of
    A0 + v A1 + v^2 A2); their linear std is |dA/dx| std, checked against a Richardson-extrapolated central
    difference through the builder (1e-7 relative: the difference's truncation error)."""
    from bikemass.analysis.uncertainty import coefficients_of
    scenario = bm.Scenario("benchmark", model="tyre")
    std = {"c": 0.001, "w": 0.01}
    for key, sigma in std.items():
        u = bm.uncertainty(scenario, {key: sigma})
        x = scenario.value(key)

        def diff(h):
            a, b = coefficients_of(scenario.build({key: x + h}).model), coefficients_of(scenario.build({key: x - h}).model)
            return {k: (a[k] - b[k]) / (2 * h) for k in a}
        coarse, fine = diff(1e-3 * abs(x)), diff(5e-4 * abs(x))
        for name in ("A0", "A1", "A2"):
            reference = np.abs((4 * fine[name] - coarse[name]) / 3) * sigma
            scale = max(np.abs(reference).max(), 1e-300)
            np.testing.assert_allclose(u.matrices[name]["std"], reference, rtol=0, atol=1e-7 * scale)
            np.testing.assert_allclose(u.matrices[name]["nominal"], coefficients_of(scenario.build().model)[name],
                                       rtol=0, atol=0)


def test_the_keywords_given_beside_a_scenario_change_it():
    """``bm.uncertainty(scenario, model=...)``, like ``bm.stability``, applies the keywords to the scenario
    (they were dropped without a word): the nominal weave speed is that of the changed scenario."""
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)       # the Browser's IByy, as measured
        scenario = bm.Scenario("browser-measured")
        tyre = bm.uncertainty(scenario, model="tyre").speeds["weave_speed"].nominal
        reference = bm.stability(scenario.replace(model="tyre")).weave_speeds[0]
        plain = bm.uncertainty(scenario).speeds["weave_speed"].nominal
    assert tyre == pytest.approx(reference, abs=1e-9)
    assert abs(tyre - plain) > 0.1


def test_a_members_own_parameter_spreads_by_both_methods(tmp_path, capsys):
    """A member's own parameter (the tyres' ``CaF``, an input of the scenario) has a linear spread equal to its
    exact derivative times its std (the sensitivity's), and Monte Carlo draws of it (each built through the
    scenario) agree with it within 10 % (400 seeded draws of a spread small enough to be linear: the
    standard error of a sample std is 3.5 %); the std file takes it as the command line's input."""
    import bikemass as bm
    from bikemass.cli.main import main
    scenario = Scenario("benchmark", model="tyre")
    linear = propagate(scenario, {"CaF": Spread("normal", 0.1)})
    d = bm.sensitivity(scenario, names=("CaF",)).d_weave_speed["CaF"]
    assert linear.speeds["weave_speed"].std == pytest.approx(abs(d) * 0.1, rel=1e-9)
    mc = propagate(scenario, {"CaF": Spread("normal", 0.1)}, method="montecarlo", samples=400, seed=3)
    assert mc.speeds["weave_speed"].std == pytest.approx(linear.speeds["weave_speed"].std, rel=0.1)
    std = tmp_path / "std.yaml"
    std.write_text("uncertainty:\n  CaF: 0.1 1/rad\n  c: 0.001 m\n")
    assert main(["uncertainty", "benchmark", "--model", "tyre", "--std", str(std), "--method", "montecarlo",
                 "--samples", "20", "--format", "json"]) == 0
    assert set(json.loads(capsys.readouterr().out)["inputs"]) == {"CaF", "c"}


@pytest.mark.parametrize("bike, options, entry, words", [
    ("benchmark", [], "lam: 0.2 m", "uncertainty.lam: a spread of an angle"),
    ("benchmark", [], "w: 3 deg", "uncertainty.w: a spread of a length"),
    ("benchmark", [], "mB: 0.2 m", "uncertainty.mB: a spread of a mass"),
    ("jamis", [], "geometry.head_angle: 5 kg", "uncertainty.geometry.head_angle: a spread of an angle"),
    ("jamis", ["--rider", "relaxed", "--model", "tyre"], "sigmaF: 5 deg", "uncertainty.sigmaF: a spread of a length"),
    ("jamis", ["--rider", "relaxed", "--model", "tyre"], "CaF: 1.0 m", "uncertainty.CaF: a spread of an inverse angle"),
    ("jamis", ["--rider", "relaxed"], "geometry.trail: 2 deg", "uncertainty.geometry.trail: a spread of a length"),
    ("jamis", ["--rider", "relaxed"], "geometry.rear_wheel_radius: 3 kg",
     "uncertainty.geometry.rear_wheel_radius: a spread of a length"),
])
def test_a_std_files_spread_in_another_dimension_is_refused(tmp_path, capsys, bike, options, entry, words):
    """A spread written in a unit of another dimension than its input's (a length for the steer-axis tilt) was
    taken as its number alone (0.2 m as 0.2 rad; 2 deg of trail, which the file writes bare, as 0.035 m); it is
    refused in one line naming the file, the key, the input's dimension and the unit's."""
    from bikemass.cli.main import main
    std = tmp_path / "u.yaml"
    std.write_text(f"uncertainty:\n  {entry}\n")
    assert main(["uncertainty", bike, *options, "--std", str(std), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(std) in err[0] and words in err[0]


def test_a_std_files_spread_in_another_unit_of_the_same_dimension_is_converted(tmp_path, capsys):
    """``w: 3 mm`` is 0.003 m, ``lam: 0.5 deg`` 0.0087 rad: the spreads the JSON reports (SI)."""
    from bikemass.cli.main import main
    std = tmp_path / "u.yaml"
    std.write_text("uncertainty:\n  w: 3 mm\n  lam: 0.5 deg\n")
    assert main(["uncertainty", "benchmark", "--std", str(std), "--format", "json"]) == 0
    inputs = json.loads(capsys.readouterr().out)["inputs"]
    assert inputs["w"]["std"] == pytest.approx(0.003, rel=1e-12)
    assert inputs["lam"]["std"] == pytest.approx(0.5 * np.pi / 180, rel=1e-12)


def test_a_grid_over_the_limit_names_a_way_out_only_where_the_command_has_one(tmp_path, capsys):
    """``uncertainty --speeds 0:1000:0.001`` said "(raise with --max-speeds)", an option it does not have; it
    names no such option now, and ``stability``, which has it, still does."""
    from bikemass.cli.main import main
    std = tmp_path / "u.yaml"
    std.write_text("uncertainty:\n  w: 0.01\n")
    assert main(["uncertainty", "benchmark", "--std", str(std), "--speeds", "0:1000:0.001"]) == 2
    assert main(["stability", "benchmark", "--speeds", "0:1000:0.001"]) == 2
    unc, stab = capsys.readouterr().err.strip().splitlines()
    assert "at most" in unc and "--max-speeds" not in unc
    assert "raise with --max-speeds" in stab


def test_a_spread_on_a_code_parameter_that_is_no_input_is_refused_by_both_methods(tmp_path, capsys):
    """The flexible frame's modal mass ``mtr`` follows from the beam models: the linear method took a spread on it
    (with any unit) and Monte Carlo said "no 'mtr' under (top)"; both refuse it in one line naming the inputs."""
    from bikemass.cli.main import main
    std = tmp_path / "u.yaml"
    std.write_text("uncertainty:\n  mtr: 0.01\n")
    scenario = ["jamis", "--rider", "relaxed", "--stiffness", "steel", "--model", "flexible", "--std", str(std)]
    assert main(["uncertainty", *scenario]) == 2
    assert main(["uncertainty", *scenario, "--method", "montecarlo", "--samples", "20"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all("mtr: one of the flexible model's inputs (cs, kr, kf)" in line for line in err)
