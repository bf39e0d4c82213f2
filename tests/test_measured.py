"""Benchmark parameters from measurements (BicycleParameters' ``<Name>Measured.txt``) against
BicycleParameters' own computation from the same raw files.

The peer is BicycleParameters 1.5.2's ``calculate_benchmark_from_measured`` (and its ``Bicycle`` with
``forceRawCalc=True``), its standard deviations from the ``uncertainties`` package.  Nominal values
agree to 1e-9 relative (the same formulas, evaluated in another order: measured 3e-13), standard
deviations to 1e-6 relative (both exact first-order propagation: measured 6e-14) with
``lam_std="bicycleparameters"``.  The default ``lam_std="implicit"`` differs from the peer only on
the four bicycles whose steer axis follows from the offsets ``h1..h5``; there it is checked against
a central finite difference of the peer's own nominal computation.

The ``test_contract_*`` tests hold bikemass to itself (a measured bicycle read through every door,
written and read back, propagated by the command as by the library), the numbers themselves being
held to the peer above.
"""

import shutil
import warnings
from itertools import permutations
from pathlib import Path

import numpy as np
import pytest
import yaml

import bicycleparameters as bp
from bicycleparameters.io import load_parameter_text_file
from bicycleparameters.main import calculate_benchmark_from_measured
from uncertainties import ufloat

import bikemass as bm
from bikemass.bicycle.measured import read_measured_data, benchmark_from_measured
from bikemass.cli.main import main
from bikemass.core.errors import InputError

DATA = Path(__file__).parent / "data" / "bicycleparameters" / "measured"
FILES = sorted(DATA.glob("*Measured.txt"))
NAMES = [p.name[:-len("Measured.txt")] for p in FILES]
OFFSETS = ("Balanceassistv1", "Gyro", "Rigid", "Rigidcl")
"""The bicycles whose steer axis tilt follows from the offsets h1..h5 (the others give gamma)."""


def peer(path):
    """BicycleParameters' ``{name: (nominal, std)}`` of a measured-data file."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")             # uncertainties: a std of 0
        par, _ = calculate_benchmark_from_measured(load_parameter_text_file(str(path)))
    return {k: (float(getattr(v, "nominal_value", v)), float(getattr(v, "std_dev", 0.0))) for k, v in par.items()}


def ours(path, lam_std="implicit"):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")             # Browser's IByy breaks the triangle inequality: as measured
        found = benchmark_from_measured(read_measured_data(path), lam_std)
    values = {**found.parameters.to_dict(), **found.extra}
    std = {**found.std, **found.extra_std}
    return {k: (values[k], std[k]) for k in values}


def relative_gaps(mine, theirs):
    """Largest relative difference of the nominal values and of the standard deviations."""
    assert set(theirs) <= set(mine), set(theirs) - set(mine)
    value = max(abs(mine[k][0] - v) / abs(v) for k, (v, _) in theirs.items() if v != 0)
    std = max(abs(mine[k][1] - s) / s for k, (_, s) in theirs.items() if s != 0)
    return value, std


def test_twelve_measured_bicycles_are_shipped_for_the_tests():
    assert len(NAMES) == 12 and "Browser" in NAMES and "Rigid" in NAMES and "Gyro" in NAMES


@pytest.mark.parametrize("path", FILES, ids=NAMES)
def test_benchmark_parameters_equal_bicycleparameters_to_1e_9_with_stds_to_1e_6(path):
    theirs = peer(path)
    assert {"w", "c", "lam", "IHxz", "IBxz"} <= set(theirs)
    value, std = relative_gaps(ours(path, "bicycleparameters"), theirs)
    assert value < 1e-9 and std < 1e-6, (value, std)


@pytest.mark.parametrize("path", [p for p, n in zip(FILES, NAMES) if n not in OFFSETS],
                         ids=[n for n in NAMES if n not in OFFSETS])
def test_default_is_bicycleparameters_where_gamma_is_measured(path):
    value, std = relative_gaps(ours(path), peer(path))
    assert value < 1e-9 and std < 1e-6, (value, std)


def test_bicycleparameters_bicycle_from_raw_data_gives_the_same(tmp_path, capsys):
    """The peer's own route: ``Bicycle(name, pathToData, forceRawCalc=True)`` on a data folder."""
    raw = tmp_path / "bicycles" / "Browser" / "RawData"
    raw.mkdir(parents=True)
    shutil.copy(DATA / "BrowserMeasured.txt", raw)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        bike = bp.Bicycle("Browser", pathToData=str(tmp_path), forceRawCalc=True)
    capsys.readouterr()
    theirs = {k: (float(v.nominal_value), float(v.std_dev)) for k, v in bike.parameters["Benchmark"].items()}
    value, std = relative_gaps(ours(DATA / "BrowserMeasured.txt"), theirs)
    assert value < 1e-9 and std < 1e-6
    # and the dynamics: the peer's eigenvalues of its bicycle from raw data, ours of the measured-data
    # file as a BIKE, at 0..10 m/s (1e-9 1/s: two eigen-solvers on the same matrices)
    speeds = np.linspace(0.0, 10.0, 41)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        peer_eig, _ = bike.eig(speeds)
        mine = bm.eigenvalues(bm.parameters(str(DATA / "BrowserMeasured.txt")), speeds=speeds).eigenvalues
    capsys.readouterr()
    orders = np.array(list(permutations(range(4))))             # the best matching of the four roots
    gap = np.abs(mine[:, orders] - peer_eig[:, None, :]).max(axis=2).min(axis=1).max()
    assert gap < 1e-9


