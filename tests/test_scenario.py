"""The scenario seam: a person rider (a chain pose with a posture rule and no ``bike:``) accepted
by every entry point, re-seated on every changed bicycle; chart changes applied to the frame (the
published redundant values check only the chart as published); every input value in SI.

References are independent of :class:`bikemass.scenario.inputs.Model`: the changed chart is
written here as a plain mapping and run through ``bm.parameters`` / ``bm.stability``.
"""

import copy
import json
import math
import warnings

import numpy as np
import pytest
import yaml

import bikemass as bm
from bikemass.bicycle.chart import CHECKED_KEYS
from bikemass.cli.main import main
from bikemass.core.paths import frames_dir
from bikemass.rider import poses_dir
from bikemass.scenario.scenario import Scenario

BIKE, SIZE = "bmc-roadmachine", 56
PERSON = {"name": "me", "body": {"height": "1.80 m", "mass": "74 kg", "sex": "male"},
          "chain": {"hands": "hoods", "front": ["lower_arm"]}}


@pytest.fixture(scope="module")
def person(tmp_path_factory):
    path = tmp_path_factory.mktemp("person") / "me.yaml"
    path.write_text(yaml.safe_dump(PERSON))
    return str(path)


def published_size():
    """The shipped chart's mapping for one size (lists per size collapsed), read with PyYAML."""
    doc = yaml.safe_load((frames_dir() / "bmc_roadmachine.yaml").read_text())
    i = doc["sizes"].index(SIZE)

    def one(d):
        return {k: one(v) if isinstance(v, dict) else
                (v[i] if isinstance(v, list) and len(v) == len(doc["sizes"]) else v)
                for k, v in d.items() if k != "sizes"}
    return one(doc)


def critical(mapping, rider):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        result = bm.stability(bm.parameters(mapping, rider))
    return result.weave_speeds[0], result.capsize_speeds[0]


def changed(**chart):
    """The published chart with ``chart`` values (mm or deg) and its redundant checks dropped."""
    mapping = copy.deepcopy(published_size())
    mapping["chart"].update(chart)
    for key in CHECKED_KEYS:
        mapping["chart"].pop(key, None)
    return mapping


def run_json(capsys, *argv):
    assert main(list(argv)) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


