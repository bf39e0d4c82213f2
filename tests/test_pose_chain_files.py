"""Chain poses as files: `bikemass pose --out` and chain-form YAML load everywhere; the
placement form's `left:`; bicycle contacts; the thesis-pose comparison shown in docs/poses.md."""

from pathlib import Path

import numpy as np
import pytest
import yaml

from bikemass.bicycle import load_bicycle
from bikemass.cli.main import main
from bikemass.core.errors import InputError
from bikemass.rider import load_rider
from bikemass.study.thesis_fit import compare_with_chain
from images import blobs, colour_mask, pixels

ROOT = Path(__file__).parents[1]
THREE_LINES = "body: thesis_rider\nbike: jamis\nchain: {torso_lean: 30 deg, hands: hoods}\n"


def test_pose_file_from_the_command_loads_like_any_pose(tmp_path, capsys):
    out, png = tmp_path / "hoods.yaml", tmp_path / "hoods.png"
    assert main(["pose", "jamis", "--torso-lean", "30", "--hands", "hoods", "-o", str(out),
                 "--plot", str(png)]) == 0
    assert capsys.readouterr().out == ""                          # the data went to -o, the figure to --plot
    # the figure decoded: the rider's chain (dark green) and the contact targets (red crosses): the
    # saddle, the hoods and the pedal spindle, each one patch, and the legend's
    rgb = pixels(png)
    assert colour_mask(rgb, "darkgreen", 0.1).mean() > 0.001
    assert blobs(colour_mask(rgb, "red", 0.1)) == 3 + 1
    assert main(["pose", "jamis", "--torso-lean", "30", "--hands", "hoods"]) == 0
    assert "largest gap at a joint" in capsys.readouterr().out    # without -o: the report
    document = yaml.safe_load(out.read_text())
    assert document["units"] == {"location": "m", "angle": "deg"}
    assert set(document["segments"]) == {"head", "torso", "upper_arm", "lower_arm", "thigh", "lower_leg"}
    chain = tmp_path / "chain.yaml"
    chain.write_text(THREE_LINES)
    a, b = load_rider(str(out)).properties("exact"), load_rider(str(chain)).properties("exact")
    assert a.mass == pytest.approx(82.15, abs=1e-12)
    np.testing.assert_array_equal(a.com, b.com)                  # the same solve, every digit kept
    np.testing.assert_array_equal(a.inertia, b.inertia)
    assert main(["rider", str(out), "--format", "json"]) == 0
    assert main(["params", "jamis", "--rider", str(chain)]) == 0


def test_crank_angle_gives_left_and_right_legs(tmp_path, capsys):
    out = tmp_path / "crank.yaml"
    assert main(["pose", "jamis", "--crank", "0", "-o", str(out)]) == 0
    legs = yaml.safe_load(out.read_text())["segments"]["lower_leg"]
    assert legs["left"]["location"][1] == -legs["location"][1]
    assert legs["left"]["angle"] != legs["angle"]
    rider = load_rider(str(out))
    right, left = (next(p for p in rider.parts if p.name == f"lower_leg_{s}") for s in ("right", "left"))
    assert not np.allclose(right.placement.rotation, left.placement.rotation)
    inertia = rider.properties("exact").inertia
    assert abs(inertia[0, 1]) > 1e-3 and abs(inertia[1, 2]) > 1e-3    # asymmetric legs: Ixy, Iyz != 0


@pytest.mark.parametrize("edit,key", [
    (lambda s: s.replace("angle: 0.0 deg, mirror: true", "angle: 0.0 deg, mirror: true, left: {location: [0.2, 0.238, -1.3], angle: 0 deg}"),
     "segments.lower_arm.left.location"),
    (lambda s: s.replace("head:      {location: [0.200, 0.000, -1.922], angle: 0.000 deg",
                         "head:      {location: [0.200, 0.000, -1.922], angle: 0.000 deg, left: {location: [0, -1, 0], angle: 0 deg}"),
     "segments.head.left"),
])
def test_left_placement_is_checked(tmp_path, edit, key):
    text = (ROOT / "bodies" / "poses" / "no_hands.yaml").read_text()
    text = text.replace("lower_arm: {location: [0.200, 0.238, -1.317], angle: 0.000 deg, mirror: true}",
                        "lower_arm: {location: [0.200, 0.238, -1.317], angle: 0.0 deg, mirror: true}")
    path = tmp_path / "p.yaml"
    path.write_text(edit(text))
    with pytest.raises(InputError) as info:
        load_rider(str(path))
    assert info.value.key == key


