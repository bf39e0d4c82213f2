"""Figures of a sweep: heat maps over two varied keys, lines over one, scatter for samples.

Every figure is drawn from columns (arrays), so a sweep of a million rows is drawn in a few
seconds from its :class:`~bikemass.sweep.result.SweepResult` (a plain list of row dicts works
too).
"""

import numpy as np

from ..core.errors import InputError
from ..models.parameters import parameter_units
from ..plots.figure import Figure

from .layout import numeric_keys

SPEED_COLUMNS = ("weave_speed", "capsize_speed")


def key_unit(spec, key):
    """The unit the values of varied ``key`` are in: the unit they were given with, else the one
    its file writes there, else SI (a benchmark parameter's own: ``c`` m, ``lam`` rad; ``"SI"``
    for a bare number where the file has none either); ``None`` for a key with no number
    (a model or a pose name)."""
    if key not in numeric_keys(spec):
        return None
    if spec.units.get(key):
        return spec.units[key]
    if key in parameter_units():
        return parameter_units()[key]
    try:
        return spec.scenario().file_unit(key) or "SI"
    except (InputError, ValueError):
        return "SI"


def key_label(spec, key):
    """Axis label of varied ``key``: the key with its unit in parentheses (``c (m)``)."""
    unit = key_unit(spec, key)
    return key if unit is None else f"{key} ({unit})"


def _prefetch(rows, spec):
    """Read every column a figure draws from in one pass (a :class:`SweepResult` keeps them)."""
    if hasattr(rows, "columns"):
        rows.columns([*spec.keys, *SPEED_COLUMNS])


def _column(rows, key, numeric=True):
    """Column ``key`` of ``rows``: a float array (``nan`` for none) if ``numeric``, else an object array."""
    if hasattr(rows, "column"):
        values = rows.column(key)
    else:
        values = [r.get(key) for r in rows]
    if numeric:
        return np.array([np.nan if v is None else v for v in values], dtype=float) if isinstance(values, list) \
            else values
    out = np.empty(len(values), dtype=object)
    out[:] = list(values)
    return out


def heatmap_figure(rows, spec, size=None):
    """Weave and capsize speed over the grid of the first two varied keys (others at their first value;
    a value listed twice is drawn once, from its first row)."""
    kx, ky = spec.keys[:2]
    xs, ys = (np.array(sorted(set(v.grid())), dtype=float) for v in spec.variables[:2])
    numeric = numeric_keys(spec)
    pick = np.ones(len(rows), dtype=bool)
    for v in spec.variables[2:]:
        pick &= _column(rows, v.key, v.key in numeric) == v.grid()[0]
    ix = np.searchsorted(xs, _column(rows, kx)[pick])
    iy = np.searchsorted(ys, _column(rows, ky)[pick])
    cell = iy * len(xs) + ix
    _, first = np.unique(cell, return_index=True)                   # a repeated value: its first row
    fig = Figure(figsize=size or (11, 4.5), layout="constrained")
    axes = fig.subplots(1, 2)
    for ax, col in zip(axes, SPEED_COLUMNS):
        z = np.full(len(xs) * len(ys), np.nan)
        z[cell[first]] = _column(rows, col)[pick][first]
        mesh = _cells(ax, xs, ys, z.reshape(len(ys), len(xs)))
        fig.colorbar(mesh, ax=ax, label=f"{col.replace('_', ' ')} (m/s)")
        ax.set_xlabel(key_label(spec, kx))
        ax.set_ylabel(key_label(spec, ky))
        ax.set_title(col.replace("_", " ") + " (blank: none)")
    return fig


def _unit_suffix(spec, key):
    unit = key_unit(spec, key)
    return "" if unit in (None, "SI") else f" {unit}"


def _evenly_spaced(values):
    return len(values) < 2 or np.allclose(np.diff(values), values[1] - values[0], rtol=1e-9, atol=0)


def _cells(ax, xs, ys, z):
    """``z`` (len(ys), len(xs)) drawn as cells centred on the grid values: an image on an evenly
    spaced grid (a million cells in a fraction of a second), else a mesh of quadrilaterals."""
    if len(xs) > 1 and len(ys) > 1 and _evenly_spaced(xs) and _evenly_spaced(ys):
        dx, dy = (xs[-1] - xs[0]) / (len(xs) - 1), (ys[-1] - ys[0]) / (len(ys) - 1)
        return ax.imshow(z, origin="lower", aspect="auto", interpolation="nearest", cmap="viridis",
                         extent=(xs[0] - dx / 2, xs[-1] + dx / 2, ys[0] - dy / 2, ys[-1] + dy / 2))
    return ax.pcolormesh(xs, ys, z, shading="nearest", cmap="viridis")


def lines_figure(rows, spec, size=None, max_lines=8):
    """Critical speeds against the first varied key; one line per value of the second (up to ``max_lines``)."""
    kx = spec.keys[0]
    fig = Figure(figsize=size or (11, 4.5), layout="constrained")
    axes = fig.subplots(1, 2, sharex=True)
    groups = {None: np.ones(len(rows), dtype=bool)}
    if len(spec.keys) > 1:
        ky = spec.keys[1]
        second = _column(rows, ky, ky in numeric_keys(spec))
        values = list(dict.fromkeys(second.tolist()))
        chosen = values[:: max(1, len(values) // max_lines)][:max_lines]
        groups = {v: second == v for v in chosen}
    x = _column(rows, kx)
    for ax, col in zip(axes, SPEED_COLUMNS):
        y = _column(rows, col)
        for value, member in groups.items():
            label = None if value is None else f"{spec.keys[1]} = {value:.4g}{_unit_suffix(spec, spec.keys[1])}" if isinstance(value, float) else str(value)
            ax.plot(x[member], y[member], marker=".", label=label)
        ax.set_xlabel(key_label(spec, kx))
        ax.set_ylabel(f"{col.replace('_', ' ')} (m/s)")
        ax.grid(alpha=0.3)
    if len(groups) > 1:
        axes[1].legend(fontsize=7)
    return fig


def scatter_figure(rows, spec, size=None):
    """Each critical speed against each varied key (sampled designs)."""
    keys = [k for k in spec.keys if k in numeric_keys(spec)]
    fig = Figure(figsize=size or (3.2 * max(len(keys), 1) + 1, 6), layout="constrained")
    axes = fig.subplots(2, max(len(keys), 1), squeeze=False)
    for j, key in enumerate(keys):
        for i, col in enumerate(SPEED_COLUMNS):
            axes[i, j].plot(_column(rows, key), _column(rows, col), ".", ms=3, alpha=0.6)
            axes[i, j].set_xlabel(key_label(spec, key))
            axes[i, j].set_ylabel(f"{col.replace('_', ' ')} (m/s)")
    return fig


def sweep_figures(rows, spec, size=None):
    """``{file stem: Figure}`` suited to the design: grid -> lines (+ heat map for 2+ numeric keys)."""
    numeric = [k for k in spec.keys if k in numeric_keys(spec)]
    _prefetch(rows, spec)
    if spec.method != "grid" or spec.global_sensitivity:
        return {"scatter": scatter_figure(rows, spec, size)}
    figures = {}
    if spec.keys[0] in numeric:
        figures["lines"] = lines_figure(rows, spec, size)
    if len(numeric) >= 2 and numeric[:2] == list(spec.keys[:2]):
        figures["heatmap"] = heatmap_figure(rows, spec, size)
    return figures
