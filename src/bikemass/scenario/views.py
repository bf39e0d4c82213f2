"""The figures of a bicycle named as :func:`bikemass.load_bicycle` takes it (``bm.plot_side_view``,
``bm.plot_pose``, ``bm.plot_chart``): the names are resolved here, and :mod:`bikemass.plots` draws
the loaded objects."""

from ..plots.chart import plot_chart as draw_chart
from ..plots.pose import plot_pose as draw_pose
from ..plots.side_view import plot_side_view as draw_side_view
from .catalog import load_bicycle, load_rider


def plot_side_view(bicycle, rider=None, title=None, size=None, xlim=None, ylim=None):
    """:func:`bikemass.plots.side_view.plot_side_view` of ``bicycle`` and ``rider``: anything
    :func:`bikemass.load_bicycle` and :func:`bikemass.load_rider` take."""
    return draw_side_view(load_bicycle(bicycle), load_rider(rider), title, size, xlim, ylim)


def plot_pose(bicycle, rider, solution, title=None, size=None, xlim=None, ylim=None):
    """:func:`bikemass.plots.pose.plot_pose` of a chain-posed ``rider`` (its
    :class:`~bikemass.rider.solve.Solution` ``solution``) on ``bicycle``: anything
    :func:`bikemass.load_bicycle` and :func:`bikemass.load_rider` take (``bm.pose_rider`` gives all three)."""
    return draw_pose(load_bicycle(bicycle), load_rider(rider), solution, title, size, xlim, ylim)


def plot_chart(bicycle, title=None, size=None):
    """:func:`bikemass.plots.chart.plot_chart` of ``bicycle``: anything :func:`bikemass.load_bicycle` takes."""
    return draw_chart(load_bicycle(bicycle), title, size)
