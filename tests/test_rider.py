"""The rider model against Williams (2015), Tables 3-2, 3-3 and 3-4.

Reference numbers are read from reference/rider_tables.yaml (checked
transcriptions of the thesis); nothing here is computed from them in the package.
"""

from pathlib import Path

import numpy as np
import pytest
import yaml

from bikemass.core.errors import InputError
from bikemass.rider import THESIS_POSES, load_rider, shipped_poses

REF = yaml.safe_load((Path(__file__).parents[1] / "reference" / "rider_tables.yaml").read_text())
POSE_KEYS = dict(zip(THESIS_POSES, REF["poses"]))      # "no-hands" -> "no_hands"
PAIRED = [k for k, v in REF["table_3_2"].items() if v.get("count") == 2]


def table_3_4(pose):
    """(mass, com, {Ixx, Ixz, Iyy, Izz}) of ``pose`` as printed in Table 3-4."""
    i = REF["poses"].index(POSE_KEYS[pose])
    t = REF["table_3_4"]
    com = np.array([t["x_m"][i], t["y_m"][i], t["z_m"][i]])
    inertia = {k: t[f"{k}_kgm2"][i] for k in ("Ixx", "Ixz", "Iyy", "Izz")}
    return t["mass_kg"][i], com, inertia


def entries(props):
    I = props.inertia
    return {"Ixx": I[0, 0], "Ixz": I[0, 2], "Iyy": I[1, 1], "Izz": I[2, 2]}


@pytest.fixture(scope="module")
def riders():
    return {p: load_rider(p) for p in THESIS_POSES}


def test_shipped_poses_are_the_thesis_poses_in_order():
    assert shipped_poses()[:5] == list(THESIS_POSES)
    assert not any(p.endswith("-thesis") for p in shipped_poses())


# -- Table 3-2: anthropometry ---------------------------------------------------

def test_segment_masses_and_volumes_match_table_3_2(riders):
    """Exact volumes equal the printed volumes to their 3 printed decimals (1e-3 of 1e-3 m^3)."""
    parts = {p.name: p for p in riders["relaxed"].parts}
    total = 0.0
    for name, row in REF["table_3_2"].items():
        if name == "total":
            continue
        copies = [p for n, p in parts.items() if n in (name, f"{name}_right", f"{name}_left")]
        assert len(copies) == row["count"]
        for part in copies:
            assert part.mass == pytest.approx(row["mass_kg"], rel=1e-12)
            assert part.solid.volume * 1e3 == pytest.approx(row["volume_1e-3_m3"], abs=5e-4)
            total += part.mass
    assert total == pytest.approx(REF["table_3_2"]["total"]["mass_kg"], rel=1e-12)


# -- Table 3-3: the pose files hold the printed table and its corrections ----

def _placements(rider):
    """{segment name: (location, angle_deg)} of the +y copy (or the single part)."""
    out = {}
    for part in rider.parts:
        name = part.name.removesuffix("_right")
        if part.name.endswith("_left"):
            continue
        axis = part.placement.rotation @ [0.0, 0.0, 1.0]
        out[name] = (part.placement.translation, np.degrees(np.arctan2(-axis[0], axis[2])))
    return out


@pytest.mark.parametrize("as_printed", [True, False])
@pytest.mark.parametrize("pose", THESIS_POSES)
def test_pose_files_reproduce_table_3_3(pose, as_printed):
    """As printed: every Table 3-3 value; corrected: the same with the reference corrections."""
    i = REF["poses"].index(POSE_KEYS[pose])
    expected = {seg: {f: vals[f][i] for f in ("x_m", "y_m", "z_m", "angle_deg")}
                for seg, vals in REF["table_3_3"].items()}
    if not as_printed:
        for c in REF["corrections"]:
            if c["pose"] == POSE_KEYS[pose]:
                expected[c["part"]][c["field"]] = c["corrected"]
    got = _placements(load_rider(pose, as_printed=as_printed))
    assert set(got) == set(expected)
    for seg, e in expected.items():
        loc, angle = got[seg]
        np.testing.assert_allclose(loc, [e["x_m"], e["y_m"], e["z_m"]], rtol=0, atol=1e-12)
        assert angle == pytest.approx(e["angle_deg"], abs=1e-9)


