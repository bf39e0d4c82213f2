"""The frame a scenario builds when a parameter file carries its own frame stiffness.

A file written by ``bikemass params --stiffness steel`` (or ``--model flexible --stiffness steel``)
carries the frame's stiffness (``frame_stiffness:``, or the compliances). Without a stiffness choice
the scenario takes the file's own. An explicit ``infinite`` is a rigid frame. Before, the file's block
was applied under ``--stiffness infinite`` too, with the title saying "rigid frame".

These are contract tests: each route is compared with the other route the file stands for. The file
read back is compared with the chart it was written from, with the same choice of stiffness.
"""

import json

import pytest

import bikemass as bm
from bikemass.cli.main import main


def stability_json(capsys, *argv):
    assert main(["stability", *argv, "--speeds", "0:10:0.1", "--format", "json"]) == 0
    return json.loads(capsys.readouterr().out)


@pytest.fixture(scope="module")
def steel_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("frame") / "steel.yaml"
    assert main(["params", "jamis", "--rider", "relaxed", "--stiffness", "steel", "--format", "yaml",
                 "-o", str(path)]) == 0
    return str(path)


def test_the_files_own_stiffness_without_a_choice_and_rigid_with_infinite(steel_file, capsys):
    own = stability_json(capsys, steel_file)
    steel = stability_json(capsys, "jamis", "--rider", "relaxed", "--stiffness", "steel")
    rigid = stability_json(capsys, steel_file, "--stiffness", "infinite")
    chart_rigid = stability_json(capsys, "jamis", "--rider", "relaxed")
    assert own["weave_speeds"] == pytest.approx(steel["weave_speeds"], abs=1e-9)
    assert rigid["weave_speeds"] == pytest.approx(chart_rigid["weave_speeds"], abs=1e-9)
    assert rigid["weave_speeds"][0] < own["weave_speeds"][0] - 0.1        # the two really differ
    assert own["frame"] == "the frame stiffness the parameter file carries"
    assert rigid["frame"] == "rigid frame"


def test_the_library_takes_the_same_choices(steel_file):
    assert bm.Scenario(steel_file).build().stiffness is not None
    assert bm.Scenario(steel_file, stiffness="infinite").build().stiffness is None
    assert bm.Scenario(steel_file).frame_label() == "the frame stiffness the parameter file carries"
    assert bm.Scenario(steel_file, stiffness="infinite").frame_label() == "rigid frame"


def test_a_flexible_models_file_and_infinite(tmp_path, capsys):
    path = str(tmp_path / "flexible.yaml")
    assert main(["params", "jamis", "--rider", "relaxed", "--model", "flexible", "--stiffness", "steel",
                 "--format", "yaml", "-o", path]) == 0
    capsys.readouterr()
    own = stability_json(capsys, path, "--model", "flexible")
    steel = stability_json(capsys, "jamis", "--rider", "relaxed", "--model", "flexible", "--stiffness", "steel")
    rigid = stability_json(capsys, path, "--model", "flexible", "--stiffness", "infinite")
    chart_rigid = stability_json(capsys, "jamis", "--rider", "relaxed", "--model", "flexible")
    assert own["weave_speeds"] == pytest.approx(steel["weave_speeds"], abs=1e-9)
    assert rigid["weave_speeds"] == pytest.approx(chart_rigid["weave_speeds"], abs=1e-9)
    assert rigid["frame"] == "rigid frame"


@pytest.mark.parametrize("model", ["tyre", "rider-lean+tyre", "flexible"])
def test_a_parameter_file_selects_the_model_it_was_written_for(tmp_path, capsys, model):
    """``params --model M`` writes ``model: M`` and the members' blocks: read back without --model the file
    is that model (before, the Whipple model of its 26 names, without a word), with --model whipple the
    Whipple model."""
    path = str(tmp_path / "written.yaml")
    stiffness = ["--stiffness", "steel"] if model == "flexible" else []
    assert main(["params", "jamis", "--rider", "relaxed", "--model", model, *stiffness, "--format", "yaml",
                 "-o", path]) == 0
    capsys.readouterr()
    own = stability_json(capsys, path)
    direct = stability_json(capsys, "jamis", "--rider", "relaxed", "--model", model, *stiffness)
    assert own["weave_speeds"] == pytest.approx(direct["weave_speeds"], abs=1e-9)
    assert bm.Scenario(path).model.name == model
    if model != "rider-lean+tyre":          # (the rider-lean set holds its rider: no Whipple reading)
        whipple = stability_json(capsys, path, "--model", "whipple")
        assert whipple["weave_speeds"] != pytest.approx(own["weave_speeds"], abs=1e-6)


@pytest.mark.parametrize("argv", [
    ["--model", "tyre", "--format", "table"],
    ["--model", "rider-lean", "--format", "bicycleparameters"],
    ["--stiffness", "steel", "--format", "csv"],
    ["--model", "tyre", "--compare", "jamis"],
])
def test_params_in_a_form_of_the_26_names_says_what_it_leaves_out(capsys, argv):
    assert main(["params", "jamis", "--rider", "relaxed", *argv]) == 0
    err = capsys.readouterr().err
    assert "26 benchmark parameters" in err and "leaves out" in err


