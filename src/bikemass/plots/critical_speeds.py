"""Many configurations compared by their result: a dot plot of each one's weave and capsize
speeds and the stable speeds between them (one row per configuration, one colour per series)."""

from collections.abc import Mapping

import numpy as np
from matplotlib import colormaps

from ..core.errors import InputError, wrong_type
from .figure import Figure, check_limits, new_figure
from .stability import CriticalSpeeds, StabilityResult

WEAVE_MARKER, CAPSIZE_MARKER = "o", "s"


def _critical(result):
    return result if isinstance(result, CriticalSpeeds) else CriticalSpeeds.of(result)


def series_colours(count):
    """``count`` colours of one sequential scale, dark to light (rigid to softest frame, say)."""
    return [colormaps["viridis"](x) for x in np.linspace(0.0, 0.8, count)] if count > 1 else ["tab:blue"]


def _write_values(ax, speeds, y, xlim):
    """Each speed beside its mark: the first to the left, the others to the right; returns the
    texts written to the right."""
    right = []
    for k, v in enumerate(speeds):
        if xlim[0] <= v <= xlim[1]:
            text = ax.annotate(f"{v:.2f}", (v, y), xytext=(5 if k else -5, 0), textcoords="offset points",
                               ha="left" if k else "right", va="center", fontsize=6.5)
            if k:
                right.append(text)
    return right


def _no_stable_speed(ax, y, marks, after, xlim):
    """The note "no stable speed" on a row: right of its last value written right of a mark
    (``after``), else right of its last mark inside ``xlim``, else at the axis's left end (never
    over the value written left of the first mark)."""
    style = dict(textcoords="offset points", va="center", fontsize=6.5, color="0.4")
    inside = [v for v in marks if xlim[0] <= v <= xlim[1]]
    if after:
        return ax.annotate("no stable speed", (1.0, 0.5), xycoords=after[-1], xytext=(6, 0), **style)
    if inside:
        return ax.annotate("no stable speed", (max(inside), y), xytext=(7, 0), **style)
    return ax.annotate("no stable speed", (xlim[0], y), xytext=(4, 0), **style)


def plot_critical_speeds(results: "Mapping[str, Mapping[str, StabilityResult | CriticalSpeeds]]", title: str = "",
                         size: "tuple[float, float] | None" = None, xlim: "tuple[float, float] | None" = None,
                         values: bool = True) -> Figure:
    """Figure: the weave and capsize speeds of many configurations and the stable speeds between.

    Each configuration is a line: a bar over its stable speeds, a circle at each weave speed, a
    square at each capsize speed, the speeds written beside the marks (or the bar's ends where no
    crossing speeds are given) if ``values``. Rows top to bottom, one colour per series.

    Parameters
    ----------
    results : Mapping of Mapping
        ``{row: {series: result}}`` (e.g. rider -> stiffness -> result); each result a
        :class:`~bikemass.StabilityResult` or :class:`~bikemass.plots.stability.CriticalSpeeds`.
    title : str
        Figure title.
    size : (float, float), optional
        Figure size (width, height) in inches; default 7 wide, the height from the rows.
    xlim : (float, float), optional
        Speed range (m/s); default from 0 to beyond the largest critical speed.
    values : bool
        Write each speed beside its mark.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputError
        No result to draw, or bad size or limits.
    InputTypeError
        ``results`` not a mapping of mappings.

    See Also
    --------
    stability : What each result is.
    plot_eigenvalues : One result in full.

    Examples
    --------
    >>> import bikemass as bm
    >>> bike = bm.load_bicycle("jamis")
    >>> p = bm.parameters(bike, "relaxed")
    >>> results = {"relaxed": {frame: bm.stability(p, stiffness=bm.stiffness(bike, frame))
    ...                        for frame in ("infinite", "steel", "aluminum")}}
    >>> fig = bm.plot_critical_speeds(results, title="Jamis + Relaxed")
    >>> [t.get_text() for t in fig.axes[0].get_yticklabels()]
    ['relaxed']
    """
    if not isinstance(results, Mapping) or not all(isinstance(row, Mapping) for row in results.values()):
        raise wrong_type("results", results, "a mapping {row: {series: result}}")
    if not results or not any(results.values()):
        raise InputError("results", "(argument)", "at least one result to draw")
    rows = list(results)
    series = list(dict.fromkeys(s for row in results.values() for s in row))
    colours = dict(zip(series, series_colours(len(series))))
    height = 0.8 / len(series)
    fig = new_figure(size or (7.0, 1.2 + 0.22 * len(rows) * len(series)))
    ax = fig.subplots()
    marks = [v for row in results.values() for r in row.values()
             for v in (*_critical(r).weave, *_critical(r).capsize)]
    ends = [v for row in results.values() for r in row.values() for span in _critical(r).stable for v in span]
    xlim = check_limits(xlim, "xlim") or ((0.0, 1.12 * max(marks + ends, default=10.0) + 0.5))
    for i, row in enumerate(rows):
        for j, name in enumerate(series):
            if name not in results[row]:
                continue
            c, colour = _critical(results[row][name]), colours[name]
            y = i + (j - (len(series) - 1) / 2) * height
            for a, b in c.stable:
                ax.plot([a, b], [y, y], "-", color=colour, lw=4.5, alpha=0.45, solid_capstyle="butt")
            for speeds, marker in ((c.weave, WEAVE_MARKER), (c.capsize, CAPSIZE_MARKER)):
                ax.plot(speeds, [y] * len(speeds), marker, color=colour, markeredgecolor="k", markersize=5,
                        markeredgewidth=0.6, zorder=3, linestyle="none")
            after = (_write_values(ax, sorted((*c.weave, *c.capsize)) or [v for r in c.stable for v in r], y, xlim)
                     if values else [])
            if not c.stable:
                _no_stable_speed(ax, y, (*c.weave, *c.capsize), after, xlim)
    if len(rows) > 1:
        for i in range(len(rows) - 1):
            ax.axhline(i + 0.5, color="0.85", lw=0.6)
    ax.set_yticks(range(len(rows)), [str(r) for r in rows])
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.set_xlim(xlim)
    ax.set_xlabel("forward speed (m/s)")
    ax.grid(axis="x", alpha=0.25, lw=0.5)
    ax.tick_params(axis="y", length=0)
    for name in series if len(series) > 1 else ():
        ax.plot([], [], "-", lw=4.5, alpha=0.6, color=colours[name], label=str(name))
    if marks:
        ax.plot([], [], WEAVE_MARKER, color="0.7", markeredgecolor="k", label="weave speed $v_\\mathrm{w}$")
        ax.plot([], [], CAPSIZE_MARKER, color="0.7", markeredgecolor="k", label="capsize speed $v_\\mathrm{c}$")
    ax.plot([], [], "-", lw=4.5, alpha=0.45, color="0.5", label="stable speeds")
    ax.legend(fontsize=7.5, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0, frameon=False)
    if title:
        ax.set_title(title, fontsize=10, y=1.0)    # y given: matplotlib skips re-measuring the axes to place it
    return fig
