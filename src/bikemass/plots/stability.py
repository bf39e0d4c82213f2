"""Eigenvalues against speed in the field's convention (Meijaard et al. 2007, Fig. 3): real
parts (solid) and imaginary parts (dashed) of every mode on one axis, zoomed to where the
modes cross zero, the fast caster root clipped with a note, the weave and capsize speeds
marked with their values and the stable speeds shaded."""

from collections.abc import Mapping
from dataclasses import dataclass
from typing import Protocol

import numpy as np

from ..core.errors import wrong_type
from .figure import Figure, check_limits, new_figure

SIZE = (7.0, 4.6)
"""Default figure size (inches): a journal's two-column width."""

REAL_WEAVE = "weave as real roots"
COLOURS = {"weave": "tab:blue", REAL_WEAVE: "tab:purple", "capsize": "tab:red", "caster": "tab:green"}
OTHER_COLOURS = ("tab:orange", "tab:brown", "tab:pink", "tab:olive", "tab:cyan", "tab:gray", "navy", "gold",
                 "teal", "maroon", "lime", "black")
"""Colours of the other modes (the richer models' lean, tyre, wobble, ...), in order of appearance,
none of them one of :data:`COLOURS`: one colour per legend entry (cycling only past twelve)."""
OTHER_COLOUR = OTHER_COLOURS[0]
LEGEND_ORDER = ("weave", REAL_WEAVE, "capsize", "caster")
BICYCLE_MODES = ("weave", REAL_WEAVE, "capsize")
"""The modes whose roots set the eigenvalue axis (with those of other modes of like size)."""
OFF_SCALE_FACTOR = 3.0
"""Another mode's roots widen the automatic eigenvalue axis only if they stay within this many
times the bicycle modes' reach; a mode beyond it (a 64 Hz fork mode, a fast tyre lag) is left
off-scale and named in a note, so the weave and capsize roots keep their room."""


def legend_name(name):
    """The name a reader sees for a name of :meth:`~bikemass.analysis.engine.modes.Modes.names`: the
    weave's real branches as one entry (a tracked weave label alone is a real root whose
    partner has paired elsewhere), tracking numbers dropped from other pairs."""
    if name.startswith("weave, real") or name in ("weave 1", "weave 2"):
        return REAL_WEAVE
    return name.replace("weave 1", "weave").replace("weave 2", "weave")
STABLE_COLOUR = "tab:green"
CLIPPED = "caster"
"""The mode whose fast, strongly damped root runs off the zoomed axis."""


class Modes(Protocol):
    """What :func:`plot_eigenvalues` draws of :class:`bikemass.analysis.engine.modes.Modes`
    (``bm.eigenvalues``): a protocol, as this layer sits below the analyses it draws."""

    @property
    def speeds(self) -> np.ndarray: ...        # (n,) m/s

    @property
    def eigenvalues(self) -> np.ndarray: ...   # (n, m) complex, 1/s

    def names(self) -> tuple: ...


class StabilityResult(Protocol):
    """What the figures read of :class:`bikemass.analysis.engine.stability.StabilityResult`
    (``bm.stability``): a protocol, as this layer sits below the analyses it draws."""

    @property
    def modes(self) -> Modes: ...

    @property
    def weave_speeds(self) -> tuple: ...       # m/s

    @property
    def capsize_speeds(self) -> tuple: ...     # m/s

    @property
    def ranges(self) -> Mapping: ...


@dataclass(frozen=True)
class CriticalSpeeds:
    """What the figures mark: ``weave`` and ``capsize`` speeds (m/s, where an oscillatory or a
    real root crosses Re = 0) and the ``stable`` speed ranges ``[[start, stop], ...]`` (m/s)."""

    weave: tuple = ()
    capsize: tuple = ()
    stable: tuple = ()

    @classmethod
    def of(cls, stability):
        """From a :class:`~bikemass.analysis.engine.stability.StabilityResult` (exact speeds, strict ranges)."""
        return cls(tuple(stability.weave_speeds), tuple(stability.capsize_speeds),
                   tuple(map(tuple, stability.ranges["strict"]["exact"])))


