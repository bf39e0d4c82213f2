"""The study's figures (PNG): one job per figure, so they can be drawn in parallel.

* ``critical_<bike>.png``: every rider and stiffness of one bicycle by its weave and capsize
  speeds and stable speeds (corrected run, exact speeds); ``critical_<bike>_thesis.png``: the
  stable speeds of the thesis run (0.05 m/s grid, the tables' numbers);
* ``eig_<bike>_<rider>_<stiffness>.png``: one configuration's eigenvalues against speed
  (Meijaard et al. 2007, Fig. 3 style; corrected run, v_w and v_c marked);
* ``pose_<pose>.png``: side view of each of the five poses on the geometry Jamis;
* ``handling_<bike>.png``: the HQM peak of the Hess, Moore & Hubbard (2012) rider against speed
  for every rider position of the Jamis and the Cargo, beside their self-stable speeds;
* ``flexible.png``: the frame and fork flexing with their inertia (:mod:`~bikemass.study.flexible`):
  the wobble's frequency and unstable speeds, the critical speeds beside the thesis's spring's, and
  the leaning rider's weave speed.

A job is ``(function, *arguments, path, title)``; ``function(*arguments, title)`` returns
the Figure.
"""

import threading

from ..core.output import write_atomic
from ..rider import THESIS_POSES
from .configurations import BICYCLES, THESIS_NAMES, configurations
from .handling import stable_speeds
from .handling import BICYCLES as HANDLED
from ..analysis.handling.figures import plot_handling_by_rider
from . import flexible
from .reference import wobble_bands

STIFFNESS_NAMES = {"infinite": "rigid frame", "steel": "steel frame", "titanium": "titanium frame",
                   "aluminum": "aluminium frame"}


def critical_speeds(outcome):
    """:class:`~bikemass.plots.stability.CriticalSpeeds` of a study outcome: exact speeds and
    ranges where the run has them, else the stable runs of the grid."""
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots.stability import CriticalSpeeds
    if outcome.weave_speeds is not None:
        return CriticalSpeeds(tuple(outcome.weave_speeds), tuple(outcome.capsize_speeds),
                              tuple(map(tuple, outcome.ranges["exact"]["strict"]["overall"])))
    return CriticalSpeeds(stable=tuple(map(tuple, outcome.ranges["grid"]["strict"]["overall"])))


def bike_results(outcomes, bike):
    """``{rider: {stiffness: CriticalSpeeds}}`` of one bicycle (thesis names, study order)."""
    results = {}
    for c, o in outcomes.items():
        if c.bike == bike:
            results.setdefault(THESIS_NAMES[c.rider], {})[STIFFNESS_NAMES[c.stiffness]] = critical_speeds(o)
    return results


def critical_jobs(outcomes, folder, suffix="", run_title="corrected run"):
    """Jobs drawing each bicycle's configurations by their critical speeds."""
    return [(draw_critical, bike_results(outcomes, bike), folder / f"critical_{bike}{suffix}.png".replace("-", "_"),
             f"{THESIS_NAMES[bike]}: stable speeds of every rider and frame ({run_title})") for bike in BICYCLES]


def eigenvalue_jobs(outcomes, folder):
    """Jobs drawing each configuration's eigenvalues against speed."""
    return [(draw_eigenvalues, o.modes, critical_speeds(o), folder / f"eig_{c.slug}.png",
             f"{THESIS_NAMES[c.bike]}, {rider_words(c.rider)}, {STIFFNESS_NAMES[c.stiffness]}"
             if not c.is_benchmark else "Benchmark bicycle (Meijaard et al. 2007)")
            for c, o in outcomes.items()]


def rider_words(rider):
    """A rider in a title: "relaxed rider", "no rider" (not "no rider rider")."""
    return "no rider" if rider == "none" else f"{THESIS_NAMES[rider].lower()} rider"


def pose_jobs(bicycle, riders, folder):
    """Jobs drawing ``riders`` (``{pose: Rider}``) on ``bicycle``."""
    return [(draw_pose, bicycle, rider, folder / f"pose_{pose.replace('-', '_')}.png",
             f"{pose} on the {bicycle.name}") for pose, rider in riders.items()]


