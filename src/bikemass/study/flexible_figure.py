"""The study's figure of the flexible frame and fork (:mod:`~bikemass.study.flexible`): one row per
bicycle; the wobble's frequency by rider and material beside the published bands, the speeds where
it is unstable beside the capsize speeds of the rigid frame, the thesis's spring and the flexible
model, and the leaning rider's weave speed beside the rigid rider's.  Returns a new
:class:`matplotlib.figure.Figure` (no pyplot)."""

import numpy as np

from ..plots.critical_speeds import series_colours
from ..plots.figure import new_figure
from .configurations import THESIS_NAMES

BAND_COLOURS = ("#dbe9f6", "#f6e3cf")
MODELS = {"rigid": ("0.55", "rigid frame"), "spring": ("tab:blue", "thesis's spring"),
          "beams": ("tab:orange", "flexible frame and fork")}
"""Colour and legend of each model's critical speeds."""
MARKERS = (("o", "weave"), ("s", "capsize"))


def _keys(results):
    bikes = list(dict.fromkeys(b for b, _, _ in results.wobble))
    riders = list(dict.fromkeys(r for _, r, _ in results.wobble))
    materials = list(dict.fromkeys(m for _, _, m in results.wobble))
    return bikes, riders, materials


def _frequencies(ax, results, bike, riders, materials, colours, bands, speed):
    for k, band in enumerate(bands):
        ax.axhspan(band["low"], band["high"], color=BAND_COLOURS[k % len(BAND_COLOURS)], alpha=0.7, lw=0,
                   label=f"{band['name']}: {band['low']:g}-{band['high']:g} Hz")
    x = np.arange(len(riders))
    for material in materials:
        w = [results.wobble[bike, r, material] for r in riders]
        f = np.array([np.nan if x.frequency is None else x.frequency for x in w])
        grows = np.array([x.growth is not None and x.growth > 0 for x in w])
        ax.plot(x, f, "-", color=colours[material], lw=1)
        ax.plot(x[grows], f[grows], "o", color=colours[material], ms=6, label=THESIS_NAMES[material])
        ax.plot(x[~grows], f[~grows], "o", mfc="white", mec=colours[material], ms=6)
    ax.set_xticks(x, [THESIS_NAMES[r] for r in riders], fontsize="x-small", rotation=20)
    ax.set_ylabel(f"wobble at {speed:g} m/s (Hz)")
    ax.set_ylim(0, max(14.0, *(b["high"] + 1 for b in bands)))
    ax.grid(True, axis="y", alpha=0.3)
    ax.legend(fontsize="xx-small", loc="upper right", title="filled: growing", title_fontsize="xx-small")


def _speeds(ax, results, speeds, bike, riders, materials, colours, hi):
    rows = [(r, m) for r in riders for m in materials]
    for y, (r, m) in enumerate(rows):
        for a, b in results.wobble[bike, r, m].unstable:
            ax.plot([a, b], [y, y], color="tab:red", lw=5, alpha=0.35, solid_capstyle="butt")
        w = results.wobble[bike, r, m]
        marks = {"rigid": speeds[bike, r, "infinite"][:2], "spring": speeds[bike, r, m][:2],
                 "beams": (w.weave_speeds, w.capsize_speeds)}
        for model, found in marks.items():
            for (marker, _), crossing in zip(MARKERS, found):
                ax.plot(crossing[:1], [y] * len(crossing[:1]), marker, color=MODELS[model][0], mec="k", mew=0.5,
                        ms=4.5, zorder=3)
    for k in range(1, len(riders)):
        ax.axhline(k * len(materials) - 0.5, color="0.8", lw=0.6)
    ax.set_yticks(range(len(rows)), [f"{THESIS_NAMES[r]}, {THESIS_NAMES[m].lower()}" for r, m in rows],
                  fontsize="xx-small")
    for label, (_, m) in zip(ax.get_yticklabels(), rows):
        label.set_color(colours[m])
    ax.set_ylim(len(rows) - 0.5, -0.5)
    ax.set_xlim(0, hi)
    ax.set_xlabel("forward speed (m/s)")
    ax.grid(True, axis="x", alpha=0.3)
    ax.plot([], [], color="tab:red", lw=5, alpha=0.35, label="wobble unstable")
    for colour, text in MODELS.values():
        ax.plot([], [], "-", color=colour, lw=4, label=text)
    for marker, text in MARKERS:
        ax.plot([], [], marker, color="white", mec="k", mew=0.5, label=f"{text} speed (first)")
    ax.legend(fontsize="xx-small", loc="upper left", bbox_to_anchor=(1.0, 1.0), frameon=False)


def _lean(ax, results, bike, riders):
    y = np.arange(len(riders))
    rigid = [x.rigid_weave_speeds[0] if x.rigid_weave_speeds else np.nan for x in
             (results.lean[bike, r] for r in riders)]
    leaning = [x.weave_speeds[0] if x.weave_speeds else np.nan for x in (results.lean[bike, r] for r in riders)]
    for k in y:
        ax.annotate("", (leaning[k], k), (rigid[k], k), arrowprops={"arrowstyle": "->", "color": "0.4", "lw": 0.8})
    ax.plot(rigid, y, "o", color="0.55", mec="k", mew=0.5, label="rigid rider")
    ax.plot(leaning, y, "o", color="tab:green", mec="k", mew=0.5, label="leaning rider")
    ax.set_yticks(y, [THESIS_NAMES[r] for r in riders], fontsize="x-small")
    ax.set_ylim(len(riders) - 0.5, -0.5)
    ax.set_xlabel("weave speed (m/s), rigid frame")
    ax.grid(True, axis="x", alpha=0.3)
    ax.legend(fontsize="xx-small", loc="lower right")


def plot_flexible(results, speeds, bands, speed, title=""):
    """Figure of :class:`~bikemass.study.flexible.FlexibleResults`; ``speeds`` =
    ``{(bike, rider, stiffness): (weave, capsize, stable)}`` (m/s) of the rigid frame (``"infinite"``)
    and the thesis's spring; ``bands`` the published wobble bands (``[{"name", "low", "high"}]``, Hz);
    ``speed`` (m/s) where the frequencies are stated."""
    bikes, riders, materials = _keys(results)
    colours = dict(zip(materials, series_colours(len(materials))))
    fig = new_figure((12.0, 3.9 * len(bikes) + 0.4))
    axes = np.atleast_2d(fig.subplots(len(bikes), 3, width_ratios=(1.0, 1.4, 0.9)))
    for row, bike in zip(axes, bikes):
        _frequencies(row[0], results, bike, riders, materials, colours, bands, speed)
        _speeds(row[1], results, speeds, bike, riders, materials, colours,
                max(w.span[1] for w in results.wobble.values()))
        _lean(row[2], results, bike, riders)
        row[0].set_title(f"{THESIS_NAMES[bike]}: the wobble", fontsize="small")
        row[1].set_title(f"{THESIS_NAMES[bike]}: wobble and capsize", fontsize="small")
        row[2].set_title(f"{THESIS_NAMES[bike]}: the leaning rider", fontsize="small")
    if title:
        fig.suptitle(title, fontsize="medium")
    return fig
