"""Chart dimensions drawn on a side view (x forward, height up, m): stack, reach, angles, ...

:func:`annotate_chart` adds the dimension lines of :func:`~bikemass.bicycle.derived_chart.derived_chart` to
any matplotlib axes showing the bicycle side on (``bikemass draw`` of a chart bicycle);
:func:`plot_chart` makes a figure of the frame's centre lines, the wheels and the
dimensions (``bikemass geometry --plot``, the figure of docs/bicycles.md).
"""

import numpy as np

from ..bicycle.derived_chart import derived_chart, frame_points
from .figure import new_figure

DIMENSION_COLOUR = "tab:red"
GAP = 0.06
"""m: how far dimension lines stand off the points they measure."""


def _xh(p):
    return np.array([p[0], -p[2]], dtype=float)


def _dimension(ax, a, b, text, offset=(0.0, 0.0), rotate=False):
    """A double arrow from ``a`` to ``b`` shifted by ``offset`` with extension lines and a label."""
    a, b, o = np.asarray(a, float), np.asarray(b, float), np.asarray(offset, float)
    style = dict(color=DIMENSION_COLOUR, linewidth=0.7)
    if np.any(o):
        for p in (a, b):
            ax.plot(*np.column_stack([p, p + o * 1.15]), linestyle=":", **style)
    ax.annotate("", xy=b + o, xytext=a + o, arrowprops=dict(arrowstyle="<->", shrinkA=0, shrinkB=0, **style))
    d = b - a
    angle = np.degrees(np.arctan2(d[1], d[0])) if rotate else 0.0
    if angle > 90 or angle < -90:
        angle -= 180 * np.sign(angle)
    ax.text(*((a + b) / 2 + o), text, color=DIMENSION_COLOUR, fontsize=7, ha="center", va="center",
            rotation=angle, bbox=dict(facecolor="white", edgecolor="none", pad=0.5, alpha=0.85))


def annotate_chart(ax, bicycle):
    """Draw the bicycle's chart dimensions (mm, deg) on ``ax``; returns the derived chart (m, deg)."""
    chart = derived_chart(bicycle)
    p = frame_points(bicycle)
    g = bicycle.geometry
    rear, front = _xh(g.rear_axle), _xh(g.front_axle)
    mm = lambda key: f"{key.replace('_length', '').replace('_', ' ')} {chart[key] * 1000:.0f}"  # noqa: E731
    _dimension(ax, [0, 0], [g.wheelbase, 0], mm("wheelbase"), (0, -1.6 * GAP))
    _dimension(ax, [g.wheelbase, 0], [g.wheelbase + g.trail, 0], mm("trail"), (0, -0.6 * GAP))
    ha = g.head_angle
    down_axis = np.array([np.cos(ha), -np.sin(ha)])
    foot = front - g.fork_offset() * np.array([np.sin(ha), np.cos(ha)])
    _dimension(ax, foot, front, mm("fork_offset"), -0.8 * GAP * down_axis, rotate=True)
    if "bottom_bracket" not in p:
        return chart
    bb = p["bottom_bracket"]
    _dimension(ax, rear, bb, mm("chainstay_length"), (0, -0.6 * GAP), rotate=True)
    _dimension(ax, bb, front, mm("front_center"), (0, -1.1 * GAP), rotate=True)
    _dimension(ax, [bb[0], bb[1] + chart["bb_drop"]], bb, f"drop {chart['bb_drop'] * 1000:.0f}",
               (0.8 * GAP, 0))
    if "head_top" in p:
        top = p["head_top"]
        _dimension(ax, bb, [bb[0], top[1]], mm("stack"), (top[0] - bb[0] + GAP, 0))
        _dimension(ax, bb, [top[0], bb[1]], mm("reach"), (0, top[1] - bb[1] + GAP))
        _dimension(ax, p["head_bottom"], top, mm("head_tube_length"),
                   GAP * np.array([np.sin(ha), np.cos(ha)]), rotate=True)
        ax.text(*(p["head_bottom"] + 0.02 * down_axis + [0.025, 0]), f"{chart['head_tube_angle']:.1f}°",
                color=DIMENSION_COLOUR, fontsize=7)
    if "seat_top" in p:
        sa = np.radians(chart["seat_tube_angle"])
        _dimension(ax, bb, p["seat_top"], mm("seat_tube_length"), -GAP * np.array([np.sin(sa), np.cos(sa)]),
                   rotate=True)
        ax.text(bb[0] - 0.16, bb[1] + 0.03, f"{chart['seat_tube_angle']:.1f}°", color=DIMENSION_COLOUR, fontsize=7)
        if "head_top" in p:
            start = [p["head_top"][0] - chart["top_tube_length"], p["head_top"][1]]
            _dimension(ax, start, p["head_top"], mm("top_tube_length"), (0, 2.2 * GAP))
    return chart


def plot_chart(bicycle, title=None, size=None):
    """Figure: frame centre lines, wheels, steer axis and the chart's dimensions (m, height up);
    ``bicycle``: a loaded :class:`~bikemass.bicycle.Bicycle` (``bm.plot_chart`` also takes its name:
    :mod:`bikemass.scenario.views`)."""
    fig = new_figure(size or (10, 6.5))
    ax = fig.subplots()
    for tube in bicycle.tubes:
        if tube.start[1] >= 0 and tube.end[1] >= 0:        # the right-hand side and the centre plane
            colour = "tab:blue" if tube.body == "rear_frame" else "tab:orange"
            ax.plot(*np.column_stack([_xh(tube.start), _xh(tube.end)]), color=colour, linewidth=2.5,
                    solid_capstyle="round")
    g = bicycle.geometry
    for axle, radius in ((g.rear_axle, g.rear_wheel_radius), (g.front_axle, g.front_wheel_radius)):
        centre = _xh(axle)
        t = np.linspace(0, 2 * np.pi, 200)
        ax.plot(centre[0] + radius * np.cos(t), centre[1] + radius * np.sin(t), color="0.5", linewidth=1)
        ax.plot(*centre, "o", color="0.3", markersize=3)
    ground = g.wheelbase + g.trail
    ax.plot([ground, ground - 1.1 * np.cos(g.head_angle)], [0, 1.1 * np.sin(g.head_angle)], "k--", linewidth=0.7)
    ax.axhline(0, color="black", linewidth=0.8)
    annotate_chart(ax, bicycle)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m, forward from the rear contact)")
    ax.set_ylabel("height (m)")
    ax.set_title(title or f"{bicycle.name}: chart dimensions (mm, deg)")
    ax.grid(True, linewidth=0.3)
    return fig
