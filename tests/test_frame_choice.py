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
