"""The figures of a bicycle named as :func:`bikemass.load_bicycle` takes it (``bm.plot_side_view``,
``bm.plot_pose``, ``bm.plot_chart``): the names are resolved here, and :mod:`bikemass.plots` draws
the loaded objects."""

from typing import Protocol

from ..plots.chart import plot_chart as draw_chart
from ..plots.pose import plot_pose as draw_pose
from ..plots.side_view import plot_side_view as draw_side_view
from ..plots.figure import Figure
from .catalog import load_bicycle, load_rider
from .loading import BicycleLike, RiderLike


class Solution(Protocol):
    """What :func:`plot_pose` draws of :class:`bikemass.rider.solve.Solution` (a solved chain pose): a
    protocol here, so that annotating it does not load the pose solver (scipy.optimize) with this module."""

    @property
    def pose(self) -> object: ...       # the solved ChainPose

    @property
    def targets(self) -> tuple: ...     # the contacts it was solved for


def plot_side_view(bicycle: BicycleLike, rider: RiderLike = None, title: str | None = None,
                   size: "tuple[float, float] | None" = None, xlim: "tuple[float, float] | None" = None,
                   ylim: "tuple[float, float] | None" = None) -> Figure:
    """Figure: the side view of a bicycle with an optional rider, their centres of mass and inertias.

    Parts are filled outlines in their body's colour (rear frame blue, front frame orange, a
    rider's parts green edged in the colour of the body they move with), wheels drawn from the
    geometry (also for parameter-file bicycles), each body's centre of mass labelled with its name
    and mass, its ellipse of gyration (semi-axes the radii of gyration sqrt(I/m) about the
    principal axes in the x-z plane) round it, the steer axis dashed; the legend below the axes.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes.
    rider : str, os.PathLike, Mapping, Rider or None
        Anything :func:`bikemass.load_rider` takes (used as placed; seat it first with
        :func:`bikemass.seated_rider` if it should sit on this bicycle's contacts).
    title : str, optional
        Axes title (default: the bicycle's and rider's names).
    size : (float, float), optional
        Figure size (width, height) in inches; default: 6.5 wide, the height fitted to the drawing.
    xlim, ylim : (float, float), optional
        Axis ranges (m): x forward from the rear contact, height up.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputError
        Bad bicycle, rider, size or limits.

    See Also
    --------
    plot_pose : The same with a chain-posed rider's joints.
    save_figure : Write it to a file.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_side_view("jamis", bm.seated_rider("jamis", "relaxed"))
    >>> print(len(fig.axes), fig.axes[0].get_xlabel())
    1 x, forward from the rear contact (m)
    """
    return draw_side_view(load_bicycle(bicycle), load_rider(rider), title, size, xlim, ylim)


def plot_pose(bicycle: BicycleLike, rider: RiderLike, solution: "Solution", title: str | None = None,
              size: "tuple[float, float] | None" = None, xlim: "tuple[float, float] | None" = None,
              ylim: "tuple[float, float] | None" = None) -> Figure:
    """Figure: a chain-posed rider on a bicycle: the side view with the chain's centre lines,
    its joints (circles), hands and feet, and the contact targets (crosses).

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes.
    rider : str, os.PathLike, Mapping or Rider
        The posed rider (:attr:`PosedRider.rider <bikemass.PosedRider>`).
    solution : Solution
        How it was solved (:attr:`PosedRider.solution <bikemass.PosedRider>`).
    title : str, optional
        Axes title.
    size : (float, float), optional
        Figure size (width, height) in inches.
    xlim, ylim : (float, float), optional
        Axis ranges (m).

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputError
        Bad bicycle, rider, size or limits.

    See Also
    --------
    pose_rider : Gives all three arguments.
    plot_side_view : Without the chain.

    Examples
    --------
    >>> import bikemass as bm
    >>> posed = bm.pose_rider("jamis", hands="hoods")
    >>> fig = bm.plot_pose(posed.bicycle, posed.rider, posed.solution, title="hoods")
    >>> fig.axes[0].get_title()
    'hoods'
    """
    return draw_pose(load_bicycle(bicycle), load_rider(rider), solution, title, size, xlim, ylim)


def plot_chart(bicycle: BicycleLike, title: str | None = None, size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: a bicycle's frame centre lines, wheels and steer axis with its geometry chart's
    dimensions (stack, reach, angles, trail, wheelbase, ...; mm and deg).

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes (a size run as ``"NAME@SIZE"``).
    title : str, optional
        Axes title (default: the bicycle's name).
    size : (float, float), optional
        Figure size (width, height) in inches; default 10 x 6.5.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputError
        Bad bicycle or size.

    See Also
    --------
    geometry_chart : The same dimensions as numbers.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_chart("bmc-roadmachine@56")
    >>> fig.axes[0].get_title()
    'BMC Roadmachine (2017) (56): chart dimensions (mm, deg)'
    """
    return draw_chart(load_bicycle(bicycle), title, size)
