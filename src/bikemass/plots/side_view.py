"""Side view (x-z plane) of a bicycle with rider: part outlines, body CoMs, inertia ellipses."""

import numpy as np
from matplotlib.patches import Patch

from ..bicycle.benchmark import combined_bodies
from ..bicycle.components import BODIES
from .figure import check_limits, new_figure

COLOURS = {"rear_frame": "tab:blue", "front_frame": "tab:orange",
           "rear_wheel": "tab:purple", "front_wheel": "tab:brown"}
RIDER_COLOUR = "tab:green"
NAMES = {"rear_frame": "rear frame", "front_frame": "front frame",
         "rear_wheel": "rear wheel", "front_wheel": "front wheel"}
WHEELS = ("rear_wheel", "front_wheel")
SEGMENTS = 24
"""Polygon sides of round sections in the drawing (outlines only)."""
SPOKES = 12


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
    # lazy: scipy.spatial is slower to import than numpy; only the outlines of parts need it
    from scipy.spatial import ConvexHull
    xz = mesh.vertices[:, [0, 2]] * [1, -1]
    return xz[ConvexHull(xz).vertices]


def draw_wheel(ax, centre, radius, colour, tyre=0.025):
    """A wheel seen side on at ``centre`` (x, height) of outer ``radius`` (m): tyre and rim
    circles, spokes and hub, unfilled so that what lies behind stays visible."""
    t = np.linspace(0, 2 * np.pi, 181)
    ring = np.column_stack([np.cos(t), np.sin(t)])
    for r, width in ((radius, 1.6), (radius - tyre, 0.9)):
        ax.plot(*(centre + r * ring).T, color=colour, linewidth=width)
    angles = np.linspace(0, 2 * np.pi, SPOKES, endpoint=False)
    ends = centre + (radius - tyre) * np.column_stack([np.cos(angles), np.sin(angles)])
    spokes = np.stack([np.broadcast_to(centre, ends.shape), ends, np.full(ends.shape, np.nan)], 1).reshape(-1, 2)
    ax.plot(*spokes.T, color=colour, linewidth=0.4, alpha=0.6)
    ax.plot(*(centre + 0.03 * ring).T, color=colour, linewidth=1.0)


def _rider_body(rider, part):
    return rider is not None and part in rider.parts


def plot_side_view(bicycle, rider=None, title=None, size=None, xlim=None, ylim=None):
    """Figure: the side view (x forward, height up, m) of ``bicycle`` with an optional ``rider``.

    Parts are filled outlines in their body's colour (a rider's parts green, edged in the
    colour of the body they move with), wheels drawn as wheels from the geometry (also for
    parameter-file bicycles), each body's centre of mass labelled with its name and mass,
    its ellipse of gyration (semi-axes = radii of gyration sqrt(I/m) about the principal axes
    in the x-z plane) drawn round it, the steer axis dashed; the legend sits below the axes.
    ``bicycle`` and ``rider``: a :class:`~bikemass.bicycle.Bicycle` and a :class:`~bikemass.rider.Rider`
    or None, as loaded (``bm.plot_side_view`` also takes their names: :mod:`bikemass.scenario.views`).
    """
    xlim, ylim = check_limits(xlim, "xlim"), check_limits(ylim, "ylim")
    fig = new_figure(size or (6.5, 7.2))
    ax = fig.subplots()
    g = bicycle.geometry
    drawn = set()
    for part in list(bicycle.parts) + (list(rider.parts) if rider is not None else []):
        if part.body in WHEELS:
            continue                                   # drawn as wheels below
        mesh = part.mesh(SEGMENTS)
        if mesh is None:
            continue
        drawn.add("rider" if _rider_body(rider, part) else part.body)
        if _rider_body(rider, part):
            face, edge, alpha = RIDER_COLOUR if part.body == "rear_frame" else COLOURS[part.body], \
                COLOURS[part.body], 0.3
        else:
            face, edge, alpha = COLOURS[part.body], COLOURS[part.body], 0.35
        ax.fill(*_outline(mesh).T, facecolor=face, edgecolor=edge, alpha=alpha, linewidth=0.6)
    for body, axle, radius in (("rear_wheel", g.rear_axle, g.rear_wheel_radius),
                               ("front_wheel", g.front_axle, g.front_wheel_radius)):
        draw_wheel(ax, np.array([axle[0], -axle[2]]), radius, COLOURS[body])
    ground = g.steer_ground_point
    top = ground + 1.25 * np.array([-np.sin(g.lam), 0, -np.cos(g.lam)])
    ax.plot([ground[0], top[0]], [0, -top[2]], "--", color="0.2", linewidth=0.8, label="steer axis")
    bodies = combined_bodies(bicycle, rider, "exact", "exact")
    for body in BODIES:
        props = bodies[body]
        ax.plot(*gyration_ellipse(props).T, color=COLOURS[body], linewidth=1.1)
        ax.plot(props.com[0], -props.com[2], "o", color=COLOURS[body], markersize=6, markeredgecolor="black",
                zorder=5)
        name = NAMES[body] + (" + rider" if rider is not None and any(
            p.body == body for p in rider.parts) else "")
        ax.annotate(f"{name}\n{props.mass:.2f} kg", (props.com[0], -props.com[2]), xytext=(6, 6),
                    textcoords="offset points", fontsize=7.5, color="black", zorder=6,
                    bbox=dict(facecolor="white", edgecolor=COLOURS[body], linewidth=0.6, alpha=0.85, pad=1.5))
    ax.plot([], [], "o", color="0.8", markeredgecolor="black", label="centre of mass of a body")
    ax.plot([], [], "-", color="0.4", linewidth=1.1,
            label="ellipse of gyration: semi-axes =\nradii of gyration $\\sqrt{I/m}$ about the\n"
                  "principal axes in the x-z plane")
    handles = [Patch(facecolor=COLOURS[b], alpha=0.5, label=NAMES[b]) for b in ("rear_frame", "front_frame")
               if b in drawn]
    if "rider" in drawn:
        handles.append(Patch(facecolor=RIDER_COLOUR, alpha=0.5, label="rider (edge: body it moves with)"))
    if not drawn:
        ax.text(0.02, 0.98, "bodies known by mass, centre of mass and inertia only:\nno parts to draw",
                transform=ax.transAxes, va="top", fontsize=7.5, color="0.3")
    ax.axhline(0, color="black", linewidth=0.8)
    # datalim: the axes keep the box constrained layout gives them (title and legend inside the
    # figure) and the data limits grow to keep one metre the same length both ways
    ax.set_aspect("equal", adjustable="box" if xlim and ylim else "datalim")
    ax.set_xlabel("x, forward from the rear contact (m)")
    ax.set_ylabel("height above the ground (m)")
    ax.set_title(title or bicycle.name, fontsize=10)
    lines, labels = ax.get_legend_handles_labels()
    # a figure legend below the axes: constrained layout gives it its own room under the x label
    fig.legend(handles + lines, [h.get_label() for h in handles] + labels, fontsize=7.5,
               loc="outside lower center", ncol=2, frameon=False)
    ax.grid(True, linewidth=0.3)
    if xlim:
        ax.set_xlim(xlim)
    if ylim:
        ax.set_ylim(ylim)
    if size is None:                                   # height to suit the drawing's proportions
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        fig.set_size_inches(6.5, min(10.0, 2.4 + 5.4 * (y1 - y0) / (x1 - x0)))
    return fig
