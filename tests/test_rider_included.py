"""No double rider: a bicycle or parameter file says whether its rear body holds a rider,
and adding one to a bicycle that has one is refused with one line (exit 2)."""

import json

import pytest
import yaml

from bikemass.scenario import catalog
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.cli.main import main
from bikemass.core.errors import InputError


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize("command", [["stability", "benchmark", "--rider", "relaxed"],
                                     ["params", "benchmark", "--rider", "relaxed-thesis"],
                                     ["eig", "benchmark", "--rider", "no-hands"]])
def test_benchmark_already_has_its_rider(capsys, command):
    code, out, err = run(capsys, *command)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "frames/benchmark.yaml: rider_included: no rider added" in err


def test_benchmark_without_a_rider_is_meijaard_exactly(capsys):
    code, out, _ = run(capsys, "params", "benchmark", "--format", "json")
    data = json.loads(out)
    assert code == 0 and data.pop("rider_included") is True and data.pop("units")["IBxx"] == "kg m^2"
    assert data == scenario_parameters("benchmark").to_dict()


def test_an_exported_set_with_a_rider_says_so_and_refuses_another(tmp_path, capsys):
    target = tmp_path / "jamis_relaxed.yaml"
    assert run(capsys, "params", "jamis", "--rider", "relaxed-thesis", "--method", "exact", "-o", target)[0] == 0
    assert yaml.safe_load(target.read_text())["rider_included"] is True
    code, _, err = run(capsys, "params", target, "--rider", "relaxed")
    assert code == 2 and "rider_included" in err
    bare = tmp_path / "jamis.yaml"
    assert run(capsys, "params", "jamis", "--method", "exact", "-o", bare)[0] == 0
    assert "rider_included" not in yaml.safe_load(bare.read_text())
    with_rider = scenario_parameters(str(bare), "relaxed-thesis", method="exact")
    assert with_rider.mB > 80


def test_a_bicycle_yaml_may_declare_its_rider(tmp_path):
    text = catalog.load_bicycle("jamis-thesis").source
    bike = tmp_path / "bike.yaml"
    bike.write_text(open(text).read() + "\nrider_included: true\n")
    with pytest.raises(InputError, match="rider_included"):
        scenario_parameters(str(bike), "relaxed")
    bike.write_text(open(text).read() + "\nrider_included: maybe\n")
    with pytest.raises(InputError, match="true or false"):
        catalog.load_bicycle(str(bike))