def test_paired_limbs_are_mirror_images(riders):
    for rider in riders.values():
        parts = {p.name: p for p in rider.parts}
        for seg in PAIRED:
            right, left = parts[f"{seg}_right"].exact(), parts[f"{seg}_left"].exact()
            assert right.com[1] > 0
            np.testing.assert_allclose(left.com, right.com * [1, -1, 1], atol=1e-15)
            S = np.diag([1.0, -1.0, 1.0])
            np.testing.assert_allclose(left.inertia, S @ right.inertia @ S, atol=1e-15)


# -- Table 3-4: the validation ------------------------------------------------
# Tolerances: the thesis's Creo values are printed to 3 decimals, and its geometry
# (Table 3-3) to 1 mm / 0.001 deg.  docs/thesis.md#the-rider-model records the reproduction as
# <= 0.26 % relative, CoM <= 0.5 mm, inertia <= 0.014 kg m^2; we assert just above
# those (0.3 %, 0.5 mm = half the last printed digit, 0.015 kg m^2), well inside the
# issue's 0.5 % / 1 mm, so a regression of a few tenths of a percent is caught.

REL, COM_MM, INERTIA_ABS = 3e-3, 0.5e-3 + 1e-9, 0.015


@pytest.mark.parametrize("method", ["mesh", "exact"])
@pytest.mark.parametrize("pose", THESIS_POSES)
def test_table_3_4_reproduced(riders, pose, method):
    props = riders[pose].properties(method=method)
    mass, com, inertia = table_3_4(pose)
    assert props.mass == pytest.approx(mass, rel=1e-12)
    assert np.abs(props.com - com).max() <= COM_MM
    for k, v in entries(props).items():
        assert abs(v - inertia[k]) <= REL * abs(inertia[k]), (k, v, inertia[k])
        assert abs(v - inertia[k]) <= INERTIA_ABS, (k, v, inertia[k])
    I = props.inertia
    assert abs(I[0, 1]) < 1e-9 and abs(I[1, 2]) < 1e-9                 # symmetric rider


def test_table_3_4_worst_cases_are_as_recorded(riders):
    """The worst agreement is the documented one (Relaxed Izz +0.26 %, On Hoods Iyy -0.0136)."""
    worst_rel, worst_abs = 0.0, 0.0
    for pose, rider in riders.items():
        _, _, inertia = table_3_4(pose)
        for k, v in entries(rider.properties("exact")).items():
            worst_rel = max(worst_rel, abs(v - inertia[k]) / abs(inertia[k]))
            worst_abs = max(worst_abs, abs(v - inertia[k]))
    assert 0.0025 < worst_rel < 0.0026
    assert 0.013 < worst_abs < 0.014


# -- the printed Table 3-3 (--as-printed) ---------------------------------------

def test_as_printed_changes_only_the_three_errata_poses(riders):
    for pose in ("relaxed", "aerobars"):
        a, b = riders[pose].properties("exact"), load_rider(pose, as_printed=True).properties("exact")
        np.testing.assert_array_equal(a.com, b.com)
        np.testing.assert_array_equal(a.inertia, b.inertia)


def _about_origin(mass, com, inertia):
    """The inertia (kg m^2) about the origin of a body with ``inertia`` about its centre of mass ``com``:
    the parallel-axis theorem, ``I + m (|c|^2 E - c c^T)``."""
    c = np.asarray(com, dtype=float)
    return np.asarray(inertia, dtype=float) + mass * (c @ c * np.eye(3) - np.outer(c, c))


