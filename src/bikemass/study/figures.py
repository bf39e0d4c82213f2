"""The study's figures (PNG): one job per figure, so they can be drawn in parallel.

* ``real_<bike>_<stiffness>[_corrected].png``: real parts of the eigenvalues of all six
  rider positions on one axis (the thesis's Fig. 4-6 and Figs. 5-2..5-15);
* ``modes_<bike>_<rider>_<stiffness>.png``: one configuration of the thesis-mode run in
  the Fig. 4-4 layout (real and imaginary parts, natural frequency, damping ratio), the
  stable speeds of the grid shaded;
* ``pose_<pose>.png``: side view of each of the five poses on the geometry Jamis.
"""

from dataclasses import dataclass

from ..rider import THESIS_POSES
from .configurations import BICYCLES, STIFFNESSES, THESIS_NAMES, configurations


@dataclass(frozen=True)
class GridShading:
    """What :func:`~bikemass.plots.stability.plot_eigenvalues` shades: ``ranges[criterion]["exact"]``.

    The thesis-mode run has only grid ranges; they are handed over in that slot.
    """

    ranges: dict
    modes: object = None

    def with_modes(self, modes):
        """The same shading for the figure of ``modes``."""
        return GridShading(self.ranges, modes)

    @classmethod
    def of(cls, outcome):
        grid = outcome.ranges["grid"]
        return cls({criterion: {"exact": grid[criterion]["overall"]} for criterion in grid})


def comparison_jobs(outcomes, folder, suffix="", run_title="thesis run"):
    """Jobs drawing the real parts of all riders per bicycle and stiffness."""
    jobs = []
    for bike in BICYCLES:
        for stiffness in STIFFNESSES:
            curves = {THESIS_NAMES[c.rider]: o.modes for c, o in outcomes.items()
                      if c.bike == bike and c.stiffness == stiffness}
            title = f"{bike}, {stiffness} rear frame: real parts, all riders ({run_title})"
            jobs.append((draw_comparison, curves, folder / f"real_{bike}_{stiffness}{suffix}.png".replace("-", "_"),
                         title))
    return jobs


def mode_jobs(outcomes, folder):
    """Jobs drawing each configuration in the Fig. 4-4 layout."""
    return [(draw_modes, o.modes, GridShading.of(o), folder / f"modes_{c.slug}.png",
             f"{c.label} (thesis run; stable speeds on the 0.05 m/s grid shaded)")
            for c, o in outcomes.items()]


def pose_jobs(bicycle, riders, folder):
    """Jobs drawing ``riders`` (``{pose: Rider}``) on ``bicycle``."""
    return [(draw_pose, bicycle, rider, folder / f"pose_{pose.replace('-', '_')}.png",
             f"{pose} on the {bicycle.name}") for pose, rider in riders.items()]


def figure_count():
    """How many figures the study draws (:func:`comparison_jobs` twice, :func:`mode_jobs`, :func:`pose_jobs`)."""
    return 2 * len(BICYCLES) * len(STIFFNESSES) + len(configurations()) + len(THESIS_POSES)


def draw_comparison(curves, title):
    from ..plots.stability import plot_comparison
    return plot_comparison(curves, "real", title)


def draw_modes(modes, shading, title):
    from ..plots.stability import plot_eigenvalues
    return plot_eigenvalues(shading.with_modes(modes), title)


def draw_pose(bicycle, rider, title):
    from ..bicycle.drawing import plot_side_view
    return plot_side_view(bicycle, rider, title)


def job_path(job):
    """The file a job writes: ``job`` = (function, *arguments, path, title)."""
    return job[-2]


def run_job(job):
    """Draw one figure and save it (PNG): ``job`` = (function, *arguments, path, title); returns the path."""
    from ..plots.figure import save_figure
    function, *args, path, title = job
    save_figure(function(*args, title), path)
    return path

