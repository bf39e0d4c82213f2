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


# ---------------------------------------------------------------- measured stiffness in place of the beam model's
def _compliance(stiffness, direction=(0.0, 1.0)):
    from bikemass.core.config import Node
    from bikemass.models.compliance import compliance_from_node
    block = {"name": "fork", "point": [0.9, 0.0], "direction": list(direction), "stiffness": stiffness,
             "modal_momentum": 0.0, "modal_moment": [0.0, 0.0], "modal_mass": 0.0}
    return compliance_from_node(Node(block, "test.yaml", "flexible.fork"))


def test_a_fork_lateral_stiffness_at_the_axle():
    """A lateral stiffness K (N/mm) at a point a distance d from the bending axis is a torsional stiffness
    K d^2 about it: the axis along z through x = 0.9 m, the axle at x = 1.0 m (d = 0.1 m, a closed
    form), 120 N/mm -> 120e3 * 0.01 = 1200 N m/rad (1e-12 relative)."""
    c = _compliance({"lateral": "120 N/mm", "at": [1.0, -0.35]})
    assert c.stiffness == pytest.approx(1200.0, rel=1e-12)
    tilted = _compliance({"lateral": "120 N/mm", "at": [0.9 + 0.8, -0.6]}, direction=(0.6, 0.8))
    assert tilted.stiffness == pytest.approx(120e3 * 1.0, rel=1e-12)       # (0.8, -0.6) is normal to the axis, d = 1 m


def test_a_steering_head_torsional_stiffness_as_the_test_reports_it():
    """A torque per degree about the axis itself is that stiffness in N m/rad (x 180/pi); with the test's
    load and gauge points and arms, k = K d_load d_gauge / (lever gauge_arm) (closed form: d_load 0.3 m,
    d_gauge 0.1 m, lever 0.5 m, gauge arm 0.2 m: k = K * 0.3)."""
    assert _compliance({"torsional": "100 N m/deg"}).stiffness == pytest.approx(100 * 180 / np.pi, rel=1e-14)
    c = _compliance({"torsional": "100 N m/rad", "load": [1.2, -0.5], "gauge": [1.0, 0.1], "lever": 0.5,
                     "gauge_arm": 0.2})
    assert c.stiffness == pytest.approx(100 * 0.3 * 0.1 / (0.5 * 0.2), rel=1e-12)
    same_arms = _compliance({"torsional": "100 N m/rad", "load": [1.2, -0.5], "gauge": [1.0, 0.1]})
    assert same_arms.stiffness == pytest.approx(100.0, rel=1e-12)


@pytest.mark.parametrize("stiffness, key", [
    ({"lateral": "120 N/mm", "at": [0.9, -0.3]}, "flexible.fork.stiffness.at"),          # on the axis
    ({"lateral": "120 N m/rad", "at": [1.0, 0.0]}, "flexible.fork.stiffness.lateral"),  # wrong unit
    ({"torsional": "100 N m/deg", "load": [1.0, 0.0]}, "flexible.fork.stiffness"),
])
def test_bad_measurements_are_refused(stiffness, key):
    from bikemass.core.errors import InputError
    with pytest.raises(InputError) as info:
        _compliance(stiffness)
    assert info.value.key == key


def test_contract_tyre_moments_read_back(capsys, tmp_path):
    """A tyre file with moments (the measured trail, a twisting coefficient) is written with them and reads
    back as the same model (the moments were dropped from the file before)."""
    tyres = tmp_path / "tyres.yaml"
    tyres.write_text("front: {cornering_coefficient: 11.46 1/rad, camber_coefficient: 0.573 1/rad, relaxation_length: "
                     "0.175 m, pneumatic_trail: 16.6 mm, twisting_coefficient: 0.3 mm/deg}\n"
                     "rear: {cornering_coefficient: 12 1/rad, camber_coefficient: 0.5 1/rad, relaxation_length: 0.2 m, "
                     "pneumatic_trail: 12 mm}\n")
    out = round_trip(capsys, tmp_path, "tyre+flexible", "--stiffness", "steel", "--tyres", str(tyres))
    doc = yaml.safe_load(out.read_text())["tyre"]
    assert doc["front"]["pneumatic_trail"] == "0.0166 m" and doc["rear"]["pneumatic_trail"] == "0.012 m"
    assert "twisting_coefficient" in doc["front"] and "twisting_coefficient" not in doc["rear"]


def test_a_flexible_blocks_bad_field_names_the_file_and_key_and_an_absurd_stiffness_is_warned(capsys, tmp_path):
    """A ``flexible:`` block's modal mass set to 0 beside a nonzero modal momentum said "compliance frame twist:
    modal_momentum: ..." with no file or key: it names both now. A stiffness of 1e-3 N m/rad was computed without
    a word, though the same stiffness as a frame S is warned about: it is warned about too (an error under
    --strict)."""
    path = tmp_path / "flex.yaml"
    assert main(["params", "jamis", "--rider", "relaxed", "--model", "flexible", "--stiffness", "steel",
                 "--format", "yaml", "-o", str(path)]) == 0
    document = yaml.safe_load(path.read_text())
    capsys.readouterr()
    document["flexible"]["frame"]["modal_mass"] = 0
    bad = tmp_path / "bad.yaml"
    bad.write_text(yaml.safe_dump(document))
    assert main(["stability", str(bad)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{bad}: flexible.frame.modal_mass: a nonzero lateral momentum" in err[0]
    document = yaml.safe_load(path.read_text())
    document["flexible"]["frame"]["stiffness"] = 1e-3
    soft = tmp_path / "soft.yaml"
    soft.write_text(yaml.safe_dump(document))
    assert main(["stability", str(soft), "--strict"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{soft}: flexible.frame.stiffness: 0.001 N m/rad is outside 10..1e+10" in err[0]