@pytest.mark.parametrize("name", ["Balanceassistv1", pytest.param("Rigid", marks=pytest.mark.slow)])
def test_implicit_lam_std_is_the_finite_difference_of_bicycleparameters_nominal_values(name):
    """Where ``lam`` follows from the offsets, the default propagates through ``lam``'s equation: the
    standard deviations equal those from central differences of the PEER's nominal computation
    (each measurement moved by 1e-6 of its value), to 1e-5 relative (the differences' truncation
    and round-off, measured ~1e-8)."""
    path = DATA / f"{name}Measured.txt"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        raw = load_parameter_text_file(str(path))

        def nominal(changes):
            mp = {k: ufloat(changes.get(k, getattr(v, "nominal_value", v)), 0.0) if hasattr(v, "std_dev")
                  else changes.get(k, v) for k, v in raw.items()}
            par, _ = calculate_benchmark_from_measured(mp)
            return {k: float(getattr(v, "nominal_value", v)) for k, v in par.items()}

        total = None
        for k, v in raw.items():
            s = float(getattr(v, "std_dev", 0.0))
            if s == 0:
                continue
            x = v.nominal_value
            h = 1e-6 * max(abs(x), 1e-3)
            up, down = nominal({k: x + h}), nominal({k: x - h})
            d = {n: ((up[n] - down[n]) / (2 * h) * s) ** 2 for n in up}
            total = d if total is None else {n: total[n] + d[n] for n in d}
    reference = {n: (0.0, float(np.sqrt(t))) for n, t in total.items()}
    mine = ours(path)
    gap = max(abs(mine[n][1] - s) / s for n, (_, s) in reference.items() if s > 0)
    print(name, "finite difference gap", gap)
    assert gap < 1e-5
    bp_way = ours(path, "bicycleparameters")
    # the peer's lam is independent of the offsets: other stds (w, c, the mass centres) differ
    assert max(abs(bp_way[n][1] / mine[n][1] - 1) for n in reference if mine[n][1] > 0) > 0.05


def test_covariance_holds_the_standard_deviations_and_is_positive_semidefinite():
    found = bm.load_measured(DATA / "RigidMeasured.txt")
    C = found.covariance
    assert C.shape == (26, 26) and not C.flags.writeable
    assert np.allclose(np.sqrt(np.diag(C)), [found.std[n] for n in bm.PARAMETER_NAMES], rtol=1e-12, atol=0)
    assert np.linalg.eigvalsh(C).min() > -1e-12 * np.abs(C).max()
    i, j = bm.PARAMETER_NAMES.index("rF"), bm.PARAMETER_NAMES.index("c")
    assert abs(C[i, j]) > 0                                       # the trail shares the wheel radius


def test_contract_yaml_form_reads_as_the_text():
    text = ours(DATA / "BrowserMeasured.txt")
    shipped = bm.load_measured("browser-measured")
    for k, (v, s) in text.items():
        assert getattr(shipped.parameters, k) == v and shipped.std[k] == s


def test_missing_measurement_names_the_key(tmp_path):
    lines = [ln for ln in (DATA / "BrowserMeasured.txt").read_text().splitlines() if not ln.startswith("TtB3")]
    path = tmp_path / "ShortMeasured.txt"
    path.write_text("\n".join(lines))
    with pytest.raises(InputError, match="TtB3"):
        bm.load_measured(path)
    with pytest.raises(InputError, match="lam_std"):
        benchmark_from_measured(read_measured_data(DATA / "BrowserMeasured.txt"), "guess")


# -- a measured bicycle everywhere a bicycle is read -------------------------------------------------

