"""Every model's parameters out and back in: ``params --model M`` (with ``--stiffness``, ``--tyres``, the
rider) writes a file that every command reads back as the same model.

A round trip compares the code with itself, so these are contract tests: the reference is the model
built from the bicycle and rider directly (``eig BIKE --rider R --model M --stiffness S``), the file's
model must give its eigenvalues (1e-9 relative: the file holds every float with 17 digits, and the
rider-lean set's conversion to MooreRiderLean2012 and back rounds in the last digits, measured 3e-15).
"""

import json

import numpy as np
import pytest
import yaml

from bikemass.cli.main import main


def eigenvalues(capsys, *argv):
    assert main(["eig", *argv, "--speeds", "0:10:2.5", "--format", "json"]) == 0, capsys.readouterr().err
    d = json.loads(capsys.readouterr().out)
    return [m["label"] for m in d["modes"]], np.array([m["eigenvalues"] for m in d["modes"]])


def round_trip(capsys, tmp_path, model, *options, fmt="yaml"):
    out = tmp_path / f"model.{fmt}"
    scenario = ["jamis", "--rider", "relaxed", "--model", model, *options]
    assert main(["params", *scenario, "--format", fmt, "-o", str(out)]) == 0, capsys.readouterr().err
    capsys.readouterr()
    labels, direct = eigenvalues(capsys, *scenario)
    labels_back, back = eigenvalues(capsys, str(out), "--model", model)
    assert labels_back == labels
    assert back == pytest.approx(direct, rel=1e-9, abs=1e-9 * np.abs(direct).max())
    return out


def test_contract_params_flexible_steel_reads_back_as_the_same_model(capsys, tmp_path):
    """The issue's must-show: ``params jamis --rider relaxed --model flexible --stiffness steel --format
    yaml -o F`` read back by ``eig F --model flexible`` gives the same eigenvalues (1e-9)."""
    out = round_trip(capsys, tmp_path, "flexible", "--stiffness", "steel")
    doc = yaml.safe_load(out.read_text())
    assert doc["model"] == "flexible" and doc["flexible"]["source"] == "steel"
    assert doc["flexible"]["frame"]["stiffness"] > 0 and doc["units"]["stiffness"] == "N m/rad"


@pytest.mark.parametrize("model, options", [
    ("whipple", ("--stiffness", "steel")),
    ("tyre", ()),
    ("tyre+flexible", ("--stiffness", "titanium")),
    ("rider-lean", ()),
    ("rider-lean+tyre+flexible", ("--stiffness", "steel")),
])
def test_contract_every_member_reads_back(capsys, tmp_path, model, options):
    round_trip(capsys, tmp_path, model, *options)


def test_contract_json_reads_back_too(capsys, tmp_path):
    round_trip(capsys, tmp_path, "tyre+flexible", "--stiffness", "steel", fmt="json")


def test_given_tyres_are_written_and_read_back(capsys, tmp_path):
    tyres = tmp_path / "tyres.yaml"
    tyres.write_text("front: {cornering_coefficient: 0.25 1/deg, camber_coefficient: 0.012 1/deg, "
                     "relaxation_length: 0.12 m}\nrear: {cornering_coefficient: 0.18 1/deg, "
                     "camber_coefficient: 0.009 1/deg, relaxation_length: 0.2 m}\n")
    out = round_trip(capsys, tmp_path, "tyre", "--tyres", str(tyres))
    front = yaml.safe_load(out.read_text())["tyre"]["front"]
    assert float(front["cornering_coefficient"].split()[0]) == pytest.approx(0.25 * 180 / np.pi, rel=1e-15)


def test_a_measured_stiffness_edited_into_the_file_is_used(capsys, tmp_path):
    """A limit, not a contract: the file's frame stiffness edited to a huge measured value (given in N
    m/deg) gives the model with the frame twist held rigid (its other modes to 1e-5 relative)."""
    out = tmp_path / "f.yaml"
    assert main(["params", "jamis", "--rider", "relaxed", "--model", "flexible", "--stiffness", "steel",
                 "--format", "yaml", "-o", str(out)]) == 0
    doc = yaml.safe_load(out.read_text())
    stiff, rigid = tmp_path / "stiff.yaml", tmp_path / "rigid.yaml"
    stiff.write_text(yaml.safe_dump({**doc, "flexible": {**doc["flexible"], "frame": {
        **doc["flexible"]["frame"], "stiffness": "1e9 N m/deg"}}}))
    rigid.write_text(yaml.safe_dump({**doc, "flexible": {**doc["flexible"], "frame": "rigid"}}))
    capsys.readouterr()
    labels_a, a = eigenvalues(capsys, str(stiff), "--model", "flexible")
    labels_b, b = eigenvalues(capsys, str(rigid), "--model", "flexible")
    assert len(labels_a) == len(labels_b) + 2                   # the frame twist's pair is gone
    ours = (a[..., 0] + 1j * a[..., 1]).T                       # (speeds, roots)
    held = (b[..., 0] + 1j * b[..., 1]).T
    for speed, roots in enumerate(held):
        for root in roots:
            assert np.min(np.abs(ours[speed] - root)) <= 1e-5 * max(1.0, abs(root))
