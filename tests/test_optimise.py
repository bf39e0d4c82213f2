"""``bm.optimise`` and ``bikemass optimise`` against references that know nothing of the optimiser: a
root finder on ``bm.stability`` (a target), a 10 x 10 grid of the same box (a maximum), central
differences of whole analyses (the gradients), and the design file read back by ``bikemass stability``.
"""

import json
import math

import numpy as np
import pytest
import yaml
from scipy.optimize import brentq

import bikemass as bm
from bikemass.cli.main import main
from bikemass.design.figures import objective_slices, plot_optimisation
from bikemass.design.metrics import catalogue, metric
from bikemass.design.optimise import _kinks
from bikemass.design.problem import Problem
from bikemass.design.spec import DesignVariable, OptimiseSpec, read_spec

PERSON = {"name": "a person", "body": {"height": "1.75 m", "mass": "70 kg", "sex": "male"},
          "chain": {"torso_lean": "45 deg", "hands": "hoods"}}
"""A person re-seated on every design (a chain pose without a bicycle)."""


@pytest.fixture
def person(tmp_path):
    path = tmp_path / "person.yaml"
    path.write_text(yaml.safe_dump(PERSON))
    return path


def write_spec(tmp_path, doc):
    path = tmp_path / "spec.yaml"
    path.write_text(yaml.safe_dump(doc, sort_keys=False))
    return path


def test_a_target_on_a_benchmark_parameter_is_the_root_of_the_stability_analysis():
    """Trail for a weave speed of 5 m/s: the optimiser's answer is the root brentq finds on bm.stability
    (to 1e-9 m: both converge far below it)."""
    p = bm.parameters("benchmark")
    root = brentq(lambda c: bm.stability(p.replace(c=c)).weave_speeds[0] - 5.0, 0.1, 0.2, xtol=1e-14)
    spec = OptimiseSpec(source="test", bike="benchmark", variables=(DesignVariable("c", 0.02, 0.2),),
                        sense="target", objective="weave-speed", target=5.0)
    result = bm.optimise(spec)
    assert result.converged
    assert result.variables["c"] == pytest.approx(root, abs=1e-9)
    assert result.objective == pytest.approx(5.0, abs=1e-8)


@pytest.mark.slow
def test_a_target_over_a_chart_head_angle_with_a_person_matches_a_bisection(tmp_path, person):
    """Issue 34: target weave-speed 5.0 over a chart's head angle, a person re-seated on every design: the
    head angle a bisection on the stability analysis of the same scenario gives, within 0.005 deg."""
    spec = write_spec(tmp_path, {"bike": "bmc-roadmachine@54", "rider": str(person),
                                 "variables": {"chart.head_tube_angle": {"min": "70 deg", "max": "75 deg"}},
                                 "target": {"weave-speed": 5.0}})
    result = bm.optimise(spec)
    scenario = bm.Scenario("bmc-roadmachine@54", str(person))

    def weave(deg):
        built = scenario.build({"chart.head_tube_angle": f"{deg!r} deg"})
        return bm.stability(built).weave_speeds[0] - 5.0
    bisected = brentq(weave, 70.0, 75.0, xtol=1e-6)
    assert result.converged
    assert math.degrees(result.variables["chart.head_tube_angle"]) == pytest.approx(bisected, abs=0.005)


