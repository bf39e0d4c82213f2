"""``bikemass rider`` / ``bikemass riders``: output forms and bad input (exit 2, one line).

The ``test_contract_*`` tests hold the command's JSON to the library it calls (the same code, so
digit for digit: the shell passes its options through and prints every digit); the numbers
themselves are held to Williams (2015) Table 3-4 in tests/test_rider.py, and here the total mass
to the printed 82.150 kg."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import yaml

from bikemass.cli.main import main
from bikemass.rider import THESIS_POSES, load_rider

BODIES = Path(__file__).parents[1] / "bodies"
RELAXED = (BODIES / "poses" / "relaxed.yaml").read_text()
ANTHROPOMETRY = (BODIES / "thesis_rider.yaml").read_text()


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_contract_rider_json_is_the_librarys(capsys):
    code, out, err = run(capsys, "rider", "relaxed", "--format", "json", "--method", "exact")
    assert code == 0 and err == ""
    data = json.loads(out)
    assert set(data) == {"pose", "mass", "com", "inertia", "units"}
    assert data["units"] == {"mass": "kg", "com": "m", "inertia": "kg m^2"}
    props = load_rider("relaxed").properties("exact")
    assert data["pose"] == "relaxed"
    assert data["mass"] == props.mass == pytest.approx(82.150, rel=1e-12)          # Table 3-4
    np.testing.assert_array_equal(data["com"], props.com)
    np.testing.assert_array_equal(data["inertia"], props.inertia)


def test_rider_yaml_and_as_printed(capsys):
    _, out, _ = run(capsys, "rider", "no-hands", "--format", "yaml", "--as-printed")
    printed = yaml.safe_load(out)
    _, out, _ = run(capsys, "rider", "no-hands", "--format", "yaml")
    corrected = yaml.safe_load(out)
    assert printed["com"][2] > corrected["com"][2] + 0.3      # the head 1.9 m below ground


def test_rider_table_has_the_segment_breakdown(capsys):
    code, out, _ = run(capsys, "rider", "aero-tuck", "--overlap", "union")
    assert code == 0
    assert "overlap union" in out and "mass     " in out
    for name in ("head", "torso", "upper_arm_right", "upper_arm_left", "lower_leg_left"):
        assert f"\n{name} " in out


def test_contract_riders_json_keyed_by_pose_is_the_librarys(capsys):
    code, out, _ = run(capsys, "riders", "--format", "json", "--method", "exact")
    data = json.loads(out)
    assert code == 0 and list(data) == ["riders", "units"] and list(data["riders"]) == list(THESIS_POSES)
    for pose, value in data["riders"].items():
        assert set(value) == {"pose", "mass", "com", "inertia"} and value["pose"] == pose
        assert value["mass"] == pytest.approx(82.150, rel=1e-12)                      # Table 3-4
        np.testing.assert_array_equal(value["inertia"], load_rider(pose).properties("exact").inertia)


def test_riders_table_and_compare(capsys):
    _, out, _ = run(capsys, "riders")
    assert out.splitlines()[0].split() == list(THESIS_POSES)
    assert len(out.splitlines()) == 2 + 8                     # header, rule, Table 3-4's 8 rows
    _, out, _ = run(capsys, "riders", "--compare", "--format", "json")
    data = json.loads(out)
    assert data["riders"]["on-hoods"]["thesis"]["inertia"][1][1] == 9.934    # Table 3-4, On Hoods Iyy


# -- bad input ---------------------------------------------------------------------

def _pose(tmp_path, text, body=None):
    if body is not None:
        (tmp_path / "body.yaml").write_text(body)
    path = tmp_path / "pose.yaml"
    path.write_text(text)
    return path


BAD_POSES = {
    # name: (pose text, anthropometry text or None, key expected in the message, words expected)
    "unknown segment": (RELAXED + "  neck: {location: [0, 0, -1.8], angle: 0 deg}\n", None,
                        "segments.neck", "segment of the anthropometry"),
    "misspelt segment": (RELAXED.replace("  head:", "  haed:"), None, "segments.haed", "(head, torso,"),
    "missing key": (RELAXED.replace(", angle: 15.362 deg}", "}", 1), None, "segments.head.angle", "missing"),
    "extra key": (RELAXED.replace("angle: 15.362 deg}", "angle: 15.362 deg, colour: red}", 1), None,
                  "segments.head.colour", "no such key"),
    "missing segment": ("\n".join(l for l in RELAXED.splitlines() if "lower_leg" not in l), None,
                        "segments", "missing: lower_leg"),
    "non-numeric location": (RELAXED.replace("[0.402, 0.000, -1.895]", "[0.402, 0.000, high]"), None,
                             "segments.head.location[2]", "number"),
    "unknown body": (RELAXED.replace("body: thesis_rider", "body: martian"), None, "body",
                     "shipped anthropometry"),
    "mirror mismatch": (RELAXED.replace("angle: -45.220 deg, mirror: true", "angle: -45.220 deg"), None,
                        "segments.thigh.mirror", "mirror: true"),
    "bad frame": (RELAXED.replace("angle: 15.362 deg}", "angle: 15.362 deg, frame: fork}", 1), None,
                  "segments.head.frame", "one of rear, front"),
    "unknown shape": (RELAXED.replace("thesis_rider", "body.yaml"),
                      ANTHROPOMETRY.replace("shape: cylinder", "shape: sphere", 1), "segments.head.shape",
                      "one of cylinder, trapezoidal_prism"),
    "negative size": (RELAXED.replace("thesis_rider", "body.yaml"),
                      ANTHROPOMETRY.replace("length: 310 mm", "length: -310 mm"), "segments.upper_arm.length",
                      "positive number"),
    "non-numeric size": (RELAXED.replace("thesis_rider", "body.yaml"),
                         ANTHROPOMETRY.replace("diameter: 82 mm", "diameter: slim"), "segments.lower_arm.diameter",
                         "number"),
    "zero mass": (RELAXED.replace("thesis_rider", "body.yaml"),
                  ANTHROPOMETRY.replace("mass: 8.2 ", "mass: 0 "), "segments.thigh.mass", "positive number"),
    "lumped zero mass": ("segments:\n  rider: {mass: 0, com: [0, 0, -1], inertia: [[1,0,0],[0,1,0],[0,0,1]]}\n",
                         None, "segments.rider.mass", "positive number"),
    "lumped asymmetric inertia": ("segments:\n  rider: {mass: 80, com: [0, 0, -1], "
                                  "inertia: [[1,0,0.5],[0,1,0],[0,0,1]]}\n", None, "segments.rider.inertia",
                                  "symmetric"),
    "placed without body": ("segments:\n  head: {location: [0, 0, -1.9], angle: 0 deg}\n", None,
                            "segments.head", "body:"),
    "angle in mm": (RELAXED.replace("angle: 15.362 deg}", "angle: 15 mm}", 1), None, "segments.head.angle",
                    "'<number> deg'"),
    "bad printed value": (RELAXED.replace("angle: 15.362 deg}", "angle: 15.362 deg, printed: {angle: steep}}", 1),
                          None, "segments.head.printed.angle", "number"),
    "bad yaml": ("segments: [unclosed\n", None, "line", "valid YAML"),
}


@pytest.mark.parametrize("case", list(BAD_POSES))
def test_bad_pose_is_one_line_exit_2(tmp_path, capsys, case):
    text, body, key, words = BAD_POSES[case]
    path = _pose(tmp_path, text, body)
    before = sorted(tmp_path.iterdir())
    code, out, err = run(capsys, "rider", str(path), "--format", "json")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "Traceback" not in err
    source = "pose.yaml" if body is None else "body.yaml"     # the file holding the bad key
    assert err.startswith(f"bikemass: error: {tmp_path / source}: {key}"), err
    assert words in err, err
    assert sorted(tmp_path.iterdir()) == before                # nothing written


def test_unknown_pose_name(capsys):
    code, out, err = run(capsys, "rider", "sprinting")
    assert code == 2 and out == "" and "no-hands" in err and err.count("\n") == 1


def test_console_script_exit_status_and_single_line(tmp_path):
    """The installed entry point, as a user runs it: exit 2, one line on stderr, no traceback."""
    path = _pose(tmp_path, RELAXED.replace("body: thesis_rider", "body: martian"))
    proc = subprocess.run([sys.executable, "-m", "bikemass.cli.main", "rider", str(path)],
                          capture_output=True, text=True)
    assert proc.returncode == 2 and proc.stdout == ""
    assert proc.stderr.strip().count("\n") == 0 and "Traceback" not in proc.stderr
    assert f"{path}: body: a shipped anthropometry (thesis-rider)" in proc.stderr