def test_contract_load_bicycle_takes_a_measured_file_and_keeps_its_std():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        bike = bm.load_bicycle(DATA / "PistaMeasured.txt")
        direct = bm.load_measured(DATA / "PistaMeasured.txt")
    assert bike.published == direct.parameters
    assert dict(bike.measured.std) == dict(direct.std)
    assert bm.Scenario(str(DATA / "PistaMeasured.txt")).file_std == {k: v for k, v in direct.std.items() if v > 0}


def test_contract_std_survives_yaml_and_json_and_the_bicycleparameters_text(tmp_path, capsys):
    """``params`` of a measured bicycle writes its standard deviations (YAML/JSON ``uncertainty:``,
    BicycleParameters' ``value+/-std``); read back, they are the same (bit for bit: repr)."""
    source = str(DATA / "FisherMeasured.txt")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        expected = bm.Scenario(source).file_std
        for fmt, name in (("yaml", "p.yaml"), ("json", "p.json"), ("bicycleparameters", "FisherBenchmark.txt")):
            out = tmp_path / name
            assert main(["params", source, "--format", fmt, "-o", str(out), "--quiet"]) == 0
            again = bm.Scenario(str(out))
            assert again.file_std == expected, fmt
            assert again.parameters() == bm.Scenario(source).parameters()
    document = yaml.safe_load((tmp_path / "p.yaml").read_text())
    assert document["uncertainty"]["c"] == expected["c"]


def test_contract_uncertainty_command_propagates_the_measurements(tmp_path):
    """``bikemass uncertainty <Name>Measured.txt`` takes the 40 measurements with a std as its independent
    inputs (the bicycle recomputed from them): the weave speed's linear std equals ``sqrt(g' C g)``
    with ``g`` the exact sensitivities (``bm.sensitivity``) and ``C`` the 26 parameters' covariance
    (1e-6 relative: the measurement directions are central differences, measured 5e-10); Monte Carlo
    agrees within sampling error. Through ``params``' YAML (the 26 standard deviations, no
    covariance) it equals the propagation of the 26 as independent inputs (1e-12)."""
    source = str(DATA / "BrowserMeasured.txt")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert main(["params", source, "-o", str(tmp_path / "b.yaml"), "--quiet"]) == 0
        for bike, out in ((source, "direct.json"), (str(tmp_path / "b.yaml"), "yaml.json")):
            assert main(["uncertainty", bike, "--format", "json", "-o", str(tmp_path / out), "--quiet"]) == 0
        mc = tmp_path / "mc.json"
        assert main(["uncertainty", source, "--method", "montecarlo", "--samples", "300", "--seed", "3",
                     "--format", "json", "-o", str(mc), "--quiet"]) == 0
        scenario = bm.Scenario(source)
        sensitivity = bm.sensitivity(scenario)
        independent = bm.uncertainty(scenario, scenario.file_std)
        covariance = bm.load_measured(source).covariance
    direct, again = (yaml.safe_load((tmp_path / n).read_text()) for n in ("direct.json", "yaml.json"))
    assert len(direct["inputs"]) == 40 and all(k.startswith("measured.") for k in direct["inputs"])
    g = np.array([sensitivity.d_weave_speed[n] for n in bm.PARAMETER_NAMES])
    w = direct["weave_speed"]["std"]
    assert abs(w / np.sqrt(g @ covariance @ g) - 1) < 1e-6
    assert sorted(again["inputs"]) == sorted(scenario.file_std)
    assert abs(again["weave_speed"]["std"] / independent.speeds["weave_speed"].std - 1) < 1e-12
    assert again["weave_speed"]["std"] > 1.2 * w           # the shared measurements make it smaller
    sampled = yaml.safe_load(mc.read_text())["weave_speed"]
    # 300 draws: the sample std is within ~4/sqrt(2*300) = 16 % of the true std
    assert abs(sampled["std"] / w - 1) < 0.2


def test_measured_inputs_are_refused_on_other_bicycles_and_named_when_unknown():
    with pytest.raises(InputError, match="measured.TtB1"):
        bm.Scenario("benchmark").build({"measured.TtB1": 2.0})
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario = bm.Scenario(str(DATA / "BrowserMeasured.txt"))
        with pytest.raises(InputError, match="TtX9"):
            scenario.build({"measured.TtX9": 2.0})
        with pytest.raises(InputError, match="geometry.wheelbase"):
            scenario.build({"measured.TtB1": 2.1, "geometry.wheelbase": 1.0})
        moved = scenario.build({"measured.mB": 10.86}).parameters
    assert moved.mB == 10.86 and moved.IByy != scenario.parameters().IByy     # the pendulum formula holds mB


