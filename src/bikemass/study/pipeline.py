"""The whole study: inputs -> three stability runs and the frame models -> comparisons -> files."""

import os
from dataclasses import dataclass, field

from ..core.output import dumps, write_atomic
from ..core.threads import one_blas_thread
from ..rider import THESIS_POSES
from . import corrections, figures
from .body_tables import bicycle_table, rider_table
from .configurations import BICYCLES, Configuration, configurations
from .explain import explain
from .flexible import (FlexibleResults, damped_table, flexible_results, flexible_table, lean_table,
                       quasi_static_speeds)
from .frame_tables import modes_table, stiffness_table
from .frames import FRAMES, MATERIALS, frame_results
from .handling import handled, handling_result
from .parallel import executor
from .records import records
from .report import render
from .report_html import render_html
from .runs import CORRECTED, GEOMETRY, THESIS, Inputs, run
from .stability_tables import CHAPTER4, CHAPTER5, compare, entry_table
from .handling import handling_table

REFERENCE_CORES = 2
"""The cores of the machine the study's timings are measured on (docs/study.md)."""
WORKERS = min(REFERENCE_CORES, os.cpu_count() or 1)
"""Worker processes by default: the reference machine's cores, at most this machine's."""
_INPUTS = None
"""The study's :class:`~bikemass.study.runs.Inputs`, set before the pool forks (workers inherit it)."""


@dataclass(frozen=True)
class StudyResults:
    """Everything the report and the files are made of."""

    runs: dict
    entries: list
    explanations: dict
    input_tables: list
    correction_tables: list
    correction_summary: list
    contacts: dict = field(default_factory=dict)
    """``{(pose, bike): {contact: (gap m, key)}}``: the geometry riders as the thesis placed them."""
    handling: dict = field(default_factory=dict)
    """``{bike: {rider: HandlingResult}}``: the rider in the loop (:mod:`~bikemass.study.handling`)."""
    flexible: FlexibleResults = None
    """The frame and fork flexing with their inertia, and the leaning rider (:mod:`~bikemass.study.flexible`)."""
    figure_paths: tuple = ()
    """The PNG files :func:`compute` drew into its ``draw_into`` folder (none without one)."""


def _preload(inputs):
    """Load what every run and job needs once, before the workers fork."""
    for bike in BICYCLES:
        for name in (bike, f"{bike}-thesis"):
            inputs.bicycle(name)
    inputs.bicycle("benchmark")
    for pose in THESIS_POSES:
        inputs.rider(pose)
        inputs.rider(f"{pose}-thesis")
        for bike in BICYCLES:                    # the geometry run's riders on its bicycles
            inputs.rider(GEOMETRY.rider_name(pose), GEOMETRY.bike_name(bike))
    for frame in FRAMES:
        for material in MATERIALS:
            for procedure in ("thesis", "condensed"):
                inputs.frame_stiffness(frame, material, procedure)


def _run_part(spec, part):
    return run(spec, part, _INPUTS)


def _frames():
    return frame_results(_INPUTS)


def _handling(bike, rider):
    return handling_result(_INPUTS, bike, rider)


def _flexible():
    return flexible_results(_INPUTS)


def _by_bike(configs):
    """Configurations grouped into jobs of about equal size (the benchmark joins the first bicycle)."""
    groups = {bike: [c for c in configs if c.bike == bike] for bike in BICYCLES}
    groups[BICYCLES[0]] = [c for c in configs if c.bike not in BICYCLES] + groups[BICYCLES[0]]
    return list(groups.values())


@one_blas_thread()
def compute(workers=WORKERS, step=lambda label: None, draw_into=None):
    """:class:`StudyResults`; ``step(label)`` is called after each unit of work (:func:`steps`).

    ``draw_into``: a folder to draw the figures into (PNG) while the study computes: each figure
    goes to the workers as soon as what it shows is computed, behind the computation still
    waiting, so no process idles between computing and drawing; the paths written are the
    results' ``figure_paths`` (:func:`draw` draws the same figures afterwards).  BLAS runs on
    one thread here and in the workers (forked inside the limit, they inherit it)."""
    global _INPUTS
    inputs = Inputs()
    _preload(inputs)
    _INPUTS = inputs
    configs = configurations()
    if draw_into is not None:
        _load_plotting()                          # before the pool forks: the workers inherit matplotlib
    with executor(workers) as pool:
        drawing = _Drawing(pool, draw_into, step)
        handling_jobs = {pair: pool.submit(_handling, *pair) for pair in handled()}   # the longest jobs first
        parts = [(spec, pool.submit(_run_part, spec, part)) for spec in (CORRECTED, GEOMETRY)
                 for part in _by_bike(configs)]
        frames_job = pool.submit(_frames)
        flexible_job = pool.submit(_flexible)
        drawing.add(lambda folder: _pose_jobs(inputs, folder))
        thesis = run(THESIS, configs, inputs, step)
        drawing.add(lambda folder: _thesis_critical_jobs(thesis, folder))
        entries = compare(thesis)
        explanations = {e: explain(e, inputs).text() for e in entries if not e.match}
        step("misses explained")
        riders = {pose: inputs.rider(pose).properties("exact") for pose in THESIS_POSES}
        bikes = {bike: inputs.parameters(GEOMETRY, Configuration(bike, "none", "infinite"))
                 for bike in BICYCLES}
        input_tables = [rider_table(riders), bicycle_table(bikes)]
        step("Tables 3-4, 3-9")
        runs = {"thesis": thesis}
        for spec, job in parts:
            outcomes = job.result()
            runs.setdefault(spec.name, {}).update(outcomes)
            if spec is CORRECTED:
                drawing.add(lambda folder, o=outcomes: figures.eigenvalue_jobs(o, folder))
            step(f"{spec.name} run")
        runs = {name: {c: outcomes[c] for c in configs} for name, outcomes in runs.items()}   # study order
        drawing.add(lambda folder: figures.critical_jobs(runs["corrected"], folder))
        frames = frames_job.result()
        step("frame models")
        handling = {}
        for (bike, rider), job in handling_jobs.items():
            handling.setdefault(bike, {})[rider] = job.result()
        drawing.add(lambda folder: figures.handling_jobs(handling, runs["corrected"], folder))
        step("rider in the loop")
        flexible = flexible_job.result()
        drawing.add(lambda folder: figures.flexible_jobs(flexible, runs["geometry"], folder))
        step("flexible frame and fork")
        figure_paths = drawing.finish()
    published = {(f, m): inputs.bicycle(f"{f}-thesis").published_stiffness(inputs.material(m))
                 for f in FRAMES for m in MATERIALS}
    input_tables += [stiffness_table(frames, published), modes_table(frames, "jamis"), modes_table(frames, "cargo")]
    correction_tables = [corrections.inertia_table(thesis, runs["corrected"]),
                         corrections.stiffness_table(thesis, runs["corrected"]),
                         corrections.range_table(thesis, runs["corrected"], runs["geometry"])]
    return StudyResults(runs, entries, explanations, input_tables, correction_tables,
                        corrections.summary(thesis, runs["corrected"]), dict(inputs.contacts), handling, flexible,
                        figure_paths)