def test_as_printed_misses_table_3_4():
    """The printed Table 3-3 misses Table 3-4 badly where the errata are (reference/rider_tables.yaml,
    ``corrections``), by what the parallel-axis theorem predicts from the corrected rider and the
    segments the errata move.

    No Hands: the head's z printed +1.922 m (1.9 m below the ground): with Table 3-2's head mass the
    CoM moves down by ``m_head * 3.844 m / M`` exactly.  On Hoods: the head's x printed 0.723 for 0.773
    m: the CoM moves by ``m_head * 0.05 m / M``.  Aero Tuck: the forearms' angle printed as its
    supplement.  Each composite inertia, about its new CoM, is the corrected rider's with the moved
    segments swapped (parallel-axis theorem, to round-off), and misses Table 3-4 by more than three times the
    corrected rider's tolerance (No Hands by hundreds, Aero Tuck's CoM by 2.5 mm against 0.5 mm).
    """
    head_mass, total = REF["table_3_2"]["head"]["mass_kg"], REF["table_3_4"]["mass_kg"][0]
    moved = {"no-hands": np.array([0.0, 0.0, 1.922 - -1.922]), "on-hoods": np.array([0.723 - 0.773, 0.0, 0.0])}
    for pose in ("no-hands", "on-hoods", "aero-tuck"):
        corrected, printed = load_rider(pose), load_rider(pose, as_printed=True)
        a, b = corrected.properties("exact"), printed.properties("exact")
        assert b.mass == pytest.approx(a.mass, rel=1e-12) == total
        if pose in moved:                                   # published numbers and a closed form only
            np.testing.assert_allclose(b.com - a.com, head_mass * moved[pose] / total, rtol=1e-9, atol=1e-12)
        old = {p.name: p.exact() for p in corrected.parts}
        new = {p.name: p.exact() for p in printed.parts}
        swapped = [n for n in old if not np.array_equal(old[n].com, new[n].com)
                   or not np.array_equal(old[n].inertia, new[n].inertia)]
        assert swapped == (["head"] if pose in moved else ["lower_arm_right", "lower_arm_left"])
        com = (a.mass * a.com + sum(new[n].mass * new[n].com - old[n].mass * old[n].com for n in swapped)) / a.mass
        origin = _about_origin(a.mass, a.com, a.inertia) + sum(
            _about_origin(new[n].mass, new[n].com, new[n].inertia) - _about_origin(old[n].mass, old[n].com, old[n].inertia)
            for n in swapped)
        np.testing.assert_allclose(b.com, com, rtol=0, atol=1e-12)
        np.testing.assert_allclose(b.inertia, origin - _about_origin(a.mass, com, np.zeros((3, 3))),
                                   rtol=0, atol=1e-10)
        _, table_com, table_inertia = table_3_4(pose)
        misses = max(np.abs(b.com - table_com).max() / COM_MM,
                     max(abs(v - table_inertia[k]) / INERTIA_ABS for k, v in entries(b).items()))
        assert misses > 3, (pose, misses)            # beyond 3 times what the corrected rider is held to


# -- published riders, methods and overlaps -------------------------------------

@pytest.mark.parametrize("pose", THESIS_POSES)
def test_published_riders_are_table_3_4_exactly(pose):
    rider = load_rider(pose + "-thesis")
    assert len(rider.parts) == 1
    for method in ("mesh", "exact"):
        props = rider.properties(method)
        mass, com, inertia = table_3_4(pose)
        assert props.mass == mass
        np.testing.assert_allclose(props.com, com, rtol=1e-15, atol=1e-15)
        assert entries(props) == inertia


def test_mesh_and_exact_agree_for_every_rider(riders):
    """Equal-area tessellation: mesh mass exact to round-off, inertia within 1e-5 of the largest."""
    for rider in riders.values():
        mesh, exact = rider.properties("mesh"), rider.properties("exact")
        assert mesh.mass == pytest.approx(exact.mass, rel=1e-9)
        np.testing.assert_allclose(mesh.com, exact.com, rtol=0, atol=1e-9)
        scale = np.abs(exact.inertia).max()
        assert np.abs(mesh.inertia - exact.inertia).max() <= 1e-5 * scale


def test_breakdown_adds_up_to_the_total(riders):
    from bikemass.mass.inertia import combine
    rider = riders["aero-tuck"]
    rows = rider.breakdown("exact")
    assert [name for name, _, _ in rows][:2] == ["head", "torso"]
    assert {body for _, body, _ in rows} == {"rear_frame"}
    total = combine(mp for _, _, mp in rows)
    np.testing.assert_allclose(total.inertia, rider.properties("exact").inertia, atol=1e-12)


def _union_bounds(rider):
    """Bounds on the mass the union removes: overlap volume times the min/max density."""
    import trimesh
    meshes = [p.mesh() for p in rider.parts]
    overlap = sum(m.volume for m in meshes) - trimesh.boolean.union(meshes, engine="manifold").volume
    densities = [p.density for p in rider.parts]
    return overlap, overlap * min(densities), overlap * max(densities)


@pytest.mark.parametrize("pose", ["relaxed", "aero-tuck"])
def test_union_counts_overlaps_once(riders, pose):
    rider = riders[pose]
    summed, united = rider.properties(), rider.properties(overlap="union")
    overlap, low, high = _union_bounds(rider)
    assert overlap > 1e-4                                   # the thesis rider's segments do overlap
    assert low - 1e-9 <= summed.mass - united.mass <= high + 1e-9


