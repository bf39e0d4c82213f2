"""Side view (x-z plane) of a bicycle with rider: part outlines, body CoMs, inertia ellipses."""

import numpy as np

from .benchmark import combined_bodies
from .components import BODIES

COLOURS = {"rear_frame": "tab:blue", "front_frame": "tab:orange",
           "rear_wheel": "tab:gray", "front_wheel": "tab:gray"}
SEGMENTS = 24
"""Polygon sides of round sections in the drawing (outlines only)."""


def gyration_ellipse(props, samples=100):
    """(samples, 2) points (x, height) of the body's ellipse of gyration in the x-z plane.

    Semi-axes are the radii of gyration sqrt(I/m) about the principal axes of the
    x-z block of the inertia tensor, drawn along those axes around the CoM (m).
    """
    block = props.inertia[np.ix_([0, 2], [0, 2])]
    moments, axes = np.linalg.eigh(block)
    radii = np.sqrt(np.clip(moments, 0, None) / props.mass)
    t = np.linspace(0, 2 * np.pi, samples)
    local = np.column_stack([radii[0] * np.cos(t), radii[1] * np.sin(t)])
    xz = props.com[[0, 2]] + local @ axes.T
    return xz * [1, -1]


def _outline(mesh):
    from scipy.spatial import ConvexHull
    xz = mesh.vertices[:, [0, 2]] * [1, -1]
    return xz[ConvexHull(xz).vertices]


def plot_side_view(bicycle, rider=None, title=None, size=None, xlim=None, ylim=None):
    """Figure: the side view of ``bicycle`` with an optional ``rider``; limits in metres."""
    from ..plots.figure import new_figure

    fig = new_figure(size or (10, 6))
    ax = fig.subplots()
    parts = list(bicycle.parts) + (list(rider.parts) if rider is not None else [])
    for part in parts:
        mesh = part.mesh(SEGMENTS)
        if mesh is not None:
            colour = "tab:green" if rider is not None and part in rider.parts else COLOURS[part.body]
            ax.fill(*_outline(mesh).T, facecolor=colour, edgecolor=colour, alpha=0.25, linewidth=0.6)
    bodies = combined_bodies(bicycle, rider, "exact", "exact")
    for body in BODIES:
        props = bodies[body]
        ax.plot(*gyration_ellipse(props).T, color=COLOURS[body], linewidth=1.2)
        ax.plot(props.com[0], -props.com[2], "o", color=COLOURS[body], markersize=6,
                markeredgecolor="black", label=f"{body}: {props.mass:.3f} kg")
    g = bicycle.geometry
    ground = g.steer_ground_point
    top = ground + 1.2 * np.array([-np.sin(g.lam), 0, -np.cos(g.lam)])
    ax.plot([ground[0], top[0]], [0, -top[2]], "k--", linewidth=0.8, label="steer axis")
    ax.axhline(0, color="black", linewidth=0.8)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m, forward)")
    ax.set_ylabel("height = -z (m)")
    ax.set_title(title or bicycle.name)
    ax.legend(loc="upper right", fontsize="small")
    ax.grid(True, linewidth=0.3)
    if xlim:
        ax.set_xlim(xlim)
    if ylim:
        ax.set_ylim(ylim)
    return fig
