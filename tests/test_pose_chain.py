"""Chain poses: joined segments, contacts met, closed-form checks of the solver, bad input.

Tolerances: joints and contacts are checked on the Rider's placed parts (not on the
chain's own formulas) to 1e-9 m: the solver converges to ~1e-14 m and the placement
form keeps every digit.  Joint angles are checked against the law of cosines to 1e-7
deg; reach limits against straight-limb distances to the printed 0.1 mm.
"""

import numpy as np
import pytest

from bikemass.bicycle import load_bicycle
from bikemass.cli.main import main
from bikemass.core.config import Node
from bikemass.core.convention import thesis_segment_rotation
from bikemass.core.errors import InputError
from bikemass.core.paths import bodies_dir
from bikemass.rider import Rider
from bikemass.rider.chain import joint_gaps, load_chain_body
from bikemass.rider.pose import read_pose
from bikemass.rider.solve import solve_on_bicycle
from printed import number_after

BODY = load_chain_body(bodies_dir() / "thesis_rider.yaml", "thesis_rider")
JAMIS = load_bicycle("jamis")
L = BODY.lengths                       # Table 3-2: 0.295, 0.466, 0.310, 0.479, 0.524, 0.450 m


def rider_of(solution):
    name, parts = read_pose(Node(solution.pose.placement_form("test", "thesis_rider"), "test.yaml", None))
    return Rider("test", name, parts)


def part_ends(rider):
    """{part name: (top-plane centre, far end)} from the placed solids (local z = the axis)."""
    return {p.name: (p.placement.apply([0, 0, 0]), p.placement.apply([0, 0, p.solid.length]))
            for p in rider.parts}


CASES = [(hands, lean, crank) for hands in ("tops", "hoods", "drops", "aero", "none")
         for lean in (None, 35.0) for crank in (None, 0.0, 200.0)
         if not (hands in ("drops", "aero") and lean == 35.0)]   # out of reach at 35 deg: tested below


@pytest.mark.parametrize("hands,lean,crank", CASES)
def test_generated_poses_are_joined_and_meet_their_contacts(hands, lean, crank):
    fixed = {} if lean is None else {"torso_lean": lean}
    solution = solve_on_bicycle(BODY, JAMIS.contacts, hands, crank, fixed).check_reachable()
    ends = part_ends(rider_of(solution))
    torso_top, torso_end = ends["torso"]
    R = thesis_segment_rotation(solution.pose.angles["torso_lean"])
    for side, s in (("right", 1), ("left", -1)):
        mirror = np.array([1, s, 1])
        joins = [(ends[f"upper_arm_{side}"][0], torso_top + R @ (BODY.shoulder * mirror)),   # shoulder
                 (ends[f"lower_arm_{side}"][0], ends[f"upper_arm_{side}"][1]),               # elbow
                 (ends[f"thigh_{side}"][0], torso_top + R @ (BODY.hip * mirror)),             # hip
                 (ends[f"lower_leg_{side}"][0], ends[f"thigh_{side}"][1])]                    # knee
        for a, b in joins:
            np.testing.assert_allclose(a, b, rtol=0, atol=1e-9)
        foot = ends[f"lower_leg_{side}"][1]
        target = JAMIS.contacts.bottom_bracket if crank is None else JAMIS.contacts.pedal(crank, side)
        np.testing.assert_allclose(foot[[0, 2]], target[[0, 2]], rtol=0, atol=1e-9)
        if hands != "none":
            hand = ends[f"lower_arm_{side}"][1]
            np.testing.assert_allclose(hand[[0, 2]], JAMIS.contacts.grips[hands][[0, 2]], rtol=0, atol=1e-9)
    np.testing.assert_allclose(ends["head"][1], torso_top + R @ BODY.neck, rtol=0, atol=1e-9)     # neck
    hip = (ends["thigh_right"][0] + ends["thigh_left"][0]) / 2
    np.testing.assert_allclose(hip + [0, 0, BODY.seat], JAMIS.contacts.saddle, rtol=0, atol=1e-9)  # saddle
    assert max(solution.residuals.values()) < 1e-9
    right, _ = solution.pose.placements()
    assert max(joint_gaps(right, BODY).values()) < 1e-12
    if lean is not None:
        assert solution.pose.angles["torso_lean"] == lean


def test_leg_and_arm_angles_match_the_law_of_cosines():
    """Independent of the solver: a two-link limb reaching a point at distance d has the
    joint flexion 180 deg - the triangle's angle opposite d."""
    solution = solve_on_bicycle(BODY, JAMIS.contacts, "hoods", None, {"torso_lean": 30.0})
    hip = JAMIS.contacts.saddle - [0, 0, BODY.seat]
    d = np.linalg.norm((JAMIS.contacts.bottom_bracket - hip)[[0, 2]])
    knee = 180 - np.degrees(np.arccos((L["thigh"] ** 2 + L["lower_leg"] ** 2 - d**2)
                                      / (2 * L["thigh"] * L["lower_leg"])))
    assert solution.pose.angles["knee"] == pytest.approx(knee, abs=1e-7)
    R = thesis_segment_rotation(30.0)
    top = hip - R @ (BODY.hip * [1, 0, 1])
    d = np.linalg.norm((JAMIS.contacts.grips["hoods"] - top)[[0, 2]])
    elbow = 180 - np.degrees(np.arccos((L["upper_arm"] ** 2 + L["lower_arm"] ** 2 - d**2)
                                       / (2 * L["upper_arm"] * L["lower_arm"])))
    assert solution.pose.angles["elbow"] == pytest.approx(elbow, abs=1e-7)


