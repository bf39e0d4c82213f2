"""Published parameter sets read as their authors wrote them (tests/data/bicycleparameters/README.md):
BicycleParameters' parameter-set YAML files (flat and ``parameterization:``/``values:``, the
benchmark, principal and rider-lean parameterizations), the two-mass-skate bicycle with point
wheels, and frame inertias that break the triangle inequality, warned about alike in every format.

References are independent of bikemass: the files' own values read with PyYAML, and
BicycleParameters' own conversion (``Moore2019ParameterSet.to_parameterization``) and model
(``Meijaard2007Model.calc_eigen``)."""

import json
import warnings
from pathlib import Path

import numpy as np
import pytest
import yaml

import bicycleparameters as bp
import bikemass as bm
from bikemass.cli.main import main
from bikemass.core.errors import BikemassWarning, InputError
from bikemass.bicycle.parameter_sets import RIDER_LEAN_NAMES

DATA = Path(__file__).parent / "data" / "bicycleparameters"
YAML_SETS = sorted(p.name for p in DATA.glob("*.yml"))
WHIPPLE_SETS = [n for n in YAML_SETS if "RiderLean" not in n]
BP_TEXT = Path(bp.__file__).parent / "app-data" / "bicycles"


def _values(name):
    """The file's values as PyYAML reads them (the ``values:`` mapping or the top level)."""
    document = yaml.safe_load((DATA / name).read_text())
    return {k: float(v) for k, v in document.get("values", document).items()}


def _quiet_load(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BikemassWarning)
        return bm.load_parameter_set(path)


def test_every_shipped_set_is_here():
    assert len(YAML_SETS) == 12 and (DATA / "TmsBenchmark.txt").is_file()


@pytest.mark.parametrize("name", WHIPPLE_SETS)
def test_every_whipple_set_is_analysed_from_the_command_line(name, capsys):
    assert main(["stability", str(DATA / name), "--format", "json"]) == 0
    reply = json.loads(capsys.readouterr().out)
    assert "weave_speeds" in reply and "capsize_speeds" in reply


@pytest.mark.parametrize("name", [n for n in WHIPPLE_SETS if "principal" not in n and "Moore2019" not in n])
def test_benchmark_sets_keep_the_files_values_exactly(name):
    read = _quiet_load(DATA / name)
    values = _values(name)
    assert read.parameterization == "benchmark"
    assert read.parameters.to_dict() == {k: values[k] for k in bm.PARAMETER_NAMES}


@pytest.mark.parametrize("name", YAML_SETS)
def test_the_speed_v_is_kept_as_the_files_speed(name):
    assert _quiet_load(DATA / name).speed == _values(name)["v"]


def test_a_bicycle_from_a_set_carries_its_speed():
    assert bm.load_bicycle(str(DATA / "benchmark-benchmark.yml")).speed == 5.0
    assert bm.load_bicycle("benchmark").speed is None


@pytest.mark.parametrize("name", ["principal-browserjason.yml", "principal-extendedoptf.yml",
                                  "to_yaml-Moore2019-browserjason.yml"])
def test_principal_sets_convert_as_bicycleparameters_converts_them(name):
    from bicycleparameters.parameter_sets import Moore2019ParameterSet
    expected = Moore2019ParameterSet(_values(name)).to_parameterization("Meijaard2007").parameters
    read = _quiet_load(DATA / name)
    assert read.parameterization == "principal" and read.rider_included
    for key, value in read.parameters.to_dict().items():
        assert value == pytest.approx(expected[key], rel=1e-10, abs=1e-12), key


def test_a_principal_value_that_contradicts_the_others_is_warned_about_and_not_used(tmp_path):
    text = (DATA / "principal-browserjason.yml").read_text().replace("xF: 1.1210", "xF: 1.3")
    f = tmp_path / "set.yml"
    f.write_text(text)
    with pytest.warns(bm.ParameterFileWarning, match=r"values.xF = 1.3 but the other principal parameters imply 1.121"):
        read = bm.load_parameter_set(f)
    assert read.parameters.w == 1.121


def test_rider_lean_sets_keep_their_named_values_as_read():
    from bicycleparameters.parameter_dicts import mooreriderlean2012_browser_jason as expected
    read = bm.load_parameter_set(DATA / "to_yaml-MooreRiderLean2012-browserjason.yml")
    assert read.parameterization == "MooreRiderLean2012" and isinstance(read.parameters, bm.RiderLeanParameters)
    assert dict(read.values) == {k: expected[k] for k in RIDER_LEAN_NAMES}
    assert read.speed == expected["v"]


def test_a_rider_lean_set_read_feeds_the_model_as_bicycleparameters_own_model():
    """The file read is the rider-lean model's one parameter class (``bm.RiderLeanParameters``); its
    model has the non-zero eigenvalues of BicycleParameters' MooreRiderLean2012Model of the same file
    (Moore's own derivation) at 1..10 m/s, to 1e-9 relative."""
    from bicycleparameters.models import MooreRiderLean2012Model
    from bicycleparameters.parameter_sets import MooreRiderLean2012ParameterSet
    from bikemass.models.family import build
    path = DATA / "to_yaml-MooreRiderLean2012-browserjason.yml"
    model = build("rider-lean", bm.load_parameter_set(path).parameters)
    peer = MooreRiderLean2012Model(MooreRiderLean2012ParameterSet._from_yaml(str(path)))
    for v in range(1, 11):
        A, _ = peer.form_state_space_matrices(v=float(v))
        theirs = np.linalg.eigvals(A)
        theirs = theirs[np.abs(theirs) > 1e-9 * np.max(np.abs(theirs))]       # 6 of 12 are structurally zero
        ours = np.linalg.eigvals(model.dynamic_matrix(float(v)))
        assert len(ours) == len(theirs) == 6
        for z in theirs:
            assert np.min(np.abs(ours - z)) <= 1e-9 * abs(z), (v, z, ours)


