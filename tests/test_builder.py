"""The one scenario builder and the model choice on every entry point.

The commands with ``--model`` are checked against independent references where they exist: the
benchmark Whipple bicycle against Meijaard et al. (2007)'s exact critical speeds; the leaning
rider against BicycleParameters' ``MooreRiderLean2012Model`` (Moore's own derivation, a peer that
shares no code with bikemass) on BicycleParameters' Browser + Jason set and on a bikemass scenario
exported in its YAML; the tyre member with very stiff tyres against the Whipple limit; the
flexible member with an infinite stiffness against the rigid model; every derivative through the
engine against a central difference of the critical speeds.  Tests named ``contract`` hold the
shell to the library on held-out cases (what the command prints is what the API returns).
"""

import json
import math

import numpy as np
import pytest
import yaml

import bikemass as bm
from bikemass.cli.main import main
from bikemass.scenario import inputs as scenario_inputs

DATA = __import__("pathlib").Path(__file__).parent / "data" / "bicycleparameters"
BROWSER_JASON = DATA / "to_yaml-MooreRiderLean2012-browserjason.yml"
MEIJAARD_WEAVE, MEIJAARD_CAPSIZE = 4.2923825363411040, 6.0242620153883589
"""Meijaard et al. (2007), Table 3 (the benchmark's exact critical speeds, m/s)."""
SPEEDS = [float(v) for v in range(1, 11)]


def run_json(capsys, *argv):
    assert main(list(argv)) == 0, capsys.readouterr().err
    return json.loads(capsys.readouterr().out)


def refused(capsys, *argv):
    """The one line a bad command line gets (exit status 2, nothing on stdout)."""
    status = main(list(argv))
    out, err = capsys.readouterr()
    assert status == 2 and out == "" and len(err.strip().splitlines()) == 1, (status, out, err)
    return err


# ------------------------------------------------------------------ independent references
def test_benchmark_whipple_equals_meijaard_2007_on_every_command(capsys):
    for named in ((), ("--model", "whipple")):                                   # default and named
        d = run_json(capsys, "stability", "benchmark", *named, "--format", "json")
        assert d["model"] == "whipple"
        assert d["weave_speeds"] == pytest.approx([MEIJAARD_WEAVE], abs=1e-12)
        assert d["capsize_speeds"] == pytest.approx([MEIJAARD_CAPSIZE], abs=1e-12)
    s = run_json(capsys, "sensitivity", "benchmark", "--model", "whipple", "--format", "json")
    assert (s["weave_speed"], s["capsize_speed"]) == pytest.approx((MEIJAARD_WEAVE, MEIJAARD_CAPSIZE), abs=1e-12)


def test_very_stiff_tyres_give_back_the_benchmark(capsys, tmp_path):
    """The knife-edge limit (docs/models.md, "Checks"): cornering coefficient 1e5 per rad, camber
    coefficient 1 per rad, relaxation length 1e-5 m; ``eig --model tyre --tyres FILE`` holds the
    benchmark's four eigenvalues at 1..10 m/s to 1e-3 relative and ``stability`` its capsize speed
    (Meijaard et al. 2007) to 1e-5 relative.  The default tyres move the weave speed."""
    stiff = tmp_path / "stiff.yaml"
    tyre = {"cornering_coefficient": "1e5 1/rad", "camber_coefficient": "1 1/rad", "relaxation_length": "1e-5 m"}
    stiff.write_text(yaml.safe_dump({"front": tyre, "rear": dict(tyre)}))
    tyres = command_eigenvalues(run_json(capsys, "eig", "benchmark", "--model", "tyre", "--tyres", str(stiff),
                                         "--speeds", "1:10:1", "--format", "json"))
    whipple = command_eigenvalues(run_json(capsys, "eig", "benchmark", "--speeds", "1:10:1", "--format", "json"))
    for v in SPEEDS:
        for z in whipple[v]:
            assert np.min(np.abs(tyres[v] - z)) <= 1e-3 * abs(z), (v, z)
    d = run_json(capsys, "stability", "benchmark", "--model", "tyre", "--tyres", str(stiff), "--speeds", "0:10:0.05",
                 "--format", "json")
    assert d["model"] == "tyre" and d["capsize_speeds"][0] == pytest.approx(MEIJAARD_CAPSIZE, rel=1e-5)
    default = run_json(capsys, "stability", "benchmark", "--model", "tyre", "--speeds", "0:10:0.05", "--format", "json")
    assert abs(default["weave_speeds"][0] - MEIJAARD_WEAVE) > 1e-3


