"""Stability figures: the thesis's Fig. 4-4 layout and many-curve comparisons (Figs. 4-6, 5-2..5-15)."""

import numpy as np

from ..stability.labels import LABELS
from .figure import new_figure

MODE_COLOURS = {"weave 1": "tab:blue", "weave 2": "tab:cyan", "capsize": "tab:red", "caster": "tab:green"}
MODE_STYLES = {"weave 1": "-", "weave 2": "--", "capsize": "-.", "caster": ":"}


def _figure(nrows, ncols, size):
    fig = new_figure(size)
    return fig, fig.subplots(nrows, ncols, sharex=True, squeeze=False)


def _shade(ax, ranges, colour, label):
    for i, (a, b) in enumerate(ranges):
        ax.axvspan(a, b, color=colour, alpha=0.15, lw=0, label=label if i == 0 else None)


def plot_eigenvalues(result, title="", size=None, xlim=None, ylim=None):
    """Figure: real and imaginary parts (1/s), natural frequency (rad/s) and damping ratio against speed.

    ``result``: :class:`~bikemass.stability.modes.Modes`, or a
    :class:`~bikemass.stability.analysis.Stability` whose strictly stable speeds are shaded
    green and marginally stable ones grey.  ``xlim`` (m/s), ``ylim`` (1/s, real parts).
    """
    stability = result if hasattr(result, "modes") else None
    modes = result.modes if stability is not None else result
    fig, axes = _figure(2, 2, size or (11, 7.5))
    panels = ((axes[0, 0], lambda z: z.real, "real part (1/s)"),
              (axes[0, 1], lambda z: z.imag, "imaginary part (rad/s)"),
              (axes[1, 0], np.abs, "natural frequency (rad/s)"),
              (axes[1, 1], lambda z: -z.real / np.where(np.abs(z) > 0, np.abs(z), np.nan), "damping ratio"))
    v = modes.speeds
    for ax, part, ylabel in panels:
        for label in LABELS:
            ax.plot(v, part(modes[label]), MODE_STYLES[label], color=MODE_COLOURS[label], label=label)
        if stability is not None:
            _shade(ax, stability.ranges["marginal"]["exact"], "0.5", "marginally stable")
            _shade(ax, stability.ranges["strict"]["exact"], "tab:green", "stable")
        ax.axhline(0, color="k", lw=0.6)
        ax.set_ylabel(ylabel)
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=8, loc="best")
    for ax in axes[1]:
        ax.set_xlabel("speed (m/s)")
    fig.suptitle(title)
    axes[0, 0].set_xlim(xlim or (v[0], v[-1]))
    if ylim:
        axes[0, 0].set_ylim(ylim)
    return fig


def plot_comparison(curves, part="real", title="", size=None, xlim=None, ylim=None):
    """Figure: many bicycles on one axis: ``curves`` = ``{name: Modes}``; one colour per name, one line style per mode.

    ``part``: ``real`` (1/s), ``imag`` (rad/s), ``frequency`` (rad/s) or ``damping``; the
    real-part axis is scaled to the weave and capsize roots (the caster runs off it).
    """
    fig, axes = _figure(1, 1, size or (9, 5.5))
    ax = axes[0, 0]
    get = {"real": lambda z: z.real, "imag": lambda z: z.imag, "frequency": np.abs,
           "damping": lambda z: -z.real / np.where(np.abs(z) > 0, np.abs(z), np.nan)}[part]
    from matplotlib.lines import Line2D

    colours = [f"C{i % 10}" for i in range(len(curves))]
    for colour, (name, modes) in zip(colours, curves.items()):
        for label in LABELS:
            ax.plot(modes.speeds, get(modes[label]), MODE_STYLES[label], color=colour)
    handles = [Line2D([], [], color=c, label=name) for c, name in zip(colours, curves)]
    handles += [Line2D([], [], color="k", ls=MODE_STYLES[label], label=label) for label in LABELS]
    if part == "real":   # scale to weave and capsize; the fast caster roots run off the axis
        focus = np.concatenate([modes[label].real for modes in curves.values()
                                for label in LABELS if label != "caster"])
        lo, hi = np.nanmin(focus), np.nanmax(focus)
        pad = 0.08 * (hi - lo) or 1.0
        ax.set_ylim(lo - pad, hi + pad)
    ax.axhline(0, color="k", lw=0.6)
    ax.set_xlabel("speed (m/s)")
    ax.set_ylabel({"real": "real part (1/s)", "imag": "imaginary part (rad/s)",
                   "frequency": "natural frequency (rad/s)", "damping": "damping ratio"}[part])
    ax.grid(alpha=0.3)
    ax.legend(handles=handles, fontsize=8, ncol=2, loc="best")
    ax.set_title(title)
    if xlim:
        ax.set_xlim(xlim)
    if ylim:
        ax.set_ylim(ylim)
    return fig
