"""Uncertainty propagation: linear against the `uncertainties` package (through BicycleParameters'
own canonical-matrix formulas), Monte Carlo against linear where both should agree."""

import json

import numpy as np
import pytest
from bicycleparameters.bicycle import benchmark_par_to_canonical
from uncertainties import ufloat, unumpy

from bikemass import catalog
from bikemass.analysis.inputs import Model
from bikemass.analysis.uncertainty import Spread, propagate
from bikemass.cli import main
from bikemass.parameters import NAMES

# BicycleParameters' Browser (BrowserBenchmark.txt): nominal +/- std of every parameter
BROWSER = {
    "IBxx": (0.5296, 0.00247550148476), "IBxz": (-0.1163, 0.00114783359707), "IByy": (1.3164, 0.00400774617153),
    "IBzz": (0.7568, 0.00330394515109), "IFxx": (0.0884, 0.00035969731805), "IFyy": (0.1492, 0.00151585483097),
    "IHxx": (0.2534, 0.00126852786611), "IHxz": (-0.0720, 0.000790281755242), "IHyy": (0.2458, 0.00299166644562),
    "IHzz": (0.0956, 0.000737521114809), "IRxx": (0.0904, 0.000367953786506), "IRyy": (0.1524, 0.00113908424669),
    "c": (0.0686, 0.00169464113488), "g": (9.81, 0.01), "lam": (0.399680398707, 0.00349065850399),
    "mB": (9.9, 0.02), "mF": (2.0, 0.02), "mH": (3.2, 0.02), "mR": (3.1, 0.02), "rF": (0.344, 0.000122426879301),
    "rR": (0.341, 0.000122426879301), "w": (1.121, 0.002), "xB": (0.274, 0.00309782583552),
    "xH": (0.867, 0.003842300035), "zB": (-0.538, 0.00265022978777), "zH": (-0.748, 0.00263543623177)}


@pytest.fixture()
def browser(tmp_path):
    bike = tmp_path / "browser.yaml"
    bike.write_text("\n".join(f"{k}: {v[0]!r}" for k, v in BROWSER.items()) + "\n")
    std = tmp_path / "browser_std.yaml"
    std.write_text("uncertainty:\n" + "\n".join(f"  {k}: {v[1]!r}" for k, v in BROWSER.items()) + "\n")
    return str(bike), str(std)


def test_linear_matrix_std_equals_uncertainties_package(browser, capsys):
    """`bikemass uncertainty --method linear --format json`: std of M, C1, K0, K2 equal the
    `uncertainties` package's propagation through BicycleParameters' formulas to 1e-6 relative."""
    bike, std = browser
    assert main(["uncertainty", bike, "--std", std, "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    peer = benchmark_par_to_canonical({k: ufloat(*v) for k, v in BROWSER.items()})
    for name, U in zip(("M", "C1", "K0", "K2"), peer):
        ref = unumpy.std_devs(U)
        np.testing.assert_allclose(doc["matrices"][name]["std"], ref, rtol=1e-6, atol=1e-15)
        np.testing.assert_allclose(doc["matrices"][name]["nominal"], unumpy.nominal_values(U), rtol=1e-12)
    assert doc["weave_speed"]["nominal"] == pytest.approx(4.2147, abs=1e-4)
    assert 0.03 < doc["weave_speed"]["std"] < 0.1


def test_montecarlo_agrees_with_linear_for_small_spreads(browser):
    """Seeded; with the Browser's small spreads the outputs are near-linear: MC std within about
    3 times its sampling error (~4.5 % at 500 samples) of the linear std; the MC mean within 3
    standard errors of the nominal value plus 5 % of a std for the second-order bias."""
    bike, _ = browser
    spreads = {k: Spread("normal", v[1]) for k, v in BROWSER.items()}
    model = Model(bike)
    mc = propagate(model, spreads, "montecarlo", samples=500, seed=7, speeds=np.linspace(0, 8, 9))
    for name in ("weave_speed", "capsize_speed"):
        s = mc.speeds[name]
        assert s["std"] == pytest.approx(s["linear_std"], rel=0.14)
        assert abs(s["mean"] - s["nominal"]) < (3 / np.sqrt(500) + 0.05) * s["linear_std"]
        assert s["fraction_without"] == 0
    for m in ("M", "C1", "K2"):
        np.testing.assert_allclose(mc.matrices[m]["std"], mc.matrices[m]["linear_std"], rtol=0.14, atol=1e-12)


def test_linear_eigenvalue_std_equals_differences():
    """Eigenvalue std at 5 m/s (weave pair and capsize, away from any double root) from the
    eigenvector derivatives equals the root-sum-square of central differences."""
    p = catalog.parameters("benchmark")
    spreads = {"c": Spread("normal", 0.002), "lam": Spread("normal", 0.004), "mB": Spread("normal", 0.3)}
    r = propagate(Model("benchmark"), spreads, speeds=np.array([3.0, 5.0, 8.0]))
    from bikemass.stability import canonical_matrices, follow_modes
    speeds = np.concatenate([np.linspace(0, 3, 61), [5.0, 8.0]])
    fd = {}
    for k, s in spreads.items():
        x = getattr(p, k)
        h = 1e-6 * abs(x)
        a = follow_modes(canonical_matrices(p.replace(**{k: x + h})), speeds).eigenvalues[-3:]
        b = follow_modes(canonical_matrices(p.replace(**{k: x - h})), speeds).eigenvalues[-3:]
        fd[k] = (a - b) / (2 * h) * s.std
    rss_re = np.sqrt(sum(d.real ** 2 for d in fd.values()))
    for i, label in enumerate(("weave 1", "weave 2", "capsize", "caster")):
        np.testing.assert_allclose(r.eigen["modes"][label]["std_re"], rss_re[:, i], rtol=1e-5)


def test_geometry_level_input_and_bad_files(tmp_path, capsys):
    """A tube wall of the Jamis as an input: its std reaches the mass matrix; bad spreads: one line."""
    spec = tmp_path / "u.yaml"
    spec.write_text("uncertainty:\n  sections.seat_stay.wall: 0.0001\n")
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