def test_union_equals_sum_without_overlaps(tmp_path):
    pose = tmp_path / "apart.yaml"
    pose.write_text(_spread_pose())
    rider = load_rider(str(pose))
    summed, united = rider.properties(), rider.properties(overlap="union")
    # manifold3d's booleans keep vertices to ~1e-7 of the model's size: 1e-6 relative.
    assert united.mass == pytest.approx(summed.mass, rel=1e-6)
    np.testing.assert_allclose(united.com, summed.com, rtol=0, atol=1e-6)
    np.testing.assert_allclose(united.inertia, summed.inertia, rtol=1e-6)


def _spread_pose():
    """Every thesis segment hanging straight down, 0.6 m apart along x: nothing overlaps."""
    lines = ["name: Spread out", "body: thesis_rider", "segments:"]
    for i, seg in enumerate(REF["table_3_2"]):
        if seg == "total":
            continue
        mirror = ", mirror: true" if seg in PAIRED else ""
        lines.append(f"  {seg}: {{location: [{0.6 * i}, 0.3, -1.0], angle: 0 deg{mirror}}}")
    return "\n".join(lines) + "\n"


# -- user pose files ---------------------------------------------------------------

def test_user_pose_file_front_frame_units_and_printed(tmp_path):
    """A copy of Relaxed written by hand, hands on the bars, units, and a printed value."""
    text = (Path(__file__).parents[1] / "bodies" / "poses" / "relaxed.yaml").read_text()
    text = text.replace("lower_arm: {location: [0.450, 0.238, -1.312], angle: -48.829 deg, mirror: true}",
                        "lower_arm: {location: ['450 mm', 0.238, -1.312], angle: '-0.852232 rad', "
                        "mirror: true, frame: front, printed: {angle: 0 deg}}")
    assert "frame: front" in text
    pose = tmp_path / "my_pose.yaml"
    pose.write_text(text)
    rider = load_rider(str(pose))
    bodies = {p.name: p.body for p in rider.parts}
    assert bodies["lower_arm_left"] == bodies["lower_arm_right"] == "front_frame"
    assert bodies["head"] == "rear_frame"
    mine, shipped = rider.properties("exact"), load_rider("relaxed").properties("exact")
    np.testing.assert_allclose(mine.inertia, shipped.inertia, atol=2e-5)   # -0.852232 rad = -48.829 deg
    printed = load_rider(str(pose), as_printed=True).properties("exact")
    # printed angle 0: both forearms (2 x 1.9 kg, CoM 0.2395 m from the elbow) hang straight down.
    shift = 2 * 1.9 * 0.2395 * (1 - np.cos(0.852232)) / 82.15
    assert printed.com[2] - mine.com[2] == pytest.approx(shift, rel=1e-9)


def test_user_pose_with_own_anthropometry_and_lumped_load(tmp_path):
    """body: a .yaml next to the pose; a lumped segment (backpack) beside placed ones."""
    (tmp_path / "stick.yaml").write_text(
        "name: stick\nsegments:\n  pole: {shape: cylinder, diameter: 0.1, length: 2.0, mass: 3.0}\n")
    (tmp_path / "pose.yaml").write_text(
        "body: stick.yaml\nsegments:\n  pole: {location: [0, 0, -2], angle: 90 deg}\n"
        "  pack: {mass: 1.0, com: [-1.0, 0, -2.0], inertia: [[0, 0, 0], [0, 0, 0], [0, 0, 0]]}\n")
    props = load_rider(str(tmp_path / "pose.yaml")).properties("exact")
    # pole axis (-sin 90, 0, cos 90) = -x: from x = 0 back to x = -2, CoM at x = -1.
    np.testing.assert_allclose(props.com, [-1.0, 0.0, -2.0], atol=1e-12)
    m, r, L = 3.0, 0.05, 2.0
    np.testing.assert_allclose(np.diag(props.inertia), [m * r**2 / 2, m * (3 * r**2 + L**2) / 12,
                                                         m * (3 * r**2 + L**2) / 12], rtol=1e-12)


def test_unknown_pose_name_lists_the_shipped_ones():
    with pytest.raises(InputError, match="relaxed"):
        load_rider("sprinting")