@pytest.mark.slow
def test_the_widest_stable_range_is_at_least_the_best_of_a_10_by_10_sweep(tmp_path, person):
    """Issue 34: maximise the stable range over head angle and fork offset with the trail in 50-70 mm: at
    least the best design of a 10 x 10 grid of the same box whose trail is within the bounds."""
    doc = {"bike": "bmc-roadmachine@54", "rider": str(person),
           "variables": {"chart.head_tube_angle": {"min": "70 deg", "max": "75 deg"},
                         "chart.fork_offset": {"min": "35 mm", "max": "60 mm"}},
           "maximise": "stable-range", "constraints": {"trail": {"min": "50 mm", "max": "70 mm"}}}
    result = bm.optimise(write_spec(tmp_path, doc))
    scenario = bm.Scenario("bmc-roadmachine@54", str(person))
    best = -np.inf
    for angle in np.linspace(70, 75, 10):
        for offset in np.linspace(35, 60, 10):
            built = scenario.build({"chart.head_tube_angle": f"{float(angle)!r} deg",
                                   "chart.fork_offset": f"{float(offset)!r} mm"})
            if not 0.050 <= built.parameters.c <= 0.070:
                continue
            ranges = bm.stability(built).stable_speeds
            if ranges:
                best = max(best, max(b - a for a, b in ranges))
    assert best > 0
    assert result.converged
    assert result.objective >= best - 1e-9
    assert 0.050 - 1e-9 <= result.metrics["trail"] <= 0.070 + 1e-9


def test_gradients_equal_central_differences_of_whole_analyses():
    """The weave speed's and the stable range's gradients (exact in the parameters) against central
    differences of bm.stability (relative 1e-6: the differences' own error)."""
    variables = (DesignVariable("c", 0.02, 0.2), DesignVariable("lam", 0.2, 0.4), DesignVariable("mB", 60, 100))
    spec = OptimiseSpec(source="test", bike="benchmark", variables=variables, sense="maximise",
                        objective="stable-range")
    problem = Problem(spec)
    x = np.array([0.08, np.pi / 10, 85.0])
    p = bm.parameters("benchmark")

    def analysed(xx):
        r = bm.stability(p.replace(c=xx[0], lam=xx[1], mB=xx[2]))
        return r.weave_speeds[0], max(b - a for a, b in r.stable_speeds)
    for k in range(3):
        h = 1e-6 * abs(x[k])
        step = np.eye(3)[k] * h
        up, down = analysed(x + step), analysed(x - step)
        for j, name in enumerate(("weave-speed", "stable-range")):
            exact = problem.gradient(metric(name), x)[k]
            assert exact == pytest.approx((up[j] - down[j]) / (2 * h), rel=1e-6)


def test_parameter_metrics_and_their_gradients_are_the_closed_forms():
    """Wheel flop c sin(lam) cos(lam) and the front load x_T / w with their derivatives by hand."""
    variables = (DesignVariable("c", 0.02, 0.2), DesignVariable("lam", 0.2, 0.4), DesignVariable("w", 0.9, 1.2))
    spec = OptimiseSpec(source="test", bike="benchmark", variables=variables, sense="minimise",
                        objective="wheel-flop")
    problem = Problem(spec)
    c, lam, w = x = np.array([0.08, np.pi / 10, 1.02])
    assert problem.value(metric("wheel-flop"), x) == pytest.approx(c * np.sin(lam) * np.cos(lam), rel=1e-15)
    assert problem.gradient(metric("wheel-flop"), x) == pytest.approx(
        [np.sin(lam) * np.cos(lam), c * np.cos(2 * lam), 0.0], rel=1e-12, abs=1e-15)
    p = bm.parameters("benchmark")
    mass = p.mR + p.mB + p.mH + p.mF
    moment = p.xB * p.mB + p.xH * p.mH + w * p.mF
    assert problem.value(metric("front-load"), x) == pytest.approx(moment / mass / w, rel=1e-14)
    assert problem.gradient(metric("front-load"), x)[2] == pytest.approx(-(moment - w * p.mF) / mass / w ** 2,
                                                                          rel=1e-12)


def test_a_kink_is_found_and_a_smooth_point_is_not():
    """The kink check on |u - 0.4| (a kink at 0.4) and on a parabola (smooth)."""
    spec = OptimiseSpec(source="test", bike="benchmark", variables=(DesignVariable("c", 0.0, 1.0),),
                        sense="minimise", objective="trail")
    assert _kinks(lambda u: abs(u[0] - 0.4), np.array([0.4]), 1, spec, 1.0) == ["c"]
    assert _kinks(lambda u: (u[0] - 0.4) ** 2, np.array([0.4]), 1, spec, 1.0) == []