def test_shipped_contacts():
    jamis = load_bicycle("jamis")
    np.testing.assert_array_equal(jamis.contacts.grips["hoods"], jamis.keypoints["hood_right"])
    np.testing.assert_array_equal(jamis.contacts.bottom_bracket, jamis.keypoints["bottom_bracket"])
    thesis = load_bicycle("jamis-thesis").contacts
    for name, point in jamis.contacts.grips.items():                  # same points written out
        np.testing.assert_array_equal(thesis.grips[name], point)
    assert load_bicycle("cargo-loaded").contacts.grips.keys() == {"tops", "hoods"}   # inherited via base:
    np.testing.assert_allclose(jamis.contacts.pedal(90), jamis.contacts.bottom_bracket + [0, 0, 0.17], atol=1e-15)


@pytest.mark.parametrize("contacts,key", [
    ("contacts: {saddle: [0.15, 0, -1], bottom_bracket: nowhere, crank_length: 0.17}", "contacts.bottom_bracket"),
    ("contacts: {saddle: [0.15, 0, -1], bottom_bracket: bottom_bracket, crank_length: -1}", "contacts.crank_length"),
    ("contacts: {saddle: [0.15, 0, -1], bottom_bracket: bottom_bracket, crank_length: 0.17, grips: {none: bar_right}}",
     "contacts.grips.none"),                                     # any word names a grip but 'none'
    ("contacts: {saddle: [0.15, 0, -1], bottom_bracket: bottom_bracket, crank_length: 0.17, grips: {bullhorn: nowhere}}",
     "contacts.grips.bullhorn"),
])
def test_bad_contacts_name_the_key(tmp_path, contacts, key):
    text = (ROOT / "frames" / "jamis.yaml").read_text().split("\ncontacts:")[0]
    path = tmp_path / "bike.yaml"
    path.write_text(text + "\n" + contacts + "\n")
    with pytest.raises(InputError) as info:
        load_bicycle(str(path))
    assert info.value.key == key


@pytest.mark.parametrize("chain,key", [("torso_lean: 0 deg, hands: aero", "chain.hands"),
                                       ("crank: 80 deg", "chain.crank"), ("hands: bars", "chain.hands"),
                                       ("torso_lean: 30 deg, wrist: 3", "chain.wrist")])
def test_bad_chain_file_names_its_key(tmp_path, chain, key):
    path = tmp_path / "far.yaml"
    path.write_text(THREE_LINES.replace("torso_lean: 30 deg, hands: hoods", chain))
    with pytest.raises(InputError) as info:
        load_rider(str(path))
    assert info.value.key == key and str(path) == info.value.source


def test_thesis_gaps_and_the_no_hands_fit():
    """Table 3-3 Aero Tuck: upper arm from (0.746, -1.107) at 26.831 deg (0.310 m) ends at
    x = 0.746 - 0.310 sin 26.831 = 0.6061, z = -0.8302; the lower arm starts at (0.477, -0.850):
    130.6 mm away in x-z (the thesis's 'up to 131 mm').  No Hands is nearly a chain already."""
    tuck = compare_with_chain("aero-tuck")
    assert tuck["plane_gaps"]["elbow"] == pytest.approx(np.hypot(0.746 - 0.310 * np.sin(np.radians(26.831)) - 0.477,
                                                              -1.107 + 0.310 * np.cos(np.radians(26.831)) + 0.850), abs=1e-12)
    assert max(tuck["chain_gaps"].values()) < 1e-12
    upright = compare_with_chain("no-hands")
    assert upright["rms"] < 0.003 and np.linalg.norm(upright["fitted"].com - upright["thesis"].com) < 0.001


def test_contract_the_written_pose_file_names_the_command_that_writes_it_again(tmp_path):
    """Contract test of the shell with itself: the header of ``pose -o`` names every option given
    (``--torso-lean`` was left out), so the command it names, run again, writes the same placement to the bit."""
    first = tmp_path / "first.yaml"
    assert main(["pose", "jamis", "--torso-lean", "30", "--hands", "hoods", "--fix", "neck=10", "-o", str(first)]) == 0
    command = first.read_text().splitlines()[0].split("written by: bikemass ")[1].split()
    assert "--torso-lean" in command and "neck=10" in command
    again = tmp_path / "again.yaml"
    assert main([*command, "-o", str(again)]) == 0
    assert yaml.safe_load(again.read_text()) == yaml.safe_load(first.read_text())