@pytest.fixture(scope="module")
def bp():
    """BicycleParameters' models and parameter sets (the peer; the tests that need it skip without it)."""
    return pytest.importorskip("bicycleparameters.models"), pytest.importorskip("bicycleparameters.parameter_sets")


def peer_eigenvalues(bp, path, speed):
    """The non-zero eigenvalues of BicycleParameters' MooreRiderLean2012Model of a YAML set (6 of its
    12 are structurally zero)."""
    bp_models, bp_sets = bp
    model = bp_models.MooreRiderLean2012Model(bp_sets.MooreRiderLean2012ParameterSet._from_yaml(str(path)))
    A, _ = model.form_state_space_matrices(v=speed)
    ev = np.linalg.eigvals(A)
    return ev[np.abs(ev) > 1e-9 * np.max(np.abs(ev))]


def command_eigenvalues(document):
    """``{speed: eigenvalues}`` of ``bikemass eig --format json``."""
    speeds = document["speeds"]
    return {v: np.array([complex(*m["eigenvalues"][k]) for m in document["modes"]]) for k, v in enumerate(speeds)}


def assert_same_roots(mine, peer, rtol):
    assert len(mine) == len(peer) == 6
    for z in peer:
        assert np.min(np.abs(mine - z)) <= rtol * abs(z), (z, mine)


def test_rider_lean_on_browser_jason_equals_moore_rider_lean_2012(capsys, bp):
    """BicycleParameters' own Browser + Jason set read by ``bikemass eig FILE --model rider-lean``."""
    d = run_json(capsys, "eig", str(BROWSER_JASON), "--model", "rider-lean", "--speeds", "1:10:1", "--format", "json")
    ours = command_eigenvalues(d)
    for v in SPEEDS:
        assert_same_roots(ours[v], peer_eigenvalues(bp, BROWSER_JASON, v), 1e-9)


def test_a_bikemass_rider_exported_with_params_equals_moore_rider_lean_2012(capsys, tmp_path, bp):
    """Held out: the Cargo with a person (height, mass, sex) split at the hips, written by ``params
    --model rider-lean --format bicycleparameters-yaml`` and read by BicycleParameters; its model's
    eigenvalues are ``bikemass eig``'s on the same scenario."""
    person = tmp_path / "person.yaml"
    person.write_text("body: {height: 1.72 m, mass: 66 kg, sex: female}\nchain: {hands: hoods}\n")
    out = tmp_path / "cargo_lean.yml"
    assert main(["params", "cargo", "--rider", str(person), "--model", "rider-lean", "--format",
                 "bicycleparameters-yaml", "-o", str(out)]) == 0, capsys.readouterr().err
    capsys.readouterr()
    assert yaml.safe_load(out.read_text())["parameterization"] == "MooreRiderLean2012"
    d = run_json(capsys, "eig", "cargo", "--rider", str(person), "--model", "rider-lean", "--speeds", "1:10:1",
                 "--format", "json")
    ours = command_eigenvalues(d)
    for v in SPEEDS:
        assert_same_roots(ours[v], peer_eigenvalues(bp, out, v), 1e-9)


def test_the_meijaard2007_yaml_is_read_by_bicycleparameters_with_the_same_eigenvalues(capsys, tmp_path, bp):
    bp_models, bp_sets = bp
    out = tmp_path / "jamis.yml"
    assert main(["params", "jamis", "--rider", "aero-tuck", "--format", "bicycleparameters-yaml", "-o", str(out)]) == 0
    capsys.readouterr()
    peer = bp_models.Meijaard2007Model(bp_sets.Meijaard2007ParameterSet._from_yaml(str(out)))
    theirs = peer.calc_eigen(v=np.array(SPEEDS))[0]
    ours = command_eigenvalues(run_json(capsys, "eig", "jamis", "--rider", "aero-tuck", "--speeds", "1:10:1",
                                        "--format", "json"))
    for k, v in enumerate(SPEEDS):
        for z in theirs[k]:
            assert np.min(np.abs(ours[v] - z)) <= 1e-9 * abs(z), (v, z)