def plot_eigenvalues(result: "StabilityResult | Modes", title: str = "", size: "tuple[float, float] | None" = None,
                     xlim: "tuple[float, float] | None" = None,
                     ylim: "tuple[float, float] | None" = None) -> Figure:
    """Figure: eigenvalues (1/s) against speed (m/s) in the field's convention (Meijaard et al.
    2007, Fig. 3).

    Real parts solid and imaginary parts dashed on one axis, one colour per mode, zoomed to about
    1.6 times the last critical speed and to the weave and capsize roots; the fast caster root is
    clipped with a note; the weave and capsize speeds are dotted lines with their values and the
    stable speeds are shaded (docs/figures.md).

    Parameters
    ----------
    result : StabilityResult or Modes
        From :func:`bikemass.stability` (critical speeds marked, stable speeds shaded) or
        :func:`bikemass.eigenvalues` (the curves alone).
    title : str
        Axes title.
    size : (float, float), optional
        Figure size (width, height) in inches; default 7 x 4.6.
    xlim : (float, float), optional
        Speed range (m/s), overriding the automatic zoom.
    ylim : (float, float), optional
        Eigenvalue range (1/s), overriding the automatic zoom.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputError
        Bad size or limits.
    InputTypeError
        ``result`` of another type.

    See Also
    --------
    stability : What it draws.
    plot_critical_speeds : Many results on one figure.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_eigenvalues(bm.stability(bm.parameters("benchmark")), title="benchmark")
    >>> ax = fig.axes[0]
    >>> [t.get_text() for t in ax.get_legend().get_texts()][:4]
    ['weave', 'weave as real roots', 'capsize', 'caster']
    >>> [t.get_text() for t in ax.texts if t.get_text().startswith("=")]     # v_w and v_c marked
    ['= 4.29 m/s ', '= 6.02 m/s ']
    >>> [float(x) for x in ax.get_xlim()]               # 0 to about 1.6 times the capsize speed
    [0.0, 10.0]
    """
    if not hasattr(result, "modes") and not hasattr(result, "eigenvalues"):
        raise wrong_type("result", result, "a StabilityResult (bm.stability) or Modes (bm.eigenvalues)")
    if hasattr(result, "modes"):
        return eigenvalue_figure(result.modes, CriticalSpeeds.of(result), title, size, xlim, ylim)
    return eigenvalue_figure(result, CriticalSpeeds(), title, size, xlim, ylim)


def default_xlim(speeds, critical):
    """Speed range (m/s) shown: from the first speed to about 1.6 times the last critical speed
    (whole metres per second), or the whole sweep if nothing crosses."""
    marks = [*critical.weave, *critical.capsize]
    if not marks:
        return float(speeds[0]), float(speeds[-1])
    return float(speeds[0]), float(min(speeds[-1], max(np.ceil(1.6 * max(marks)), speeds[0] + 1)))


def _mode_reach(speeds, eigenvalues, names, xlim):
    """``{legend name: largest |Re| or |Im| (1/s) in xlim}`` of every mode (the clipped caster root
    not among them)."""
    inside = (speeds >= xlim[0]) & (speeds <= xlim[1])
    reach = {}
    for name in dict.fromkeys(names[inside].ravel()):
        if name == CLIPPED:
            continue
        values = eigenvalues[inside][names[inside] == name]
        top = max(np.abs(values.real).max(initial=0), np.abs(values.imag).max(initial=0))
        legend = legend_name(name)
        reach[legend] = max(reach.get(legend, 0.0), float(top))
    return reach


def default_ylim(speeds, eigenvalues, names, xlim):
    """Eigenvalue range (1/s) shown, symmetric about zero, with a margin: the roots of the
    bicycle modes (:data:`BICYCLE_MODES`) in ``xlim`` and those of every other mode within
    :data:`OFF_SCALE_FACTOR` times their reach (the clipped caster root never counts)."""
    reach = _mode_reach(speeds, eigenvalues, names, xlim)
    core = max((r for name, r in reach.items() if name in BICYCLE_MODES), default=0.0)
    shown = [r for name, r in reach.items() if name in BICYCLE_MODES or not core or r <= OFF_SCALE_FACTOR * core]
    top = 1.08 * max(shown, default=0.0) or 1.0
    return -top, top