def test_the_command_writes_json_and_a_design_that_reads_back(tmp_path, capsys):
    """bikemass optimise --format json -o: the JSON keys of the issue, and the design file read back by
    bikemass stability gives the reported objective (1e-9 m/s)."""
    spec = write_spec(tmp_path, {"bike": "benchmark", "variables": {"c": {"min": 0.05, "max": 0.12},
                                                                    "mH": {"min": 2.0, "max": 6.0}},
                                 "maximise": "stable-range", "constraints": {"trail": {"max": "100 mm"}}})
    design = tmp_path / "best.yaml"
    assert main([ "optimise", str(spec), "--format", "json", "-o", str(design), "--quiet"]) == 0
    assert main(["optimise", str(spec), "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    for key in ("variables", "objective", "metrics", "converged", "evaluations", "history", "units"):
        assert key in doc
    assert doc["metrics"]["trail"] <= 0.1 + 1e-9
    assert main(["stability", str(design), "--format", "json"]) == 0
    read_back = json.loads(capsys.readouterr().out)
    ranges = read_back["ranges"]["strict"]["exact"]
    assert max(b - a for a, b in ranges) == pytest.approx(doc["objective"], abs=1e-9)


def test_a_member_model_design_reads_back_as_its_model(tmp_path, capsys):
    """A design of the tyre model over the 26 parameters is written with its model and the tyres' block:
    ``bikemass stability`` of the file, no option given, gives the reported weave speed of the tyre model
    (1e-9 m/s), not the Whipple bicycle's (it was the Whipple bicycle, without a word)."""
    spec = write_spec(tmp_path, {"bike": "benchmark", "model": "tyre",
                                 "variables": {"c": {"min": 0.05, "max": 0.12}}, "maximise": "weave-speed"})
    design = tmp_path / "best.yaml"
    assert main(["optimise", str(spec), "--format", "json", "-o", str(design)]) == 0
    objective = json.loads(capsys.readouterr().out)["objective"]
    assert yaml.safe_load(design.read_text())["model"] == "tyre"
    assert main(["stability", str(design), "--format", "json"]) == 0
    read_back = json.loads(capsys.readouterr().out)
    assert read_back["model"] == "tyre"
    assert read_back["weave_speeds"][0] == pytest.approx(objective, abs=1e-9)
    whipple = bm.stability(bm.parameters("benchmark").replace(c=bm.parameters(str(design)).c))
    assert abs(whipple.weave_speeds[0] - objective) > 0.01


def test_a_bicycle_file_design_of_a_member_model_names_the_options_to_read_it_back(tmp_path, capsys):
    """A design whose variables are all in the bicycle file is the bicycle file: its model and members'
    files are not in it, and one warning names the options that analyse it as the spec did."""
    spec = write_spec(tmp_path, {"bike": "bmc-roadmachine@54", "model": "tyre",
                                 "variables": {"chart.head_tube_angle": {"min": "72 deg", "max": "73 deg"}},
                                 "minimise": "trail"})
    design = tmp_path / "best.yaml"
    assert main(["optimise", str(spec), "-o", str(design), "--quiet"]) == 0
    warned = capsys.readouterr().err.strip().splitlines()
    assert len(warned) == 1 and "warning" in warned[0] and "--model tyre" in warned[0]
    assert "chart" in yaml.safe_load(design.read_text())


def test_a_bicycle_file_design_names_every_option_and_strict_writes_nothing(tmp_path, capsys):
    """A bicycle-file design of a spec with a rider and ``combine: thesis``: the header and the one warning
    name ``--rider relaxed --combine thesis``, and those options give the reported objective (1e-9 m/s;
    without ``--combine thesis`` it differs). Under ``--strict`` the warning is an error before anything is
    written."""
    spec = write_spec(tmp_path, {"bike": "jamis", "rider": "relaxed", "combine": "thesis",
                                 "variables": {"sections.seat_stay.wall": {"min": "0.035 in", "max": "0.045 in"}},
                                 "maximise": "weave-speed"})
    design = tmp_path / "best.yaml"
    assert main(["optimise", str(spec), "-o", str(design), "--format", "json"]) == 0
    out = capsys.readouterr()
    objective = json.loads(out.out)["objective"]
    assert "--rider relaxed --combine thesis" in out.err
    assert "# analysed as the spec did with: --rider relaxed --combine thesis" in design.read_text()
    weave = {}
    for combine in ("thesis", "exact"):
        assert main(["stability", str(design), "--rider", "relaxed", "--combine", combine, "--format", "json"]) == 0
        weave[combine] = json.loads(capsys.readouterr().out)["weave_speeds"][0]
    assert weave["thesis"] == pytest.approx(objective, abs=1e-9)
    assert abs(weave["exact"] - objective) > 1e-3
    strict = tmp_path / "strict.yaml"
    assert main(["optimise", str(spec), "-o", str(strict), "--strict", "--quiet"]) == 2
    assert not strict.exists()


def test_a_changed_trail_is_written_as_the_parameter_set_that_reads_back(tmp_path, capsys):
    """A design over ``geometry.trail`` of a keypoint bicycle: the changed bicycle file would contradict
    its head-tube keypoints when read as a file (a search leaves them in place), so the parameter set is
    written; ``bikemass stability`` of it (with the spec's speeds, which the warning names) hits the
    target to 1e-6 m/s."""
    spec = write_spec(tmp_path, {"bike": "jamis", "rider": "relaxed", "max_speed": 20,
                                 "variables": {"geometry.trail": {"min": "50 mm", "max": "70 mm"}},
                                 "target": {"weave-speed": 5.5}})
    design = tmp_path / "best.yaml"
    assert main(["optimise", str(spec), "-o", str(design), "--quiet"]) == 0
    assert "--speeds 0:20:0.05" in capsys.readouterr().err
    assert "c" in yaml.safe_load(design.read_text())
    assert main(["stability", str(design), "--speeds", "0:20:0.05", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["weave_speeds"][0] == pytest.approx(5.5, abs=1e-6)


@pytest.mark.parametrize("doc, key", [
    ({"bike": "benchmark", "variables": {"c": {"min": 0.1, "max": 0.05}}, "maximise": "stable-range"}, "variables.c"),
    ({"bike": "benchmark", "variables": {"c": {"min": 0.05, "max": 0.1}}, "maximise": "speed"}, "maximise"),
    ({"bike": "benchmark", "variables": {"c": {"min": 0.05, "max": 0.1}}}, "maximise"),
    ({"bike": "benchmark", "variables": {"nothing.here": {"min": 1, "max": 2}}, "maximise": "trail"},
     "variables.nothing.here"),
    ({"bike": "benchmark", "variables": {"c": {"min": 0.05, "max": 0.1}}, "minimise": "trail",
      "constraints": {"trail": {"min": "3 kg"}}}, "constraints.trail.min"),
])
def test_a_bad_spec_is_one_line_naming_the_key(tmp_path, capsys, doc, key):
    spec = write_spec(tmp_path, doc)
    assert main(["optimise", str(spec)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and key in err and str(spec) in err


@pytest.mark.parametrize("doc, words", [
    ({"bike": "nosuchbike"}, "nosuchbike: (name): a bicycle file or one of"),
    ({"bike": "jamis", "rider": "nosuch.yaml"}, "nosuch.yaml: (file): an existing pose file"),
])
def test_a_bicycle_or_rider_that_does_not_build_is_its_own_error_as_in_a_sweep(tmp_path, capsys, doc, words):
    """Not 'variables: a box whose centre can be built: ...' (the box is fine)."""
    spec = write_spec(tmp_path, {**doc, "variables": {"c": {"min": 0.05, "max": 0.1}}, "maximise": "stable-range"})
    assert main(["optimise", str(spec)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and "centre" not in err


def test_a_search_that_reaches_an_unbuildable_design_keeps_its_start_and_says_why():
    """A box wider than bicycles (lam to 3 rad, beyond the horizontal steer axis at pi/2): the search
    stops where a design cannot be built; the answer is its start (built by the screening, within
    (-pi/2, pi/2)), not converged, the message naming the key, and no false 'no design met every
    constraint' (there are none)."""
    spec = OptimiseSpec(source="test", bike="benchmark", variables=(DesignVariable("lam", -3.0, 3.0),),
                        sense="maximise", objective="stable-range")
    result = bm.optimise(spec)
    assert abs(result.variables["lam"]) < math.pi / 2 and not result.converged
    assert "lam" in result.message and not any("constraint" in note for note in result.notes)


def test_every_metric_has_a_unit_and_a_description():
    for m in catalogue().values():
        assert m.unit and m.description and m.kind in ("speed", "parameters", "geometry", "handling")


def test_the_figure_shows_the_convergence_and_the_slices(tmp_path):
    """The figure: two panels, the history's points on the first (decoded from the artists, not a file)."""
    spec = OptimiseSpec(source="test", bike="benchmark", variables=(DesignVariable("c", 0.02, 0.2),),
                        sense="maximise", objective="stable-range")
    result = bm.optimise(spec)
    slices = objective_slices(spec, result, points=7)
    assert slices.values.shape == (1, 7) and np.all(np.isfinite(slices.values))
    fig = plot_optimisation(result, slices, "benchmark")
    first, second = fig.axes
    plotted = np.concatenate([line.get_ydata() for line in first.lines[:1]])
    assert len(plotted) == sum(h.violation <= 1e-6 for h in result.history)
    assert "m/s" in first.get_ylabel() and "m/s" in second.get_ylabel()


def test_read_spec_takes_units_and_paths_next_to_the_spec(tmp_path, person):
    spec = read_spec(write_spec(tmp_path, {"bike": "bmc-roadmachine@54", "rider": "person.yaml",
                                           "variables": {"chart.fork_offset": {"min": "35 mm", "max": 60}},
                                           "target": {"weave-speed": "18 km/h"}}))
    assert spec.rider == str(person.resolve())
    assert spec.target == pytest.approx(5.0)
    (variable,) = spec.variables
    assert (variable.low, variable.high, variable.unit) == (pytest.approx(0.035), pytest.approx(0.06), "m")


@pytest.mark.slow
def test_the_optimal_handling_bicycle_at_4_m_s_beats_the_published_one(tmp_path, capsys):
    """Issue 34 / Moore, Hubbard & Hess (2016): minimising the HQM peak at 4 m/s over c, w, lam, rF from the
    benchmark (tuning bmd2016) reaches a peak no higher than the paper's optimum for 4 m/s (its Table 2: c, w,
    lam, rF = -0.206, 1.103, 0.265, 0.477) scored by the same code (0.635), the closed loop stable; and the
    reported objective is what bikemass handling --tuning bmd2016 gives the reported design (1e-9).  Four
    starts: the HQM peak under a stable closed loop has many local minima (the paper's own words), and a
    search from two starts reaches the published level on most orders and seeds of the box, not all."""
    spec = write_spec(tmp_path, {"bike": "benchmark", "speed": 4.0, "tuning": "bmd2016",
                                 "variables": {"c": {"min": -0.5, "max": 0.5}, "w": {"min": 0.327, "max": 2.0},
                                               "lam": {"min": -1.5, "max": 1.5}, "rF": {"min": 0.05, "max": 1.0}},
                                 "minimise": "hqm-peak", "starts": 4})
    result = bm.optimise(spec)
    published = bm.parameters("benchmark").replace(c=-0.206, w=1.103, lam=0.265, rF=0.477)
    score = bm.handling(published, [4.0], tuning="bmd2016").hqm_peak[0]
    assert result.objective <= score
    assert result.metrics["closed-loop-real"] < 0
    design = tmp_path / "design.yaml"
    design.write_text(yaml.safe_dump({**bm.parameters("benchmark").to_dict(), **result.variables}))
    assert main(["handling", str(design), "--speeds", "4", "--tuning", "bmd2016", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["hqm_peak"][0] == pytest.approx(result.objective, rel=1e-9)


def test_an_objective_the_model_has_nowhere_in_the_box_is_refused(tmp_path, capsys):
    """Maximising the wobble speed of the Whipple bicycle (it has no wobble anywhere) reported "converged yes" at
    the span's limit; it is refused in one line naming the spec, the key and what the metric needs."""
    spec = tmp_path / "o.yaml"
    spec.write_text("bike: benchmark\nvariables:\n  c: {min: 0.05, max: 0.12}\nmaximise: wobble-speed\n")
    assert main(["optimise", str(spec), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and str(spec) in err[0] and "maximise: a metric that exists somewhere in the box" in err[0]
    assert "flexible member" in err[0]


def test_a_target_the_box_cannot_reach_is_not_converged(tmp_path):
    """A weave speed of 5 km/h (1.39 m/s) lies below every trail of the box (the nearest, c = 0.05 m, gives 3.9 m/s
    by a brentq of bm.stability's weave speed over c: none reaches it): not converged, and a note says so; a
    target inside the box is reached and converged."""
    def weave(c):
        return bm.stability(bm.parameters("benchmark").replace(c=c)).weave_speeds[0]
    assert min(weave(0.05), weave(0.12)) > 5 / 3.6
    spec = tmp_path / "o.yaml"
    spec.write_text("bike: benchmark\nvariables:\n  c: {min: 0.05, max: 0.12}\ntarget: {weave-speed: 5 km/h}\n")
    result = bm.optimise(str(spec))
    assert not result.converged and any("not reached in the box" in note for note in result.notes)
    assert result.objective == pytest.approx(weave(0.05), rel=1e-6)
    spec.write_text("bike: benchmark\nvariables:\n  c: {min: 0.05, max: 0.12}\ntarget: {weave-speed: 4.5}\n")
    reached = bm.optimise(str(spec))
    c = brentq(lambda c: weave(c) - 4.5, 0.05, 0.12, xtol=1e-14)
    assert reached.converged and reached.variables["c"] == pytest.approx(c, rel=1e-6)


def test_a_design_where_the_objective_does_not_exist_is_not_converged_and_a_constraint_that_never_exists_is_refused(
        tmp_path, capsys):
    """A capsize-speed target of 30 m/s (the span's end, the stand-in for no crossing) reached at a negative
    trail, where the benchmark has no capsize crossing at all (checked by bm.stability there), said "converged
    yes"; it is not converged, and a note says the value is the stand-in. A constraint on the wobble speed of
    the Whipple bicycle (none anywhere) is refused in one line, as such an objective is."""
    spec = tmp_path / "o.yaml"
    spec.write_text("bike: benchmark\nvariables:\n  c: {min: -0.1, max: 0.1}\ntarget: {capsize-speed: 30}\n")
    result = bm.optimise(str(spec))
    assert not bm.stability(bm.parameters("benchmark").replace(c=result.variables["c"])).capsize_speeds
    assert not result.converged and any("does not exist at the design found" in n for n in result.notes)
    spec.write_text("bike: benchmark\nvariables:\n  c: {min: 0.05, max: 0.1}\nmaximise: stable-range\n"
                    "constraints:\n  wobble-speed: {min: 10}\n")
    assert main(["optimise", str(spec), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "constraints.wobble-speed: a metric that exists somewhere in the box" in err[0]


def test_a_design_of_a_set_that_holds_its_rider_says_so(tmp_path):
    """The benchmark's set holds its rider: the design's parameter file (``optimise -o``) was written without
    ``rider_included``, so it read back as a bicycle with no rider (and the arms member warned no rider rides).
    It carries ``rider_included: true`` now and reads back with the rider in the set."""
    spec = tmp_path / "o.yaml"
    spec.write_text("bike: benchmark\nmodel: tyre\nvariables:\n  c: {min: 0.05, max: 0.1}\ntarget: {weave-speed: 4.4}\n")
    design = tmp_path / "d.yaml"
    assert main(["optimise", str(spec), "-o", str(design), "--quiet"]) == 0
    assert yaml.safe_load(design.read_text())["rider_included"] is True
    assert bm.Scenario(str(design)).rider_label() == "rider in the parameter set"
