"""The study's building blocks: grid ranges, record intervals, the thesis combination used to
explain misses, the rounding half-units, and one configuration's figures."""

import numpy as np
import pytest

from bikemass.scenario import catalog
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.bicycle import bicycle_parameters
from bikemass.analysis.engine.stability import analyse
from bikemass.models.whipple import whipple_model
from bikemass.study import figures
from bikemass.study.configurations import RIDERS, Configuration, configurations
from bikemass.study.explain import PrintedInputs, half_unit_of_stiffness, with_rider
from bikemass.study.flexible import FlexibleResults
from bikemass.study.runs import CORRECTED, THESIS, Inputs, evaluate

PNG = b"\x89PNG\r\n\x1a\n"


@pytest.fixture(scope="module")
def inputs():
    return Inputs()


def test_73_configurations():
    configs = configurations()
    assert len(configs) == len(set(configs)) == 73
    assert sum(c.is_benchmark for c in configs) == 1


@pytest.mark.parametrize("config", [Configuration("jamis", "none", "infinite"),
                                    Configuration("cargo", "relaxed", "steel"),
                                    Configuration("cargo-loaded", "aero-tuck", "titanium")])
def test_grid_only_ranges_equal_the_stability_cores_grid_ranges(inputs, config):
    """The thesis run reads ranges off tracked modes without the exact roots: same grid ranges."""
    p, S = inputs.parameters(THESIS, config), inputs.stiffness(THESIS, config)
    quick = evaluate(config, p, S, exact=False).ranges["grid"]
    full = analyse(whipple_model(p, S))
    for criterion in ("strict", "marginal"):
        assert tuple(map(tuple, quick[criterion]["overall"])) == full.ranges[criterion]["grid"]
        for label in ("weave 1", "weave 2", "capsize", "caster"):
            assert tuple(map(tuple, quick[criterion][label])) == full.mode_ranges[label][criterion]["grid"]


def test_runs_build_parameters_as_the_catalog_does(inputs):
    c = Configuration("jamis", "relaxed", "steel")
    thesis = inputs.parameters(THESIS, c)
    assert thesis == scenario_parameters("jamis-thesis", "relaxed-thesis", "thesis", "exact")
    assert inputs.parameters(CORRECTED, c) == scenario_parameters("jamis-thesis", "relaxed-thesis", "exact", "exact")
    assert np.allclose(inputs.stiffness(THESIS, c), catalog.stiffness("jamis-thesis", "steel", "published"))
    assert np.allclose(inputs.stiffness(CORRECTED, c),
                       catalog.stiffness("jamis", "steel", "computed", "condensed"), rtol=1e-12)


@pytest.mark.parametrize("how", ["thesis", "exact"])
def test_with_rider_equals_the_bicycle_model(how):
    bike, rider = catalog.load_bicycle("cargo-thesis"), catalog.load_rider("on-hoods-thesis")
    ours = with_rider(bicycle_parameters(bike, None), rider.properties("exact"), how)
    theirs = bicycle_parameters(bike, rider, how, "exact")
    for name, value in theirs.to_dict().items():
        assert getattr(ours, name) == pytest.approx(value, rel=1e-13, abs=1e-13), name


def test_half_units_of_printed_values():
    # Table 3-12 prints five significant digits
    assert half_unit_of_stiffness(6538.4) == pytest.approx(0.05)
    assert half_unit_of_stiffness(694.29) == pytest.approx(0.005)
    assert half_unit_of_stiffness(1208.0) == pytest.approx(0.05)
    frame = scenario_parameters("jamis-thesis")
    rider = catalog.load_rider("relaxed-thesis").properties("exact")
    printed = PrintedInputs(frame, rider, np.array([[6538.4, 1234.9], [1234.9, 3622.1]]))
    half = printed.half_units()
    assert len(half) == len(printed.names()) == 25 + 7 + 3
    assert np.all(half[:32] == 0.0005)          # Tables 3-9 and 3-4: three decimals
    params, S = printed.perturbed(np.zeros(len(half)))
    assert params == with_rider(frame, rider, "thesis") and np.array_equal(S, printed.S)
    params, _ = printed.perturbed(np.eye(len(half))[printed.names().index("c")] * 0.0005)
    assert params.c == pytest.approx(0.0605)


def test_one_configurations_figures(tmp_path, inputs):
    c = Configuration("jamis", "relaxed", "infinite")
    outcomes = {c: evaluate(c, inputs.parameters(THESIS, c), None, exact=True)}
    jobs = (figures.eigenvalue_jobs(outcomes, tmp_path) + figures.critical_jobs(outcomes, tmp_path)[:1]
            + figures.pose_jobs(inputs.bicycle("jamis"), {"relaxed": inputs.rider("relaxed")}, tmp_path))
    written = [figures.run_job(job) for job in jobs]
    assert [p.name for p in written] == ["eig_jamis_relaxed_infinite.png", "critical_jamis.png", "pose_relaxed.png"]
    for path in written:
        data = path.read_bytes()
        assert data.startswith(PNG) and len(data) > 10_000
    assert not list(tmp_path.glob(".*.tmp"))      # written atomically, nothing left over


def test_figure_count_matches_the_jobs(tmp_path, inputs):
    """The progress bar's figure count is the number of jobs the study makes (no drawing here)."""
    from types import SimpleNamespace

    from bikemass.study.pipeline import figure_jobs
    empty = {kind: {"strict": {"overall": []}, "marginal": {"overall": []}} for kind in ("grid", "exact")}
    run = {c: SimpleNamespace(modes=None, ranges=empty, weave_speeds=None) for c in configurations()}
    handling = {bike: {rider: None for rider in RIDERS[1:]} for bike in ("jamis", "cargo")}
    flexible = FlexibleResults({}, {})
    jobs = figure_jobs(SimpleNamespace(runs={"thesis": run, "corrected": run, "geometry": run}, handling=handling,
                                       flexible=flexible), inputs, tmp_path)
    assert len(jobs) == figures.figure_count() == 2 * 3 + 73 + 5 + 2 + 1
    assert len({figures.job_path(job) for job in jobs}) == len(jobs)          # every figure has its own file


def test_contract_an_eigenvalue_figure_drawn_on_the_kept_figure_is_a_new_figures_pixels(tmp_path, inputs):
    """Contract test (the code against itself): the study draws its eigenvalue figures on one kept
    figure per process (figures.kept_figure). A figure drawn there after another configuration's
    (the Cargo with no rider: a wider legend and an off-scale note, so its right margin widens)
    has exactly the pixels of the same figure drawn on a new Figure; and its title says "no rider"."""
    from io import BytesIO

    from PIL import Image

    from bikemass.plots.figure import png_bytes
    from bikemass.plots.stability import eigenvalue_figure
    configs = [Configuration("jamis", "relaxed", "infinite"), Configuration("cargo", "none", "steel")]
    outcomes = {c: evaluate(c, inputs.parameters(CORRECTED, c), None, exact=True) for c in configs}
    jobs = figures.eigenvalue_jobs(outcomes, tmp_path)
    assert jobs[1][-1] == "Cargo, no rider, steel frame"
    margins = figures.MARGINS["draw_eigenvalues"]
    for job in (jobs[0], jobs[1], jobs[0], jobs[1]):
        kept = np.asarray(Image.open(figures.run_job(job)))
        new = np.asarray(Image.open(BytesIO(png_bytes(eigenvalue_figure(*job[1:-2], job[-1]), margins=margins))))
        assert kept.shape == new.shape == (690, 1050, 3) and (kept == new).all()