def test_flexible_with_an_infinite_stiffness_is_the_rigid_model(capsys):
    rigid = command_eigenvalues(run_json(capsys, "eig", "jamis", "--rider", "relaxed", "--speeds", "1:10:1",
                                         "--format", "json"))
    held = command_eigenvalues(run_json(capsys, "eig", "jamis", "--rider", "relaxed", "--model", "flexible",
                                        "--stiffness", "infinite", "--speeds", "1:10:1", "--format", "json"))
    for v in SPEEDS:
        assert len(held[v]) == len(rigid[v]) == 4
        for z in rigid[v]:
            assert np.min(np.abs(held[v] - z)) <= 1e-9 * abs(z)


# ------------------------------------------------------------------ derivatives through the engine
def crossings(scenario, changes=None):
    """(weave, capsize) of ``bm.stability`` of the scenario built with ``changes``: the first of each."""
    result = bm.stability(scenario.build(changes), speeds=bm.speeds(0, 15, 0.05))
    return result.weave_speeds[0], result.capsize_speeds[0]


@pytest.mark.parametrize("model, rider", [("rider-lean", "relaxed"), ("tyre", "on-hoods")])
def test_member_sensitivity_equals_a_central_difference_of_stability(model, rider):
    """``bm.sensitivity`` of a member through the engine: its critical speeds are ``bm.stability``'s
    (1e-9 m/s) and its derivatives a central difference of them (the trail and the rear frame's mass
    of the set the model takes)."""
    scenario = bm.Scenario("jamis", rider, model=model)
    result = bm.sensitivity(scenario, max_speed=15.0)
    weave, capsize = crossings(scenario)
    assert result.weave_speed == pytest.approx(weave, abs=1e-9)
    assert result.capsize_speed == pytest.approx(capsize, abs=1e-9)
    for name in ("c", "mB"):
        x = scenario.value(name)
        h = 1e-4 * abs(x)
        (wa, ca), (wb, cb) = crossings(scenario, {name: x + h}), crossings(scenario, {name: x - h})
        assert result.d_weave_speed[name] == pytest.approx((wa - wb) / (2 * h), rel=1e-5), name
        assert result.d_capsize_speed[name] == pytest.approx((ca - cb) / (2 * h), rel=1e-5), name


def test_member_uncertainty_is_first_order_in_the_spread():
    """``bm.uncertainty`` of the leaning rider (linear): the std of the weave speed is |dv/dx| sigma
    with dv/dx a central difference of ``bm.stability`` on the changed head angle of the Jamis."""
    scenario = bm.Scenario("jamis", "relaxed", model="rider-lean")
    key, sigma = "geometry.head_angle", math.radians(0.5)
    result = bm.uncertainty(scenario, {key: sigma}, speeds=np.array([2.0, 5.0]))
    x = scenario.value(key)
    h = 1e-4 * abs(x)
    (wa, _), (wb, _) = crossings(scenario, {key: x + h}), crossings(scenario, {key: x - h})
    assert result.speeds["weave_speed"].nominal == pytest.approx(crossings(scenario)[0], abs=1e-9)
    assert result.speeds["weave_speed"].std == pytest.approx(abs(wa - wb) / (2 * h) * sigma, rel=1e-4)
    n = scenario.build().model.n_dynamic                  # a member's matrices: its state matrix's coefficients
    assert sorted(result.matrices) == ["A0", "A1", "A2"]
    assert all(result.matrices[k]["nominal"].shape == (n, n) for k in result.matrices)