@pytest.mark.parametrize("name, value, message", [
    ("mg", 0, "values.mg: a positive number"), ("rf", -0.3, "values.rf: a positive number"),
    ("rf", 2.0, "values: d1, d2, d3, rf, rr of a bicycle whose front wheel reaches the ground")])
def test_a_rider_lean_set_the_model_cannot_take_is_refused_when_read(tmp_path, name, value, message):
    document = yaml.safe_load((DATA / "to_yaml-MooreRiderLean2012-browserjason.yml").read_text())
    document["values"][name] = value
    f = tmp_path / "set.yml"
    f.write_text(yaml.safe_dump(document))
    with pytest.raises(InputError, match=message):
        bm.load_parameter_set(f)


def test_a_rider_lean_set_is_not_taken_for_a_whipple_bicycle():
    with pytest.raises(InputError, match="parameterization: a Whipple parameter set .* MooreRiderLean2012"):
        bm.load_bicycle(str(DATA / "to_yaml-MooreRiderLean2012-browserjason.yml"))


@pytest.mark.parametrize("text, message", [
    ("parameterization: Whipple1899\nvalues: {w: 1}\n", "parameterization: one of benchmark, Meijaard2007"),
    ("parameterization: principal\nvalues: {w: 1}\n", "values.c: a required key that is missing"),
    ("parameterization: benchmark\nvalues: {w: 1}\nspeed: 3\n", "speed: no such key"),
    ("w: 1.02\nv: fast\n", "v: a speed"),
    ("w: 1.02\nv: -1\n", "v: a number >= 0"),
])
def test_bad_sets_name_the_key(tmp_path, text, message):
    f = tmp_path / "set.yml"
    f.write_text(text)
    with pytest.raises(InputError, match=message):
        bm.load_parameter_set(f)


# --------------------------------------------------------------- the two-mass-skate bicycle
TMS = DATA / "TmsBenchmark.txt"


def _bp_eigenvalues(values, speeds):
    from bicycleparameters.models import Meijaard2007Model
    from bicycleparameters.parameter_sets import Meijaard2007ParameterSet
    model = Meijaard2007Model(Meijaard2007ParameterSet({**values, "v": 1.0}, True))
    return model.calc_eigen(v=speeds)[0]


def test_point_wheels_are_the_limit_without_spin_momentum():
    """With no wheel mass and no spin inertia the wheel radii drop out of the Whipple matrices, so
    BicycleParameters (which divides by them) is asked at two positive radii; bikemass at zero
    gives the same eigenvalues to 1e-9 1/s at every speed, and BicycleParameters' two agree."""
    params = bm.load_bicycle(str(TMS)).published
    assert (params.rR, params.rF, params.mR, params.mF) == (0.0, 0.0, 0.0, 0.0)
    speeds = np.linspace(0.0, 10.0, 201)
    ours = np.sort_complex(bm.eigenvalues(params, speeds=speeds).eigenvalues)
    for radius in (0.3, 1.0):
        theirs = np.sort_complex(_bp_eigenvalues({**params.to_dict(), "rR": radius, "rF": radius}, speeds))
        assert np.max(np.abs(ours - theirs)) < 1e-9


def test_the_two_mass_skate_is_self_stable():
    """Kooijman et al. (2011): with neither trail (c = 0) nor gyroscopic effects (point wheels) the
    TMS bicycle is self-stable: one weave speed above which every eigenvalue has Re < 0, no capsize
    speed, stable up to the end of the grid."""
    result = bm.stability(bm.load_bicycle(str(TMS)).published)
    assert len(result.weave_speeds) == 1 and not result.capsize_speeds
    ((start, stop),) = result.ranges["strict"]["exact"]
    assert start == pytest.approx(result.weave_speeds[0], abs=1e-9) and stop == pytest.approx(30.0)
    speeds = np.array([start - 0.01, start + 0.01])
    values = bm.eigenvalues(bm.load_bicycle(str(TMS)).published, speeds=speeds).eigenvalues
    assert values[0].real.max() > 0 > values[1].real.max()


def test_the_two_mass_skate_from_every_format(tmp_path, capsys):
    assert main(["params", str(TMS), "--format", "yaml", "-o", str(tmp_path / "tms.yaml")]) == 0
    assert main(["stability", str(tmp_path / "tms.yaml"), "--format", "json"]) == 0
    from_yaml = json.loads(capsys.readouterr().out)
    assert main(["stability", str(TMS), "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["weave_speeds"] == from_yaml["weave_speeds"]


# --------------------------------------------------------------- the triangle inequality
BROWSER_TXT = BP_TEXT / "Browser" / "Parameters" / "BrowserBenchmark.txt"


def test_the_browsers_measured_IByy_warns_alike_in_every_format(tmp_path, capsys):
    as_yaml = tmp_path / "browser.yaml"
    as_json = tmp_path / "browser.json"
    assert main(["params", str(BROWSER_TXT), "-o", str(as_yaml)]) == 0
    assert main(["params", str(BROWSER_TXT), "--format", "json", "-o", str(as_json)]) == 0
    capsys.readouterr()
    for path in (BROWSER_TXT, as_yaml, as_json, DATA / "benchmark-browser.yml"):
        assert main(["stability", str(path), "--format", "json"]) == 0
        out, err = capsys.readouterr()
        lines = [line for line in json.loads(out)["warnings"] if "triangle" in line]
        assert len(lines) == 1 and ": IByy: the B inertia breaks the triangle inequality" in lines[0], path
        assert err.count("IByy: the B inertia breaks the triangle inequality") == 1