class _Drawing:
    """Figures drawn on ``pool`` into ``folder``: :meth:`add` sends jobs as their inputs are
    ready (behind the work already queued); :meth:`finish` waits for them in the order they were
    given, calling ``step`` with each file's name, and returns the paths.  With no folder, nothing
    is drawn.  Load the plotting modules (:func:`_load_plotting`) before the pool forks."""

    def __init__(self, pool, folder, step):
        self.pool, self.folder, self.step, self.pending = pool, folder, step, []

    def add(self, make_jobs):
        if self.folder is not None:
            self.pending += [self.pool.submit(figures.run_job, job) for job in make_jobs(self.folder)]

    def finish(self):
        paths = []
        for future in self.pending:
            paths.append(future.result())
            self.step(paths[-1].name)
        return tuple(paths)


def _load_plotting():
    """Import the plotting modules now (matplotlib with them), so that workers forked later have them."""
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots import critical_speeds, figure, side_view, stability  # noqa: F401


def steps(with_figures=True):
    """How many times :func:`compute` (and :func:`draw`) call ``step``."""
    n = len(configurations()) + 2 + 2 * len(BICYCLES) + 3
    return n + (figures.figure_count() if with_figures else 0)


def write_files(results, out):
    """``report.md``, the ``stability_ranges*.json`` records and one CSV per table into ``out``."""
    write_atomic(out / "report.md", render(results))
    write_atomic(out / "stability_ranges.json", dumps(records(results.runs["thesis"], "grid"), "json"))
    write_atomic(out / "stability_ranges_corrected.json",
                 dumps(records(results.runs["corrected"], "exact"), "json"))
    write_atomic(out / "stability_ranges_geometry.json", dumps(records(results.runs["geometry"], "grid"), "json"))
    tables = [entry_table(t, results.entries, results.explanations) for t in (*CHAPTER4, *CHAPTER5)]
    for table in (tables + results.input_tables + results.correction_tables + handling_tables(results)
                  + flexible_tables(results)):
        write_atomic(out / f"{table.key}.csv", table.to_csv())


def handling_tables(results):
    """The handling table (:mod:`~bikemass.study.handling`), if the rider was in the loop."""
    return [handling_table(results.handling, results.runs["corrected"])] if results.handling else []


def flexible_tables(results):
    """The flexible frame's and the leaning rider's tables (:mod:`~bikemass.study.flexible`), if computed."""
    if results.flexible is None:
        return []
    return [flexible_table(results.flexible, quasi_static_speeds(results.flexible, results.runs["geometry"])),
            lean_table(results.flexible), damped_table(results.flexible)]


def _pose_jobs(inputs, folder):
    return figures.pose_jobs(inputs.bicycle("jamis"), {p: inputs.rider(p) for p in THESIS_POSES}, folder)


def _thesis_critical_jobs(thesis, folder):
    return figures.critical_jobs(thesis, folder, "_thesis", "thesis run, 0.05 m/s grid")


def figure_jobs(results, inputs, folder):
    """Every figure job of the study (see :mod:`~bikemass.study.figures`); :func:`compute` sends
    the same jobs as their inputs are computed."""
    return (figures.critical_jobs(results.runs["corrected"], folder)
            + _thesis_critical_jobs(results.runs["thesis"], folder)
            + figures.eigenvalue_jobs(results.runs["corrected"], folder)
            + _pose_jobs(inputs, folder)
            + figures.handling_jobs(results.handling, results.runs["corrected"], folder)
            + figures.flexible_jobs(results.flexible, results.runs.get("geometry"), folder))


@one_blas_thread()
def draw(results, out, workers=WORKERS, step=lambda label: None):
    """Draw the figures into ``out/figures`` (one BLAS thread, as :func:`compute`); returns the paths written."""
    inputs = _INPUTS or Inputs()
    _load_plotting()                              # before the pool forks: the workers inherit matplotlib
    with executor(workers) as pool:
        drawing = _Drawing(pool, out / "figures", step)
        drawing.add(lambda folder: figure_jobs(results, inputs, folder))
        return list(drawing.finish())


def write_html(results, out, figure_paths=()):
    """``report.html`` with the figures at ``figure_paths`` (PNG) embedded."""
    write_atomic(out / "report.html", render_html(results, {p.name: p.read_bytes() for p in figure_paths}))