def test_a_sweep_row_of_a_member_is_the_member_on_the_changed_parameter_set(tmp_path):
    """A sweep with ``model: tyre`` varying the trail: each row's critical speeds are those of the
    benchmark set with that trail, built by ``bm.stability(params, model="tyre")`` (no scenario)."""
    spec = tmp_path / "spec.yaml"
    spec.write_text("bike: benchmark\nmodel: tyre\nmax_speed: 15\nvary:\n  c: [0.06, 0.09]\n")
    rows = bm.sweep(str(spec), tmp_path / "out")
    p = bm.parameters("benchmark")
    for row in rows:
        reference = bm.stability(p.replace(c=row["c"]), speeds=bm.speeds(0, 15, 0.05), model="tyre")
        assert row["error"] is None
        assert row["weave_speed"] == pytest.approx(reference.weave_speeds[0], abs=1e-9)
        assert row["capsize_speed"] == pytest.approx(reference.capsize_speeds[0], abs=1e-9)


# ------------------------------------------------------------------ contract tests (shell = library)
@pytest.mark.parametrize("model, rider, stiffness", [("rider-lean", "aero-tuck", "infinite"),
                                                     ("tyre", "relaxed", "infinite"),
                                                     ("rider-lean+tyre", "on-hoods", "infinite"),
                                                     ("flexible", "relaxed", "titanium")])
def test_contract_stability_command_is_the_library(capsys, model, rider, stiffness):
    d = run_json(capsys, "stability", "jamis", "--rider", rider, "--model", model, "--stiffness", stiffness,
                 "--speeds", "0:15:0.05", "--format", "json")
    result = bm.stability(bm.Scenario("jamis", rider, stiffness, model=model), speeds=bm.speeds(0, 15, 0.05))
    assert d["model"] == model
    assert [c["speed"] for c in d["crossings"]] == pytest.approx([c.speed for c in result.crossings], abs=1e-12)
    assert [c["kind"] for c in d["crossings"]] == [c.kind for c in result.crossings]
    assert d["units"]["frequency"] == "rad/s" and d["units"]["weave_speeds"] == "m/s"      # declared, not guessed


def test_contract_handling_commands_take_the_model(capsys):
    shapes = run_json(capsys, "mode-shapes", "jamis", "--rider", "relaxed", "--model", "rider-lean", "--speed", "5",
                      "--format", "json")
    built = bm.Scenario("jamis", "relaxed", model="rider-lean").build()
    assert "lean-angle" in shapes["coordinates"]
    roots = np.linalg.eigvals(built.model.dynamic_matrix(5.0))
    for mode in shapes["modes"]:
        assert np.min(np.abs(roots - complex(*mode["eigenvalue"]))) < 1e-9 * np.max(np.abs(roots))
    tf = run_json(capsys, "tf", "jamis", "--rider", "relaxed", "--model", "rider-lean", "--speed", "5",
                  "--input", "lean-torque", "--output", "roll-angle", "--format", "json")
    ours = bm.transfer_function(built.model, 5.0, "lean-torque", "roll-angle")
    assert tf["gain"] == pytest.approx(ours.gain, rel=1e-12)


def test_contract_the_api_takes_the_model_choice():
    p = bm.parameters("benchmark")
    by_name = bm.stability(p, model="tyre")
    by_scenario = bm.stability(bm.Scenario("benchmark", model="tyre"))
    assert by_name.model.name == "tyre"
    assert by_name.weave_speeds == pytest.approx(by_scenario.weave_speeds, abs=1e-12)
    assert bm.eigenvalues(p, model="tyre", speeds=[5.0]).eigenvalues.shape == (1, 8)
    with pytest.raises(bm.InputError, match="rider split at the hips"):
        bm.stability(p, model="rider-lean")
    with pytest.raises(bm.InputError, match="a Scenario for the flexible member"):
        bm.stability(p, model="flexible")