def test_defaults_solve_the_lean_with_the_elbows_bent_20_deg():
    solution = solve_on_bicycle(BODY, JAMIS.contacts, "hoods")
    assert solution.pose.angles["elbow"] == 20.0 and solution.pose.angles["neck"] == 0.0
    assert set(solution.free) == {"torso_lean", "shoulder", "hip", "knee"}
    none = solve_on_bicycle(BODY, JAMIS.contacts, "none")
    assert none.pose.segment_angles()["upper_arm"] == 0.0 == none.pose.angles["torso_lean"]  # arms hang


def test_saddle_too_high_for_the_pedal_names_the_contact_and_the_distance():
    """Crank at 90 deg: the right pedal is 170 mm below the crank axis; the straight leg
    (0.524 + 0.450 m) falls short by |hip - pedal| - 0.974 m."""
    hip = JAMIS.contacts.saddle - [0, 0, BODY.seat]
    pedal = JAMIS.contacts.bottom_bracket + [0, 0, 0.170]
    short = np.linalg.norm((pedal - hip)[[0, 2]]) - (L["thigh"] + L["lower_leg"])
    with pytest.raises(InputError) as info:
        solve_on_bicycle(BODY, JAMIS.contacts, "hoods", 90.0).check_reachable()
    assert info.value.key == "contacts.crank_length"
    assert number_after(info.value.expected, "right foot out of reach by") == pytest.approx(short * 1000, abs=0.051)
    assert 40 < short * 1000 < 42


def test_arms_too_short_for_the_aero_grips(capsys):
    hip = JAMIS.contacts.saddle - [0, 0, BODY.seat]
    shoulder = hip - thesis_segment_rotation(10.0) @ (BODY.hip * [1, 0, 1])   # shoulder = torso top
    short = np.linalg.norm((JAMIS.contacts.grips["aero"] - shoulder)[[0, 2]]) - (L["upper_arm"] + L["lower_arm"])
    assert main(["pose", "jamis", "--hands", "aero", "--torso-lean", "10"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1
    assert err.startswith("bikemass: error: ") and "frames/jamis.yaml: contacts.grips.aero: " in err
    assert "mm (arms too short for the bars)" in err
    assert number_after(err, "hands out of reach by") == pytest.approx(short * 1000, abs=0.051)   # printed to 0.1 mm


@pytest.mark.parametrize("argv,where", [
    (["pose", "cargo", "--hands", "drops"], "contacts.grips.drops: a grip named drops (this bicycle has: tops, hoods)"),
    (["pose", "benchmark"], "frames/benchmark.yaml: contacts: a bicycle with a contacts: section"),
    (["pose", "jamis", "--fix", "wrist=10"], "--fix: wrist=10: JOINT=DEG"),
    (["pose", "jamis", "--fix", "knee=x"], "--fix: knee=x: JOINT=DEG with DEG a number"),
    (["pose", "jamis", "--body", "nobody"], "body: a shipped anthropometry"),
])
def test_bad_input_is_one_line_exit_2(capsys, argv, where):
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and where in err


def test_angles_outside_human_ranges_warn_naming_the_joint(capsys):
    assert main(["pose", "jamis", "--torso-lean", "100"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err[0] == "bikemass: warning: torso lean 100.0 deg is outside the typical human range -20..90 deg"
    assert all(line.startswith("bikemass: warning: ") and " deg is outside" in line for line in err)
    assert main(["pose", "jamis"]) == 0 and capsys.readouterr().err == ""


@pytest.mark.parametrize("seed", range(4))
def test_point_derivatives_match_central_differences(seed):
    """The solver's analytic derivatives of the seat, hand and feet (left foot with its own hip
    and knee) against central differences of the points themselves (step 1e-6 rad or m: the
    truncation error, ~1e-12 m, is far below the 1e-8 asked)."""
    from bikemass.rider.chain import ChainPose
    rng = np.random.default_rng(seed)
    angles = {"torso_lean": rng.uniform(0, 60), "neck": rng.uniform(-10, 10), "shoulder": rng.uniform(20, 90),
              "elbow": rng.uniform(0, 60), "hip": rng.uniform(60, 110), "knee": rng.uniform(10, 90),
              "hip_left": rng.uniform(60, 110), "knee_left": rng.uniform(10, 90)}
    root = rng.uniform(-0.5, 0.5, 2)
    pose = ChainPose(BODY, root, angles)
    h = 1e-6

    def moved(variable, step):
        if variable.startswith("root"):
            r = root + (step * np.eye(2)[0 if variable == "root_x" else 1])
            return ChainPose(BODY, r, angles)
        return ChainPose(BODY, root, {**angles, variable: angles[variable] + np.degrees(step)})
    for point, side in (("seat", "right"), ("hand", "right"), ("foot", "right"), ("foot", "left")):
        derivative = pose.point_jacobian(point, side)
        for variable in ("root_x", "root_z", *angles):
            ahead, behind = moved(variable, h).points(side)[point], moved(variable, -h).points(side)[point]
            numeric = ((ahead - behind) / (2 * h))[[0, 2]]
            assert np.abs(derivative.get(variable, np.zeros(2)) - numeric).max() < 1e-8, (point, side, variable)
