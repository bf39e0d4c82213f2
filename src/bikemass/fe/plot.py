"""Mode shapes drawn on the frame: one 3D panel per mode."""

import numpy as np


def _polyline(points, elements):
    """All element segments as one (3n, 3) line, NaN-separated (one plot call)."""
    segments = points[elements]
    gaps = np.full((len(elements), 1, 3), np.nan)
    return np.concatenate([segments, gaps], axis=1).reshape(-1, 3)


def plot_frame_modes(modes, scale=0.12, size=None):
    """Figure: the undeformed frame (grey) and each mode shape (blue), height drawn upward.

    Each shape is scaled so that its largest nodal translation is ``scale`` times
    the frame's largest dimension.
    """
    from ..plots.figure import new_figure

    mesh = modes.mesh
    nodes = mesh.nodes
    extent = np.ptp(nodes, axis=0).max()
    count = len(modes.frequencies_hz)
    cols = min(count, 4)
    rows = int(np.ceil(count / cols))
    fig = new_figure(size or (3.2 * cols, 3.0 * rows))
    for i in range(count):
        shape = modes.shapes[:, i].reshape(-1, 6)[:, :3]
        peak = np.abs(shape).max()
        moved = nodes + shape * (scale * extent / peak if peak > 0 else 0.0)
        ax = fig.add_subplot(rows, cols, i + 1, projection="3d")
        for points, style in ((nodes, dict(color="0.7", lw=1.0)), (moved, dict(color="tab:blue", lw=1.6))):
            line = _polyline(points, mesh.elements)
            ax.plot(line[:, 0], line[:, 1], -line[:, 2], **style)
        ax.set_title(f"mode {i + 1}: {modes.frequencies_hz[i]:.2f} Hz", fontsize=9)
        ax.set_box_aspect(np.ptp(np.vstack([nodes, moved]), axis=0) + 1e-9)
        ax.set_axis_off()
    fig.suptitle(f"rear-frame modes, {modes.bc}", fontsize=10)
    return fig
