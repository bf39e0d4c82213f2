"""Mode shapes of the frame's beam model: each mode in two projections (side view and top
view) with axes, the undeformed frame, the clamped points and the mode's type."""

import numpy as np

from ..core.errors import wrong_type
from ..fe.modes import Modes
from .figure import Figure, new_figure

SIDE, TOP = ((0, 2), (0, 1))
"""Global axes shown in the side view (x, height = -z) and the top view (x, y)."""
OUT_OF_PLANE = 0.8
"""Share of the squared translations that is lateral (y) above which a mode is out-of-plane
(below 1 - this: in-plane; between: coupled)."""


def _polyline(points, elements):
    """All element segments as one (3n, 3) line, NaN-separated (one plot call)."""
    segments = points[elements]
    gaps = np.full((len(elements), 1, 3), np.nan)
    return np.concatenate([segments, gaps], axis=1).reshape(-1, 3)


def classify(shape):
    """The type of a mode from its nodal shape (n, 6) = (ux, uy, uz, rx, ry, rz) per node.

    ``in-plane bending`` when the translations stay in the x-z plane of symmetry,
    ``out-of-plane`` ones are ``torsion`` when twist about the x axis (rx) outweighs
    rotation about the vertical (rz), else ``lateral bending``; ``coupled`` otherwise.
    A participation measure of the degrees of freedom, not a decomposition.
    """
    u = shape[:, :3]
    lateral = np.sum(u[:, 1] ** 2) / max(np.sum(u ** 2), 1e-300)
    if lateral < 1 - OUT_OF_PLANE:
        return "in-plane bending"
    if lateral <= OUT_OF_PLANE:
        return "coupled in- and out-of-plane"
    twist, sway = np.sum(shape[:, 3] ** 2), np.sum(shape[:, 5] ** 2)
    return "out-of-plane torsion" if twist > sway else "out-of-plane lateral bending"


def clamped_nodes(modes):
    """Indices of the nodes held in all six DOF (their shapes are exactly zero in every mode)."""
    per_node = modes.shapes.reshape(len(modes.mesh.nodes), 6, -1)
    return np.flatnonzero(np.all(per_node == 0, axis=(1, 2)))


def _limits(values, pad):
    return values.min() - pad, values.max() + pad


def _view(ax, points, moved, elements, axes, clamped, top, limits):
    a, b = axes
    sign = -1.0 if b == 2 else 1.0                    # height = -z in the side view
    for xyz, style in ((points, dict(color="0.7", lw=1.0)), (moved, dict(color="tab:blue", lw=1.5))):
        line = _polyline(xyz, elements)
        ax.plot(line[:, a], sign * line[:, b], **style)
    if len(clamped):
        ax.plot(points[clamped, a], sign * points[clamped, b], "^" if not top else "s", color="k", markersize=6,
                linestyle="none", zorder=5)
    ax.set_xlim(limits[0])
    ax.set_ylim(limits[1])
    ax.set_aspect("equal", adjustable="box")
    ax.tick_params(labelsize=7)
    ax.grid(alpha=0.25, lw=0.5)
    if top:
        ax.invert_yaxis()                             # seen from above: the right-hand side downwards


def plot_frame_modes(modes: "Modes", scale: float = 0.12, size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: the mode shapes of a frame's beam model, one row per mode, in a side view (x
    forward, height up) and a top view (seen from above, y to the right downwards), axes in metres.

    The undeformed frame is grey, the mode shape blue; a shape's amplitude is arbitrary, so
    each is drawn with its largest nodal translation ``scale`` times the frame's largest
    dimension (stated on the figure).  Clamped nodes are black markers; each row names the
    frequency and the mode type (:func:`~bikemass.plots.frame_modes.classify`).

    Parameters
    ----------
    modes : Modes
        From :func:`bikemass.frame_modes`.
    scale : float
        Drawn amplitude as a fraction of the frame's largest dimension.
    size : (float, float), optional
        Figure size (width, height) in inches; default 9 wide, 2.6 per mode.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputError
        Bad size.
    InputTypeError
        ``modes`` not frame modes.

    See Also
    --------
    frame_modes : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_frame_modes(bm.frame_modes("jamis", support="fix-rear", count=2))
    >>> len(fig.axes)                          # a side and a top view per mode
    4
    """
    if not hasattr(modes, "mesh"):
        raise wrong_type("modes", modes, "frame Modes (bm.frame_modes)")

    mesh = modes.mesh
    nodes = mesh.nodes
    extent = np.ptp(nodes, axis=0).max()
    count = len(modes.frequencies_hz)
    clamped = clamped_nodes(modes)
    fig = new_figure(size or (7.5, 0.9 + 1.9 * count))
    axes = fig.subplots(count, 2, squeeze=False)
    shapes = modes.shapes.T.reshape(count, -1, 6)
    peaks = np.abs(shapes[:, :, :3]).max(axis=(1, 2))
    moved = nodes + shapes[:, :, :3] * (scale * extent / np.where(peaks > 0, peaks, np.inf))[:, None, None]
    every = np.concatenate([nodes[None], moved]).reshape(-1, 3)
    pad = 0.04 * extent
    x, height, y = _limits(every[:, 0], pad), _limits(-every[:, 2], pad), _limits(every[:, 1], pad)
    for i in range(count):
        shape = shapes[i]
        side, top = axes[i]
        _view(side, nodes, moved[i], mesh.elements, SIDE, clamped, False, (x, height))
        _view(top, nodes, moved[i], mesh.elements, TOP, clamped, True, (x, y))
        side.set_ylabel("height (m)", fontsize=7)
        top.set_ylabel("y, right (m)", fontsize=7)
        side.set_title(f"mode {i + 1}: {modes.frequencies_hz[i]:.1f} Hz, {classify(shape)}", fontsize=8.5,
                       loc="left")
    axes[0, 0].annotate("side view", (0.99, 0.97), xycoords="axes fraction", ha="right", va="top", fontsize=7,
                        color="0.4")
    axes[0, 1].annotate("top view, from above", (0.99, 0.03), xycoords="axes fraction", ha="right",
                        va="bottom", fontsize=7, color="0.4")
    for ax in axes[-1]:
        ax.set_xlabel("x, forward (m)", fontsize=7)
    support = ("clamped nodes (all six DOF held): black" if len(clamped)
               else "free-free: no supports (rigid-body modes left out)")
    fig.suptitle(f"Rear-frame vibration modes ({modes.bc}); grey undeformed, blue deformed.\n"
                 f"Largest displacement drawn as {scale * extent * 1000:.0f} mm (amplitude arbitrary); "
                 f"{support}", fontsize=8.5)
    return fig