def test_an_unknown_measurement_as_a_spread_is_named():
    """``measured.<name>`` in the spreads of ``uncertainty`` (its own code path: the nominal value is
    read before any build) names the key and the file's measurements (was an internal KeyError)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario = bm.Scenario(str(DATA / "BrowserMeasured.txt"))
        with pytest.raises(InputError, match=r"measured\.nosuch: a measurement of this file \('lF, "):
            bm.uncertainty(scenario, {"measured.TtB1": 1e-3, "measured.nosuch": 1.0})


@pytest.mark.parametrize("name, bad, key", [("nF", "0", "nF"), ("TtP1", "-1.2", "TtP1"), ("d", "0.01", "lam"),
                                            ("l", "0.001", "l"), ("mB", "abc", "mB"), ("aB1", "nan", "aB1"),
                                            ("TtB2", "-2.0", "TtB2")])
def test_measurements_that_give_no_bicycle_are_refused_naming_the_key(tmp_path, name, bad, key):
    """Nonsense measurements: one InputError naming the key, no numpy warning, no traceback."""
    text = "\n".join(f"{name} = {bad}" if ln.split("=")[0].strip() == name else ln
                     for ln in (DATA / "RigidMeasured.txt").read_text().splitlines())
    path = tmp_path / "BadMeasured.txt"
    path.write_text(text)
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(InputError, match=rf"\b{key}\b"):
            bm.load_measured(path)
    assert main(["params", str(path)]) == 2


@pytest.mark.parametrize("turn", [0.0, 180.0])
def test_three_orientations_about_two_axes_are_refused_naming_the_repeat(tmp_path, turn):
    """Three pendulum orientations of which two share an axis (the same angle, or 180 deg apart) give
    no inertia tensor (three unknowns, two equations): one InputError naming the repeat; a fourth
    distinct axis (RigidMeasured: five orientations) would make it solvable again."""
    lines = (DATA / "BrowserMeasured.txt").read_text().splitlines()
    alpha = {ln.split("=")[0].strip(): ln.split("=")[1].split("+/-")[0] for ln in lines if ln.startswith("alphaB")}
    assert len(alpha) == 3
    text = "\n".join(f"alphaB2 = {float(alpha['alphaB1']) + turn}" if ln.startswith("alphaB2") else ln
                     for ln in lines)
    path = tmp_path / "BadMeasured.txt"
    path.write_text(text)
    with pytest.raises(InputError, match=r"alphaB2: .*three different axes"):
        bm.load_measured(path)
    assert main(["params", str(path)]) == 2


def test_yaml_form_refuses_a_value_that_is_not_a_number(tmp_path):
    document = yaml.safe_load(Path(bm.load_measured("browser-measured").source).read_text())
    document["TcB1"] = {"value": 1.7}
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(document))
    with pytest.raises(InputError, match="TcB1"):
        bm.load_bicycle(path)


def test_contract_uncertainty_defaults_to_the_bicycles_own_spreads():
    """Contract test: ``bm.uncertainty(BIKE)`` without spreads takes the measurements of a bicycle
    computed from them, as the command does; a bicycle without standard deviations is refused."""
    source = str(DATA / "YellowMeasured.txt")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        scenario = bm.Scenario(source)
        default = bm.uncertainty(source)
        given = bm.uncertainty(scenario, scenario.measurement_std)
    assert default.inputs == given.inputs and default.speeds == given.speeds
    with pytest.raises(InputError, match="spreads"):
        bm.uncertainty("benchmark")


def test_contract_a_yaml_parameter_file_carries_std_as_value_plus_minus_or_a_block(tmp_path):
    """BicycleParameters' ``value+/-std`` in a YAML parameter file, or an ``uncertainty:`` block, are
    the file's standard deviations (the text file's the same); both for one name is refused."""
    text = bm.load_parameter_text(Path(bp.__file__).parent / "app-data" / "bicycles" / "Browser" / "Parameters"
                                  / "BrowserBenchmark.txt")
    values = text.parameters.to_dict()
    plus_minus = {k: f"{v!r}+/-{text.std[k]!r}" if text.std[k] else v for k, v in values.items()}
    (tmp_path / "pm.yaml").write_text(yaml.safe_dump(plus_minus))
    (tmp_path / "block.yaml").write_text(yaml.safe_dump({**values, "uncertainty": dict(text.std)}))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for name in ("pm.yaml", "block.yaml"):
            bike = bm.load_bicycle(tmp_path / name)
            assert bike.published == text.parameters and dict(bike.measured.std) == dict(text.std), name
        (tmp_path / "both.yaml").write_text(yaml.safe_dump({**plus_minus, "uncertainty": {"c": 0.001}}))
        with pytest.raises(InputError, match="uncertainty.c"):
            bm.load_bicycle(tmp_path / "both.yaml")
