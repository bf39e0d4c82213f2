"""Figures of a sweep: heat maps over two varied keys, lines over one, scatter for samples."""

import numpy as np
from ..plots.figure import Figure

SPEED_COLUMNS = ("weave_speed", "capsize_speed")


def _column(rows, key):
    return np.array([np.nan if r.get(key) is None else float(r[key]) for r in rows])


def _numeric(rows, key):
    return all(isinstance(r[key], (int, float)) for r in rows)


def heatmap_figure(rows, spec, size=None):
    """Weave and capsize speed over the grid of the first two varied keys (others at their first value;
    a value listed twice is drawn once, from its first row)."""
    kx, ky = spec.keys[:2]
    xs, ys = (sorted(set(v.grid())) for v in spec.variables[:2])    # a value listed twice is one column
    first = {v.key: v.grid()[0] for v in spec.variables[2:]}
    cells = {}
    for r in rows:
        if all(r[k] == v for k, v in first.items()):
            cells.setdefault((r[kx], r[ky]), r)
    fig = Figure(figsize=size or (11, 4.5), layout="constrained")
    axes = fig.subplots(1, 2)
    for ax, col in zip(axes, SPEED_COLUMNS):
        z = np.array([[np.nan if cells[x, y].get(col) is None else float(cells[x, y][col]) for x in xs]
                      for y in ys])
        mesh = ax.pcolormesh(xs, ys, z, shading="nearest", cmap="viridis")
        fig.colorbar(mesh, ax=ax, label=f"{col.replace('_', ' ')} (m/s)")
        ax.set_xlabel(kx)
        ax.set_ylabel(ky)
        ax.set_title(col.replace("_", " ") + " (blank: none)")
    return fig


def lines_figure(rows, spec, size=None, max_lines=8):
    """Critical speeds against the first varied key; one line per value of the second (up to ``max_lines``)."""
    kx = spec.keys[0]
    fig = Figure(figsize=size or (11, 4.5), layout="constrained")
    axes = fig.subplots(1, 2, sharex=True)
    groups = {None: rows}
    if len(spec.keys) > 1:
        ky = spec.keys[1]
        values = list(dict.fromkeys(r[ky] for r in rows))
        chosen = values[:: max(1, len(values) // max_lines)][:max_lines]
        groups = {v: [r for r in rows if r[ky] == v] for v in chosen}
    for ax, col in zip(axes, SPEED_COLUMNS):
        for value, group in groups.items():
            label = None if value is None else f"{spec.keys[1]} = {value:.4g}" if isinstance(value, float) else str(value)
            ax.plot(_column(group, kx), _column(group, col), marker=".", label=label)
        ax.set_xlabel(kx)
        ax.set_ylabel(f"{col.replace('_', ' ')} (m/s)")
        ax.grid(alpha=0.3)
    if len(groups) > 1:
        axes[1].legend(fontsize=7)
    return fig


def scatter_figure(rows, spec, size=None):
    """Each critical speed against each varied key (sampled designs)."""
    keys = [k for k in spec.keys if _numeric(rows, k)]
    fig = Figure(figsize=size or (3.2 * max(len(keys), 1) + 1, 6), layout="constrained")
    axes = fig.subplots(2, max(len(keys), 1), squeeze=False)
    for j, key in enumerate(keys):
        for i, col in enumerate(SPEED_COLUMNS):
            axes[i, j].plot(_column(rows, key), _column(rows, col), ".", ms=3, alpha=0.6)
            axes[i, j].set_xlabel(key)
            axes[i, j].set_ylabel(f"{col.replace('_', ' ')} (m/s)")
    return fig


def sweep_figures(rows, spec, size=None):
    """``{file stem: Figure}`` suited to the design: grid -> lines (+ heat map for 2+ numeric keys)."""
    numeric = [k for k in spec.keys if _numeric(rows, k)]
    if spec.method != "grid" or spec.global_sensitivity:
        return {"scatter": scatter_figure(rows, spec, size)}
    figures = {}
    if _numeric(rows, spec.keys[0]):
        figures["lines"] = lines_figure(rows, spec, size)
    if len(numeric) >= 2 and numeric[:2] == list(spec.keys[:2]):
        figures["heatmap"] = heatmap_figure(rows, spec, size)
    return figures