def handling_jobs(handling, outcomes, folder):
    """Jobs drawing the rider positions' HQM peaks of each bicycle of the handling question."""
    return [(draw_handling, {THESIS_NAMES[r]: res for r, res in by_rider.items()},
             {THESIS_NAMES[r]: stable_speeds(outcomes, bike, r) for r in by_rider},
             folder / f"handling_{bike}.png",
             f"{THESIS_NAMES[bike]}, rigid frame: handling quality of every rider position")
            for bike, by_rider in handling.items()]


def flexible_jobs(results, geometry, folder):
    """The job drawing the flexible frame and fork (none without its results)."""
    if results is None:
        return []
    return [(draw_flexible, results, flexible.quasi_static_speeds(results, geometry), folder / "flexible.png",
             "Frame stiffness with the frame's inertia and the fork's compliance (geometry bicycles and riders)")]


def figure_count():
    """How many figures the study draws (:func:`critical_jobs` twice, :func:`eigenvalue_jobs`,
    :func:`pose_jobs`, :func:`handling_jobs`, :func:`flexible_jobs`)."""
    return 2 * len(BICYCLES) + len(configurations()) + len(THESIS_POSES) + len(HANDLED) + 1


def draw_critical(results, title):
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots.critical_speeds import plot_critical_speeds
    return plot_critical_speeds(results, title)


def draw_eigenvalues(modes, critical, title):
    """The eigenvalue figure, drawn on this process's kept figure (:func:`kept_figure`)."""
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots.stability import SIZE, clear_axes, draw_eigenvalues as draw
    fig = kept_figure("eigenvalues", SIZE)
    clear_axes(fig.axes[0])
    draw(fig.axes[0], modes, critical, title)
    return fig


KEPT: dict = {}
"""``{kind: (Figure, its layout engine)}``: one figure of one axes per kind of figure drawn in this
process (:func:`kept_figure`), used only while :data:`DRAWING` is held."""
DRAWING = threading.Lock()
"""Held by :func:`run_job` from drawing a figure to writing it: a kept figure serves one job at a time."""


def kept_figure(kind, size):
    """The figure of ``kind`` kept in :data:`KEPT` (made at ``size`` inches, one axes, the first
    time), its layout engine put back (:func:`~bikemass.plots.figure.png_bytes` takes it off to
    draw at fixed margins). Each of the 73 eigenvalue figures would otherwise make a Figure, its
    Axes and their ticks anew: a quarter of drawing it."""
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots.figure import new_figure
    if kind not in KEPT:
        fig = new_figure(size)
        fig.subplots()
        KEPT[kind] = fig, fig.get_layout_engine()
    fig, engine = KEPT[kind]
    fig.set_layout_engine(engine)
    fig.axes[0].set_in_layout(True)
    return fig


def draw_handling(results, stable, title):
    return plot_handling_by_rider(results, title, stable_speeds=stable)


def draw_flexible(results, speeds, title):
    # lazy: the figure loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from .flexible_figure import plot_flexible
    return plot_flexible(results, speeds, wobble_bands(), flexible.SPEED, title)


def draw_pose(bicycle, rider, title):
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots.side_view import plot_side_view
    return plot_side_view(bicycle, rider, title)


def job_path(job):
    """The file a job writes."""
    return job[-2]


MARGINS = {"draw_eigenvalues": (0.78, 0.48, 2.04, 0.24), "draw_critical": (0.78, 0.48, 1.39, 0.24)}
"""Margins (inches: left, bottom, right, top) of the figures drawn at a fixed layout
(:func:`~bikemass.plots.figure.png_bytes`): room for the labels and legends of most of the study's
figures of the kind (63 of the 73 eigenvalue figures, 5 of the 6 critical-speed figures; the others
have the side their legend or note needs more room at widened to it and are drawn again)."""


def run_job(job):
    """Draw one figure and save it (PNG, at its kind's fixed layout where it fits); returns the path."""
    # lazy: plots/ loads matplotlib (slower to import than numpy); study --no-figures runs without it
    from ..plots.figure import png_bytes
    function, *args, path, title = job
    with DRAWING:
        data = png_bytes(function(*args, title), margins=MARGINS.get(function.__name__))
    write_atomic(path, data)
    return path