def off_scale(speeds, eigenvalues, names, xlim, ylim):
    """``{legend name: largest |Re| or |Im| (1/s)}`` of the modes with roots outside ``ylim``
    within ``xlim`` (the clipped caster root has its own note)."""
    low, high = min(ylim), max(ylim)
    inside = (speeds >= xlim[0]) & (speeds <= xlim[1])
    out = {}
    for name in dict.fromkeys(names[inside].ravel()):
        if name == CLIPPED:
            continue
        values = eigenvalues[inside][names[inside] == name]
        parts = np.concatenate([values.real, np.abs(values.imag[values.imag != 0])])
        if parts.size and ((parts < low) | (parts > high)).any():
            legend = legend_name(name)
            out[legend] = max(out.get(legend, 0.0), float(np.abs(parts).max()))
    return out


def _off_scale_note(ax, far):
    """A note under the legend naming the modes off the axis and how far they reach."""
    if not far:
        return None
    lines = [f"{name}: |$\\lambda$| parts to {value:.3g} 1/s" for name, value in far.items()]
    return ax.text(1.01, 0.0, "off the axis:\n" + "\n".join(lines), transform=ax.transAxes, ha="left",
                   va="bottom", fontsize=7.5, color="0.25")


def mode_colours(names):
    """``{name: colour}`` for legend ``names`` (in order): :data:`COLOURS` for the bicycle's
    modes, :data:`OTHER_COLOURS` in turn for every other name, so no two names share a colour
    (up to twelve others)."""
    colours = {}
    for name in names:
        if name not in colours:
            others = sum(1 for n in colours if n not in COLOURS)
            colours[name] = COLOURS.get(name, OTHER_COLOURS[others % len(OTHER_COLOURS)])
    return colours


def _grown(mask):
    """``mask`` with one more point at both ends of every run, so neighbouring pieces join."""
    out = mask.copy()
    out[1:] |= mask[:-1]
    out[:-1] |= mask[1:]
    return out


def _draw_curves(ax, speeds, eigenvalues, names):
    """Real (solid) and positive imaginary (dashed) parts, one colour per physical name."""
    drawn = {}
    colours = mode_colours(legend_name(name) for name in dict.fromkeys(names.ravel()))
    for name in dict.fromkeys(names.ravel()):
        legend = legend_name(name)
        colour = colours[legend]
        for c in range(eigenvalues.shape[1]):
            mask = names[:, c] == name
            if not mask.any():
                continue
            z = eigenvalues[:, c]
            oscillating = mask & (z.imag != 0)
            if oscillating.any() and (z.imag[oscillating] < 0).all():
                continue                       # the lower member of a pair: its mirror is drawn
            shown = _grown(mask)
            label = legend if legend not in drawn else None
            line, = ax.plot(speeds, np.where(shown, z.real, np.nan), "-", color=colour, lw=1.6, label=label)
            drawn.setdefault(legend, line)
            if oscillating.any():
                ax.plot(speeds, np.where(_grown(oscillating), np.abs(z.imag), np.nan), "--", color=colour, lw=1.2)
    return drawn


def _caster_note(ax, speeds, eigenvalues, names, xlim, ylim):
    """A note where the caster root leaves the axis (where it does)."""
    columns = [c for c in range(names.shape[1]) if (names[:, c] == CLIPPED).any()]
    if not columns:
        return None
    z = eigenvalues[:, columns[0]]
    inside = (speeds >= xlim[0]) & (speeds <= xlim[1]) & (names[:, columns[0]] == CLIPPED)
    below = inside & (z.real < ylim[0])
    if not below.any():
        return None
    start = speeds[below][0]
    low = f"{z.real[inside].min():.0f}".replace("-", "\u2212")
    text = (f"caster mode below the axis from {start:.1f} m/s\n(Re $\\lambda$ down to {low} 1/s)"
            if start > xlim[0] else f"caster mode below the axis\n(Re $\\lambda$ down to {low} 1/s)")
    return ax.annotate(text, xy=(min(max(start, xlim[0]), xlim[1]), ylim[0]), xycoords="data",
                       xytext=(6, 10), textcoords="offset points", fontsize=8, color=COLOURS[CLIPPED],
                       ha="left", va="bottom", arrowprops=dict(arrowstyle="->", color=COLOURS[CLIPPED], lw=0.8))