def test_person_rider_without_bike_is_accepted_by_every_entry_point(person, capsys, tmp_path):
    rider = bm.load_rider(person)
    assert rider.needs_bicycle and "seated when given a bicycle" in repr(rider)
    with pytest.raises(bm.InputError, match="bike: a bicycle to seat this chain pose on"):
        rider.properties()
    seated = bm.seated_rider("jamis", rider)
    assert seated.properties().mass == pytest.approx(74.0, rel=1e-12)
    bike = f"{BIKE}@{SIZE}"
    params = run_json(capsys, "params", bike, "--rider", person, "--format", "json")
    stability = run_json(capsys, "stability", bike, "--rider", person, "--format", "json")
    sensitivity = run_json(capsys, "sensitivity", bike, "--rider", person, "--inputs", "chart.stack",
                           "--format", "json")
    std = tmp_path / "std.yaml"
    std.write_text("uncertainty:\n  chart.stack: 2 mm\n")
    uncertainty = run_json(capsys, "uncertainty", bike, "--rider", person, "--std", str(std), "--format", "json")
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"name: stack\nbike: {bike}\nrider: {person}\nvary:\n  chart.stack: [585 mm, 595 mm]\n")
    assert main(["sweep", str(spec), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    import csv
    rows = list(csv.DictReader((tmp_path / "out" / "results.csv").open()))
    assert len(rows) == 2 and all(not row["error"] and float(row["weave_speed"]) > 0 for row in rows)
    # one scenario: the same weave speed from each (the sweep at the stack's own value is between)
    weave = stability["weave_speeds"][0]
    assert sensitivity["weave_speed"] == pytest.approx(weave, abs=1e-9)
    assert uncertainty["weave_speed"]["nominal"] == pytest.approx(weave, abs=1e-9)
    alone = bm.parameters(f"{BIKE}@{SIZE}")
    total = sum(params[k] for k in ("mR", "mB", "mH", "mF"))
    assert total == pytest.approx(74.0 + alone.mR + alone.mB + alone.mH + alone.mF, rel=1e-9)
    weaves = [float(row["weave_speed"]) for row in rows]          # stack 585 and 595 mm bracket 590 mm
    assert min(weaves) < weave < max(weaves)


def test_stack_sensitivity_equals_a_central_difference_of_stability_with_the_rider_reseated(person, capsys):
    """The issue's must-show: d(weave)/d(stack) of ``sensitivity --inputs chart.stack`` equals the
    central difference of ``stability`` on the chart with the stack +-1 mm (the rider re-seated),
    within 3 % (measured: 1e-5; the difference's own truncation error is ~(1 mm)^2 terms)."""
    out = run_json(capsys, "sensitivity", f"{BIKE}@{SIZE}", "--rider", person, "--inputs", "chart.stack",
                   "--format", "json")
    row = out["inputs"]["chart.stack"]
    assert row["value"] == pytest.approx(0.590, rel=1e-12)                   # SI: the chart writes 590 mm
    stack = published_size()["chart"]["stack"]
    (wa, ca), (wb, cb) = critical(changed(stack=stack + 1), person), critical(changed(stack=stack - 1), person)
    assert row["weave_speed"] == pytest.approx((wa - wb) / 2e-3, rel=0.03)
    assert row["capsize_speed"] == pytest.approx((ca - cb) / 2e-3, rel=0.03)
    # the thesis-era bug had the wrong sign: the rider kept where it sat on the published frame
    assert np.sign(row["weave_speed"]) == np.sign(wa - wb) != 0


def test_a_changed_head_angle_keeps_the_fork_and_drops_the_published_checks(person):
    """1 deg steeper head tube on the BMC (published wheelbase, front centre, trail would all
    refuse it): the frame is rebuilt with the same fork offset and the trail it now has."""
    scenario = Scenario(f"{BIKE}@{SIZE}", person)
    angle = scenario.value("chart.head_tube_angle")
    assert angle == pytest.approx(math.radians(72.0), rel=1e-12)
    p = scenario.build({"chart.head_tube_angle": angle + math.radians(1.0)}).parameters
    published = published_size()["chart"]
    reference = bm.parameters(changed(head_tube_angle=f"{published['head_tube_angle'] + 1.0} deg"), person)
    assert p.c == pytest.approx(reference.c, rel=1e-12) and p.w == pytest.approx(reference.w, rel=1e-12)
    assert p.c < bm.parameters(f"{BIKE}@{SIZE}", person).c          # steeper head, same fork: less trail
    with pytest.raises(bm.InputError, match="wheelbase is derived from the frame"):
        scenario.build({"chart.wheelbase": 1.0})


def test_a_stand_in_is_written_as_the_frame_value_it_stands_for(person, tmp_path):
    """A chart that gives the trail instead of the fork offset: a changed head angle keeps the fork
    offset the published chart builds (not the trail)."""
    mapping = copy.deepcopy(published_size())
    chart = mapping["chart"]
    fork = chart.pop("fork_offset")
    built = bm.load_bicycle(mapping).chart
    assert built.fork_offset == pytest.approx(fork / 1000, abs=3e-3)   # through the published 63 mm trail
    path = tmp_path / "trail_chart.yaml"
    path.write_text(yaml.safe_dump(mapping))
    scenario = Scenario(str(path), person)
    p = scenario.build({"chart.head_tube_angle": scenario.value("chart.head_tube_angle") + math.radians(1.0)}).parameters
    reference = changed(head_tube_angle=f"{chart['head_tube_angle'] + 1.0} deg", fork_offset=f"{float(built.fork_offset)!r} m")
    assert p.c == pytest.approx(bm.parameters(reference, person).c, rel=1e-12)


def test_a_chain_pose_naming_the_scenarios_own_bicycle_is_reseated_as_a_person(tmp_path):
    """``bike: bmc-roadmachine@56`` in the pose: the same derivative as without it."""
    person_here, named = tmp_path / "me.yaml", tmp_path / "me_on_bmc.yaml"
    person_here.write_text(yaml.safe_dump(PERSON))
    named.write_text(yaml.safe_dump({**PERSON, "bike": f"{BIKE}@{SIZE}"}))
    change = {"chart.stack": 0.600}
    a = Scenario(f"{BIKE}@{SIZE}", str(person_here)).build(change).parameters
    b = Scenario(f"{BIKE}@{SIZE}", str(named)).build(change).parameters
    assert b.to_dict() == a.to_dict()


def test_inputs_and_spreads_are_si(person):
    """Values are SI whatever unit the file writes (0.040 in, a chart in mm); a spread may carry
    its unit (converted) or be bare (SI)."""
    from bikemass.analysis.uncertainty import read_spreads
    from bikemass.core.config import Node
    assert Scenario("jamis").value("sections.seat_stay.wall") == pytest.approx(0.040 * 0.0254, rel=1e-12)
    spreads = read_spreads(Node({"chart.stack": "2 mm", "rider.chain.torso_lean": {"distribution": "uniform",
                                                                                    "half_width": "3 deg"},
                                 "mB": 0.5}, "std.yaml", "uncertainty"))
    assert spreads["chart.stack"].std == pytest.approx(0.002, rel=1e-12)
    assert spreads["rider.chain.torso_lean"].std == pytest.approx(math.radians(3) / math.sqrt(3), rel=1e-12)
    assert spreads["mB"].std == 0.5


def test_built_values_and_matrices_are_inputs_too():
    """``bm.uncertainty`` of a loaded Bicycle and Rider, and of a stiffness given as a 2x2 list
    (once refused, once a raw TypeError), equals the same scenario given by name."""
    S = [[2.0e5, 1.0e4], [1.0e4, 3.0e4]]
    by_name = bm.uncertainty("benchmark", {"mB": 0.5}, stiffness=S)
    built = bm.uncertainty(bm.load_bicycle("benchmark"), {"mB": 0.5}, stiffness=np.array(S))
    for key in ("weave_speed", "capsize_speed"):
        assert built.speeds[key].nominal == pytest.approx(by_name.speeds[key].nominal, abs=1e-12)
        assert built.speeds[key].std == pytest.approx(by_name.speeds[key].std, rel=1e-12)
    flexible = bm.stability(bm.parameters("benchmark"), stiffness=np.array(S))
    assert by_name.speeds["weave_speed"].nominal == pytest.approx(flexible.weave_speeds[0], abs=1e-9)
    with pytest.raises(bm.InputError, match="a bicycle was given built, not as YAML|parameter names"):
        Scenario(bm.load_bicycle("benchmark")).build({"geometry.trail": 0.1})


@pytest.mark.parametrize("c, lam", [(0.12, 0.45), (0.0025, 0.2)])
def test_stability_sensitivity_and_a_sweep_row_give_the_same_critical_speeds(c, lam, tmp_path):
    """One engine behind the three: the same weave and capsize speed to 1e-9 m/s (the last a
    benchmark variant with a stable window narrower than the thesis's 0.05 m/s grid)."""
    import csv
    p = bm.parameters("benchmark").replace(c=c, lam=lam)
    stability = bm.stability(p)
    sensitivity = bm.sensitivity(p)
    spec = tmp_path / "one.yaml"
    spec.write_text(yaml.safe_dump({"name": "one", "bike": "benchmark", "vary": {"c": [c], "lam": [lam]}}))
    assert main(["sweep", str(spec), "--out", str(tmp_path / "out"), "--quiet"]) == 0
    row = next(csv.DictReader((tmp_path / "out" / "results.csv").open()))
    for name, speeds in (("weave_speed", stability.weave_speeds), ("capsize_speed", stability.capsize_speeds)):
        ours = getattr(sensitivity, name)
        if not speeds:
            assert ours is None and row[name] == ""
            continue
        assert ours == pytest.approx(speeds[0], abs=1e-9) and float(row[name]) == pytest.approx(speeds[0], abs=1e-9)


def test_a_segment_change_of_a_pose_re_seated_by_its_posture_is_refused_not_dropped():
    """The shipped Relaxed pose misses the Jamis's contacts, so it is re-seated by its ``posture:``, which
    places every segment afresh: a changed torso angle was dropped without a word (a sweep of it flat, its
    derivative 0). It is refused in one line naming the key and the keys that act; the posture's elbow
    acts (the weave speed moves), and with the pose kept as written (``allow_off_contact``) the torso angle
    moves the rear body's mass centre as a rotation of the torso about its top plane does."""
    scenario = Scenario("jamis", "relaxed")
    with pytest.raises(bm.InputError, match=r"rider\.segments\.torso\.angle: .*rider\.posture"):
        scenario.build({"rider.segments.torso.angle": "20 deg"})
    weaves = [bm.stability(scenario.build({"rider.posture.elbow": f"{a} deg"})).weave_speeds[0] for a in (20, 30)]
    assert abs(weaves[1] - weaves[0]) > 1e-3
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        written = Scenario("jamis", "relaxed", allow_off_contact=True)
        base = written.build().parameters
        turned = written.build({"rider.segments.torso.angle": "25.362 deg"}).parameters
    torso = next(part for part in bm.load_rider("relaxed").parts if part.name == "torso")
    top, com = torso.placement.translation, torso.mass_properties().com

    def turn(a):            # the pose file's angle: clockwise about y seen from +y (axis (-sin a, 0, cos a))
        return np.array([[math.cos(a), 0.0, -math.sin(a)], [0.0, 1.0, 0.0], [math.sin(a), 0.0, math.cos(a)]])
    moved = top + turn(math.radians(10.0)) @ (com - top)
    assert turned.mB == pytest.approx(base.mB, abs=1e-12)
    # the rear body's mass centre moves by the torso's mass times its mass centre's move, over mB
    assert turned.xB - base.xB == pytest.approx(torso.mass * (moved[0] - com[0]) / base.mB, abs=1e-9)
    assert turned.zB - base.zB == pytest.approx(torso.mass * (moved[2] - com[2]) / base.mB, abs=1e-9)


def _relaxed_with(tmp_path, name, edit):
    """The shipped Relaxed pose file with ``edit(doc)`` applied, written as ``name`` (its body resolved)."""
    doc = yaml.safe_load((poses_dir() / "relaxed.yaml").read_text())
    edit(doc)
    path = tmp_path / name
    path.write_text(yaml.safe_dump(doc, sort_keys=False))
    return str(path)


def test_a_posture_change_of_a_pose_used_as_written_is_refused_not_dropped():
    """A placement pose used as written (here allowed off the contacts) does not use its ``posture:``: a
    changed elbow gave the base result to the bit. It is refused in one line naming ``rider.segments``."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        scenario = Scenario("jamis", "relaxed", allow_off_contact=True)
        with pytest.raises(bm.InputError, match=r"rider\.posture\.elbow: .*rider\.segments"):
            scenario.build({"rider.posture.elbow": "40 deg"})


def test_what_re_seating_keeps_of_a_placement_pose_still_acts(tmp_path):
    """Re-seating by the posture places the body's segments afresh but keeps a segment's ``frame:`` (the
    posture names no ``front:``) and a lumped body where the file puts it: those changes act. The
    forearms moved to the rear frame take their mass off the front assembly (mH falls by the forearms'
    mass); a lumped 5 kg load is kept, warned of, and its mass changed adds to mB."""
    front = _relaxed_with(tmp_path, "front.yaml", lambda d: d["segments"]["lower_arm"].update(frame="front"))
    forearms = sum(p.mass for p in bm.load_rider("relaxed").parts if p.name.startswith("lower_arm"))
    scenario = Scenario("jamis", front)
    held, free = scenario.build().parameters, scenario.build({"rider.segments.lower_arm.frame": "rear"}).parameters
    assert held.mH - free.mH == pytest.approx(forearms, abs=1e-9)

    load = {"mass": "5 kg", "com": [0.2, 0.0, -1.2], "inertia": [[0.1, 0, 0], [0, 0.1, 0], [0, 0, 0.1]]}
    packed = _relaxed_with(tmp_path, "pack.yaml", lambda d: d["segments"].update(backpack=load))
    with pytest.warns(bm.BikemassWarning, match=r"backpack \(5 kg\) kept"):
        with_pack = Scenario("jamis", packed).build().parameters
    without = Scenario("jamis", "relaxed").build().parameters
    assert with_pack.mB - without.mB == pytest.approx(5.0, abs=1e-9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        heavier = Scenario("jamis", packed).build({"rider.segments.backpack.mass": "8 kg"}).parameters
    assert heavier.mB - with_pack.mB == pytest.approx(3.0, abs=1e-9)


def test_the_refusal_names_the_posture_keys_the_pose_has():
    """The refusal of a lost segment change lists the posture keys the file has (Relaxed: hands, elbow)."""
    with pytest.raises(bm.InputError, match=r"change rider\.posture\.hands, rider\.posture\.elbow"):
        Scenario("jamis", "relaxed").build({"rider.segments.head.angle": "20 deg"})