def test_params_of_the_whipple_bicycle_in_a_table_says_nothing(capsys):
    assert main(["params", "jamis", "--rider", "relaxed", "--format", "table"]) == 0
    assert "warning" not in capsys.readouterr().err


def _params_file(tmp_path, name, *argv):
    path = tmp_path / name
    assert main(["params", "jamis", "--rider", "relaxed", *argv, "-o", str(path)]) == 0
    return path


def test_a_misspelt_model_or_a_bad_member_block_of_a_parameter_file_is_named(tmp_path, capsys):
    """A file written by ``params --model tyre+flexible`` with its ``model:`` misspelt was analysed as the rigid
    Whipple bicycle without a word (its blocks dropped), and a bad block of a ``MooreRiderLean2012`` file was
    refused as "a Whipple parameter set ... for the model whipple": each is one line naming the file's key."""
    import yaml
    written = _params_file(tmp_path, "f.yaml", "--model", "tyre+flexible", "--stiffness", "steel", "--format", "yaml")
    capsys.readouterr()
    doc = yaml.safe_load(written.read_text())
    cases = {"model": ({"model": "tyre+flexibel"}, "model: unknown model 'flexibel'"),
             "stiffness": ({"flexible": {**doc["flexible"], "frame": {**doc["flexible"]["frame"], "stiffness": -100}}},
                           "flexible.frame.stiffness: a positive number"),
             # an empty block was both parts rigid and no steering damping, titled as the file's frame
             "empty": ({"flexible": {}}, "flexible: frame: and fork:"),
             # a unit edited in the units block changed no value without a word
             "unit": ({"units": {**doc["units"], "stiffness": "N m/deg"}}, "units.stiffness: N m/rad")}
    for name, (edit, words) in cases.items():
        bad = tmp_path / f"bad_{name}.yaml"
        bad.write_text(yaml.safe_dump({**doc, **edit}, sort_keys=False))
        assert main(["stability", str(bad)]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and f"bad_{name}.yaml: {words}" in err[0]
    lean = _params_file(tmp_path, "lean.yaml", "--model", "rider-lean+tyre", "--format", "yaml")
    capsys.readouterr()
    doc = yaml.safe_load(lean.read_text())
    doc["tyre"]["front"]["relaxation_length"] = -0.1
    bad = tmp_path / "bad_lean.yaml"
    bad.write_text(yaml.safe_dump(doc, sort_keys=False))
    assert main(["stability", str(bad)]) == 2
    assert "bad_lean.yaml: tyre.front.relaxation_length: a positive number" in capsys.readouterr().err


def test_what_params_writes_reads_back_without_a_warning(tmp_path, capsys):
    """The leaning rider's set as JSON with the warnings params gave (the Cargo's front load) read back
    as the same model (it was refused: "warnings: no such key"); an arms block with ``forearms:
    handlebars`` over the file's own rider reads back under ``--strict`` (it warned of no rider seated)."""
    path = tmp_path / "cargo.json"
    assert main(["params", "cargo", "--rider", "relaxed", "--model", "rider-lean", "--format", "json",
                 "-o", str(path)]) == 0
    assert json.loads(path.read_text())["warnings"]
    capsys.readouterr()
    direct = stability_json(capsys, "cargo", "--rider", "relaxed", "--model", "rider-lean")
    assert stability_json(capsys, str(path))["weave_speeds"] == pytest.approx(direct["weave_speeds"], abs=1e-9)
    arms = tmp_path / "arms.yaml"
    arms.write_text("stiffness: 0 N m/rad\ndamping: 0.5 N m s/rad\nforearms: handlebars\n")
    held = _params_file(tmp_path, "held.yaml", "--model", "tyre+arms", "--arms", str(arms), "--format", "yaml")
    capsys.readouterr()
    direct = stability_json(capsys, "jamis", "--rider", "relaxed", "--model", "tyre+arms", "--arms", str(arms))
    assert stability_json(capsys, str(held), "--strict")["weave_speeds"] == pytest.approx(direct["weave_speeds"],
                                                                                            abs=1e-9)


def test_a_set_that_holds_its_rider_is_not_titled_no_rider(tmp_path, capsys):
    """A parameter file with ``rider_included: true`` (the benchmark; what ``params`` writes with a rider) was
    titled "no rider" without ``--rider``; a bicycle YAML without a rider still is."""
    written = _params_file(tmp_path, "with.yaml", "--format", "yaml")
    capsys.readouterr()
    for bike, words in ((str(written), "rider in the parameter set"), ("benchmark", "rider in the parameter set"),
                        ("jamis", "no rider")):
        assert main(["stability", bike, "--speeds", "0:5:0.5"]) == 0
        assert capsys.readouterr().out.splitlines()[0].split(", ")[1] == words
