"""Side view of a chain-posed rider on its bicycle: the bicycle drawing, the chain, joints and contacts."""

import numpy as np

from .side_view import plot_side_view

CHAIN_LINES = (("head_top", "neck", "torso_top", "hip_centre"), ("torso_top", "shoulder", "elbow", "hand"),
               ("hip_centre", "hip", "knee", "foot"))
"""Polylines through the chain's named points (:meth:`ChainPose.points`)."""

JOINT_MARKS = ("neck", "shoulder", "elbow", "hip", "knee")


def _xh(p):
    return p[0], -p[2]


def plot_pose(bicycle, rider, solution, title=None, size=None, xlim=None, ylim=None):
    """Figure: the side view of ``rider`` (solved :class:`~bikemass.rider.solve.Solution`) on
    ``bicycle``: part outlines and CoMs (bikemass.plots.side_view),
    the chain's centre lines, joints (circles), hands and feet, and contact targets (crosses)."""
    fig = plot_side_view(bicycle, rider, title, size, xlim, ylim)
    ax = fig.axes[0]
    pose = solution.pose
    sides = ("right", "left") if not pose.symmetric else ("right",)
    for side in sides:
        points = pose.points(side)
        style = "-" if side == "right" else "--"
        for line in CHAIN_LINES if side == "right" else CHAIN_LINES[2:]:
            xs, hs = zip(*(_xh(points[k]) for k in line))
            ax.plot(xs, hs, style, color="darkgreen", linewidth=1.6)
        marks = JOINT_MARKS if side == "right" else ("hip", "knee")
        ax.plot(*np.array([_xh(points[k]) for k in marks]).T, "o", color="white",
                markeredgecolor="darkgreen", markersize=6, zorder=5)
    ax.plot([], [], "o", color="white", markeredgecolor="darkgreen", label="rider joints")
    for i, target in enumerate(solution.targets):
        ax.plot(target.target[0], -target.target[1], "x", color="red", markersize=9, mew=2, zorder=6,
                label="contact targets" if i == 0 else None)
    ours = [(h, label) for h, label in zip(*ax.get_legend_handles_labels())
            if label in ("rider joints", "contact targets")]       # the side view's own are in its legend below
    ax.legend(*zip(*ours), loc="upper right", fontsize="small")
    return fig