def _mark(ax, speed, symbol, xlim):
    """A dotted vertical line at a critical speed with its symbol and value at the top of the
    axis, reading upwards: the symbol (mathtext) and the value (plain text, so that the number
    stays one editable string in SVG and PDF)."""
    ax.axvline(speed, color="0.25", lw=0.8, ls=":")
    side = "left" if speed < xlim[0] + 0.85 * (xlim[1] - xlim[0]) else "right"
    box = dict(facecolor="white", edgecolor="none", alpha=0.8, pad=0.4)
    value = ax.text(speed, 0.98, f"= {speed:.2f} m/s ", transform=ax.get_xaxis_transform(), rotation=90,
                    ha=side, va="top", fontsize=8, bbox=box)
    name = ax.annotate(f" ${symbol}$ ", xy=(0.5, 0.0), xycoords=value, rotation=90, ha="center", va="top",
                       fontsize=8, bbox=box)
    return value, name


def mark_critical_speeds(ax, critical, xlim):
    """Mark the weave (v_w) and capsize (v_c) speeds inside ``xlim``; return the value texts."""
    texts = []
    for speeds, letter in ((critical.weave, "w"), (critical.capsize, "c")):
        for i, v in enumerate(speeds):
            if xlim[0] <= v <= xlim[1]:
                subscript = letter if len(speeds) == 1 else f"{letter},{i + 1}"
                texts.append(_mark(ax, v, f"v_\\mathrm{{{subscript}}}", xlim)[0])
    return texts


def eigenvalue_figure(modes, critical, title="", size=None, xlim=None, ylim=None):
    """Figure: the Meijaard-style eigenvalue plot of ``modes`` with :class:`CriticalSpeeds` ``critical``."""
    xlim, ylim = check_limits(xlim, "xlim"), check_limits(ylim, "ylim")
    fig = new_figure(size or SIZE)
    draw_eigenvalues(fig.subplots(), modes, critical, title, xlim, ylim)
    return fig


def clear_axes(ax):
    """Remove what :func:`draw_eigenvalues` drew on ``ax`` (lines, patches, texts, collections,
    legend, title), keeping the axes, their axis objects and ticks, so it can draw on them again
    (matplotlib's ``Axes.clear`` makes the ticks anew; making them is a tenth of drawing a figure)."""
    for artist in (*ax.lines, *ax.patches, *ax.texts, *ax.collections, *ax.images, *ax.artists, *ax.tables):
        artist.remove()
    if ax.get_legend() is not None:
        ax.get_legend().remove()
    ax.set_title("")


def draw_eigenvalues(ax, modes, critical, title="", xlim=None, ylim=None):
    """Draw :func:`eigenvalue_figure`'s plot on the empty axes ``ax`` (limits checked already)."""
    speeds, eigenvalues = modes.speeds, modes.eigenvalues
    names = modes.names()
    xlim = xlim or default_xlim(speeds, critical)
    ylim = ylim or default_ylim(speeds, eigenvalues, names, xlim)
    for i, (a, b) in enumerate(critical.stable):
        ax.axvspan(a, b, color=STABLE_COLOUR, alpha=0.12, lw=0,
                   label="stable: every Re $\\lambda$ < 0" if i == 0 else None)
    _draw_curves(ax, speeds, eigenvalues, names)
    ax.axhline(0, color="k", lw=0.7)
    ax.set_xlim(xlim)
    ax.set_ylim(ylim)
    mark_critical_speeds(ax, critical, xlim)
    _caster_note(ax, speeds, eigenvalues, names, xlim, ylim)
    _off_scale_note(ax, off_scale(speeds, eigenvalues, names, xlim, ylim))
    ax.plot([], [], "-", color="0.3", label="real part")
    ax.plot([], [], "--", color="0.3", label="imaginary part")
    handles, labels = ax.get_legend_handles_labels()
    rank = {label: LEGEND_ORDER.index(label) if label in LEGEND_ORDER else len(LEGEND_ORDER) + i
            for i, label in enumerate(labels)}
    order = sorted(range(len(labels)), key=lambda i: rank[labels[i]])
    ax.set_xlabel("forward speed $v$ (m/s)")
    ax.set_ylabel("eigenvalue $\\lambda$ (1/s)")
    ax.legend([handles[i] for i in order], [labels[i] for i in order], fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0, frameon=False)
    ax.grid(alpha=0.25, lw=0.5)
    if title:
        ax.set_title(title, fontsize=10, y=1.0)    # y given: matplotlib skips re-measuring the axes to place it