# ------------------------------------------------------------------ bad choices: one line, exit 2
@pytest.mark.parametrize("argv, says", [
    (["stability", "benchmark", "--model", "wobble"], "unknown model 'wobble'"),
    (["eig", "benchmark", "--model", "tyre+tyre"], "'tyre' given twice"),
    (["stability", "benchmark", "--tyres", "tyres.yaml"], "--tyres: tyres.yaml: a --model with the tyre member"),
    (["stability", "jamis", "--rider", "relaxed", "--model", "rider-lean", "--stiffness", "steel"],
     "infinite (rigid) with the model rider-lean"),
    (["stability", "jamis", "--model", "rider-lean"], "a rider for the rider-lean model"),
    (["params", "benchmark", "--model", "tyre", "--format", "bicycleparameters-yaml"],
     "BicycleParameters has no parameter set for --model tyre"),
    (["sensitivity", "benchmark", "--model", "flexible", "--stiffness", "steel"], "structure"),
    (["tf", "benchmark", "--speed", "5", "--input", "lean-torque", "--output", "roll-angle"], "--input: lean-torque"),
])
def test_bad_model_choices_are_one_line(capsys, argv, says):
    assert says in refused(capsys, *argv)


def test_a_missing_tyre_file_names_it(capsys, tmp_path):
    err = refused(capsys, "stability", "benchmark", "--model", "tyre", "--tyres", str(tmp_path / "none.yaml"))
    assert "none.yaml" in err


# ------------------------------------------------------------------ one builder, every entry point
ENTRY_POINTS = [
    ["params", "benchmark", "--model", "tyre"],
    ["stability", "benchmark", "--model", "tyre", "--speeds", "0:2:1"],
    ["eig", "benchmark", "--model", "tyre", "--speeds", "0:2:1"],
    ["compare", "benchmark", "--model", "tyre", "--speeds", "0:2:1"],
    ["sensitivity", "benchmark", "--model", "tyre"],
    ["uncertainty", "benchmark", "--model", "tyre", "--speeds", "0:2:1", "--std", "STD"],
    ["tf", "benchmark", "--model", "tyre", "--speed", "5", "--input", "steer-torque", "--output", "roll-angle"],
    ["bode", "benchmark", "--model", "tyre", "--speed", "5", "--input", "steer-torque", "--output", "roll-angle",
     "--frequencies", "1:10:3"],
    ["simulate", "benchmark", "--model", "tyre", "--speed", "5", "--duration", "0.1"],
    ["mode-shapes", "benchmark", "--model", "tyre", "--speed", "5"],
    ["handling", "benchmark", "--model", "tyre", "--speeds", "5"],
]


@pytest.mark.parametrize("argv", ENTRY_POINTS, ids=lambda a: a[0])
def test_every_command_builds_through_the_scenario(argv, capsys, monkeypatch, tmp_path):
    """Each command's parameter set comes from the scenario's inputs (``Inputs.parameters``), and the
    model it analyses is the chosen member."""
    std = tmp_path / "std.yaml"
    std.write_text("uncertainty:\n  c: 0.001\n")
    seen = []
    original = scenario_inputs.Inputs.parameters

    def recorded(self, *args, **kwargs):
        seen.append(self.bike)
        return original(self, *args, **kwargs)
    monkeypatch.setattr(scenario_inputs.Inputs, "parameters", recorded)
    assert main([str(std) if a == "STD" else a for a in argv] + ["--format", "json"]) == 0, capsys.readouterr().err
    out = capsys.readouterr().out
    assert seen and set(seen) == {"benchmark"}
    if argv[0] in ("stability",):
        assert json.loads(out)["model"] == "tyre"


def test_the_web_page_takes_the_model(tmp_path):
    pytest.importorskip("dash")
    from bikemass.web.engine import Engine
    from bikemass.web.state import PageState
    engine = Engine()
    state = PageState.from_query({"bike": "jamis", "rider": "relaxed", "model": "rider-lean+tyre"})
    assert state.model == "rider-lean+tyre" and "model=rider-lean%2Btyre" in state.to_query()
    result, _ = engine.answer(engine.evaluate, state)
    reference = bm.stability(bm.Scenario("jamis", "relaxed", model="rider-lean+tyre"))
    assert result.stability.model.name == "rider-lean+tyre"
    assert result.stability.weave_speeds == pytest.approx(reference.weave_speeds, abs=1e-12)
    with pytest.raises(bm.InputError, match="URL: model: one of whipple, rider-lean"):
        PageState.from_query({"model": "wobble"})
