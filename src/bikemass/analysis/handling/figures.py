"""Handling figures: Bode plots, time responses, mode shapes as phasors, the handling quality
metric against frequency and its peak against speed, and lane changes.  Each function returns a
new :class:`matplotlib.figure.Figure` (no pyplot)."""

import numpy as np

from .frequency import FrequencyResponse
from .lane_change import LaneChange
from .mode_shapes import ModeShapes
from .quality import LEVEL_BOUNDS
from .survey import HandlingResult
from .time_response import TimeResponse
from ...core.errors import InputError, short, wrong_type
from ...plots.figure import Figure, new_figure

BODE_SIZE = (6.4, 5.2)
TIME_SIZE = (7.0, 5.6)
SHAPES_SIZE = (8.0, 3.4)
HANDLING_SIZE = (9.0, 3.8)
LANE_SIZE = (7.0, 6.4)
LEVEL_COLOURS = ("#e3f1e0", "#fbf1d3", "#f7dcdc")
"""Background of the handling-quality Levels 1, 2, 3."""


def _many(value, kind, what):
    items = list(value) if isinstance(value, (list, tuple)) else [value]
    if not items or not all(isinstance(v, kind) for v in items):
        raise wrong_type("result", value, what)
    return items


def plot_bode(responses: "FrequencyResponse | list[FrequencyResponse]", title: str = "",
              size: "tuple[float, float] | None" = None, hz: bool = False) -> Figure:
    """Figure: magnitude (dB) and phase (deg) against frequency (rad/s or Hz, logarithmic).

    Parameters
    ----------
    responses : FrequencyResponse or list of FrequencyResponse
        From :func:`bikemass.frequency_response`; a list gives one curve each, labelled by speed.
    title : str
        Title (default: what is drawn).
    size : (float, float), optional
        Figure size (width, height) in inches.
    hz : bool
        The frequency axis in Hz (``f = w / 2 pi``, as many papers draw it) instead of rad/s.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputTypeError
        Anything but frequency responses.

    See Also
    --------
    frequency_response : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")
    >>> curves = [bm.frequency_response(p, v, "steer-torque", "roll-angle") for v in (3.0, 5.0)]
    >>> fig = bm.plot_bode(curves)
    >>> [ax.get_ylabel() for ax in fig.axes]
    ['magnitude, dB (rad/(N m))', 'phase, deg']
    >>> bm.plot_bode(curves, hz=True).axes[1].get_xlabel()
    'frequency, Hz'
    """
    items = _many(responses, FrequencyResponse, "a FrequencyResponse (bm.frequency_response) or a list of them")
    fig = new_figure(size or BODE_SIZE)
    mag, phase = fig.subplots(2, 1, sharex=True)
    for r in items:
        label = f"{r.speed:g} m/s"
        x = r.frequencies / (2 * np.pi) if hz else r.frequencies
        mag.semilogx(x, r.magnitude, label=label)
        phase.semilogx(x, r.phase, label=label)
    first = items[0]
    mag.set_ylabel(f"magnitude, dB ({first.ratio_unit})")
    phase.set_ylabel("phase, deg")
    phase.set_xlabel("frequency, Hz" if hz else "frequency, rad/s")
    for ax in (mag, phase):
        ax.grid(True, which="both", alpha=0.3)
    if len(items) > 1:
        mag.legend(fontsize="small")
    mag.set_title(title or f"{first.output} / {first.input}")
    return fig


def plot_time_response(response: TimeResponse, title: str = "", size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: every state of a time response against time (s), one panel per unit (angles,
    rates, lengths).

    Parameters
    ----------
    response : TimeResponse
        From :func:`bikemass.simulate`.
    title : str
        Title (default: what is drawn).
    size : (float, float), optional
        Figure size (width, height) in inches.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputTypeError
        Anything but a time response.

    See Also
    --------
    simulate : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.simulate(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5})   # Meijaard's push, linear
    >>> fig = bm.plot_time_response(r)
    >>> len(fig.axes)                         # rad, rad/s, m
    3
    """
    if not isinstance(response, TimeResponse):
        raise wrong_type("response", response, "a TimeResponse (bm.simulate)")
    units = list(dict.fromkeys(response.signal_units))
    fig = new_figure(size or TIME_SIZE)
    axes = np.atleast_1d(fig.subplots(len(units), 1, sharex=True))
    for ax, unit in zip(axes, units):
        for name, u in zip(response.names, response.signal_units):
            if u == unit:
                ax.plot(response.time, response[name], label=name)
        ax.set_ylabel(unit)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small", loc="best")
    axes[-1].set_xlabel("time, s")
    axes[0].set_title(title or f"time response at {response.speed:g} m/s")
    return fig


def _shown_modes(shapes):
    """Indices of the modes drawn: each distinct mode once (a conjugate pair by its +i member)."""
    shown = []
    for i, z in enumerate(shapes.eigenvalues):
        if z.imag < 0 and any(abs(w - z.conjugate()) <= 1e-9 * max(1.0, abs(z)) for w in shapes.eigenvalues):
            continue
        shown.append(i)
    return shown


def plot_mode_shapes(shapes: ModeShapes, title: str = "", size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: one polar panel per mode (a conjugate pair once), each mechanical coordinate (roll,
    steer, ...) an arrow of its amplitude and phase relative to the mode's largest one (the
    heading and lateral position are in the table, ``shapes.to_dict()``).

    Parameters
    ----------
    shapes : ModeShapes
        From :func:`bikemass.mode_shapes`.
    title : str
        Title (default: what is drawn).
    size : (float, float), optional
        Figure size (width, height) in inches.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputTypeError
        Anything but mode shapes.

    See Also
    --------
    mode_shapes : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_mode_shapes(bm.mode_shapes(bm.parameters("benchmark"), 5.0))
    >>> len(fig.axes)                         # weave (one pair), capsize, caster
    3
    """
    if not isinstance(shapes, ModeShapes):
        raise wrong_type("shapes", shapes, "ModeShapes (bm.mode_shapes)")
    modes = _shown_modes(shapes)
    angles = list(range(shapes.n_mechanical))
    fig = new_figure(size or SHAPES_SIZE)
    axes = [fig.add_subplot(1, len(modes), j + 1, projection="polar") for j in range(len(modes))]
    colours = [f"C{k}" for k in range(len(angles))]
    for ax, i in zip(axes, modes):
        reach = max(shapes.amplitude[i, k] for k in angles)
        for colour, k in zip(colours, angles):
            a, p = shapes.amplitude[i, k], np.radians(shapes.phase[i, k])
            ax.annotate("", xy=(p, a), xytext=(0, 0),
                        arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.8})
            ax.plot([], [], color=colour, label=shapes.coordinates[k])
        ax.set_rmax(1.1 * reach)
        ax.set_rticks([])
        z = shapes.eigenvalues[i]
        ax.set_title(f"{shapes.names[i]}\n{z.real:.3g} {'+' if z.imag >= 0 else '-'} {abs(z.imag):.3g}j 1/s",
                     fontsize="small")
    handles, labels = axes[0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=len(labels), fontsize="small")   # laid out inside
    fig.suptitle(title or f"mode shapes at {shapes.speed:g} m/s", fontsize="medium")
    return fig


def _level_bands(ax, top):
    edges = (0.0, *LEVEL_BOUNDS, max(top, LEVEL_BOUNDS[-1] * 1.25))
    for k, colour in enumerate(LEVEL_COLOURS):
        ax.axhspan(edges[k], edges[k + 1], color=colour, zorder=0)
        ax.text(0.99, (edges[k] + min(edges[k + 1], top)) / 2, f"Level {k + 1}", transform=ax.get_yaxis_transform(),
                ha="right", va="center", fontsize="x-small", color="0.35")


def _speed_ranges(ranges):
    """``ranges`` as ``((start, stop), ...)`` of finite speeds (m/s); InputError otherwise."""
    expected = "((start, stop), ...) in m/s, e.g. bm.stability(p).stable_speeds"
    try:
        pairs = tuple((float(a), float(b)) for a, b in ranges)
    except (TypeError, ValueError, OverflowError):
        raise InputError("stable_speeds", short(ranges), expected) from None
    if not all(np.isfinite(pair).all() for pair in pairs):
        raise InputError("stable_speeds", short(ranges), f"finite speeds: {expected}")
    return pairs


HQM_FREQUENCY_RANGE = 20.0
"""Frequencies (rad/s) the HQM curves show at least: 0 to this (the rider's crossover region)."""


def hqm_frequency_range(result, drawn):
    """Top of the HQM curves' frequency axis (rad/s): :data:`HQM_FREQUENCY_RANGE`, widened to a
    quarter past the highest frequency at which a drawn curve peaks (the peak and its fall
    shown), never past the computed frequencies."""
    w = np.asarray(result.hqm_frequencies)
    peaks = [w[int(np.nanargmax(curve))] for curve, ok in zip(result.hqm, drawn)
             if ok and np.isfinite(curve).any()]
    top = max([HQM_FREQUENCY_RANGE, *(1.25 * f for f in peaks)])
    return float(min(top, w.max())) if w.size else top


def plot_handling(result: HandlingResult, title: str = "", size: "tuple[float, float] | None" = None,
                  stable_speeds: "tuple[tuple[float, float], ...]" = ()) -> Figure:
    """Figure: the handling quality metric (HQM) against frequency at every speed (left) and its
    peak against speed (right) over the handling-quality Levels 1-3; a speed where the closed
    loop is unstable (or no gains were found) has no level: it is drawn as a dashed (dotted) line
    across the Levels at that speed, not as a point in one of them.

    Parameters
    ----------
    result : HandlingResult
        From :func:`bikemass.handling`.
    title : str
        Title (default: what is drawn).
    size : (float, float), optional
        Figure size (width, height) in inches.
    stable_speeds : sequence of (float, float)
        ``((start, stop), ...)`` (m/s) where the bicycle without rider is self-stable, shaded on
        the right (e.g. ``bm.stability(p).stable_speeds``).

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputTypeError
        Anything but a handling result.

    See Also
    --------
    handling : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")
    >>> fig = bm.plot_handling(bm.handling(p, [3.0, 5.0, 7.0]), stable_speeds=bm.stability(p).stable_speeds)
    >>> [ax.get_xlabel() for ax in fig.axes]
    ['frequency, rad/s', 'speed, m/s']
    """
    if not isinstance(result, HandlingResult):
        raise wrong_type("result", result, "a HandlingResult (bm.handling)")
    stable_speeds = _speed_ranges(stable_speeds)
    fig = new_figure(size or HANDLING_SIZE)
    curves, peaks = fig.subplots(1, 2)
    graded = result.graded
    top = float(np.max(result.hqm_peak[graded])) * 1.1 if graded.any() else 10.0
    top = min(max(top, 9.0), 40.0)
    for v, curve, ok in zip(result.speeds, result.hqm, graded):
        if ok:
            curves.plot(result.hqm_frequencies, curve, label=f"{v:g} m/s")
    curves.set_xlim(0, hqm_frequency_range(result, graded))
    curves.set_ylim(0, top)
    _level_bands(curves, top)
    curves.set_xlabel("frequency, rad/s")
    curves.set_ylabel("HQM")
    if 0 < graded.sum() <= 10:
        curves.legend(fontsize="x-small", loc="upper left")
    for start, stop in stable_speeds:
        peaks.axvspan(start, stop, color="tab:green", alpha=0.15, zorder=1, label="self-stable")
    peaks.plot(result.speeds, np.where(graded, result.hqm_peak, np.nan), "o-", ms=3, color="k", zorder=3)
    # An unstable closed loop (or a speed without gains) has no level: marked across the bands at its
    # speed, never as a point in one of them.
    unstable = ~graded & np.array([g is not None for g in result.gains])
    for mask, colour, style, label in ((unstable, "tab:red", "--", "closed loop unstable: no level"),
                                       (~graded & ~unstable, "0.4", ":", "no gains found: no level")):
        for v in result.speeds[mask]:
            peaks.axvline(v, color=colour, ls=style, lw=1.2, zorder=4, label=label)
    if not graded.any():
        curves.text(0.5, 0.5, "no speed has a stable closed loop", transform=curves.transAxes, ha="center",
                    va="center", color="0.3", fontsize="small")
    peaks.set_ylim(0, top)
    _level_bands(peaks, top)
    peaks.set_xlabel("speed, m/s")
    peaks.set_ylabel("HQM peak")
    handles, labels = peaks.get_legend_handles_labels()
    if handles:
        unique = dict(zip(labels, handles))
        peaks.legend(unique.values(), unique.keys(), fontsize="x-small", loc="upper right")
    fig.suptitle(title or "handling quality metric (Hess, Moore & Hubbard 2012)", fontsize="medium")
    return fig


def plot_lane_change(runs: "LaneChange | list[LaneChange]", title: str = "",
                     size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: lateral positions (road and front contact), roll and steer angles (deg) and the
    rider's steer torque (N m) against the distance along the road (m; the front contact's, the
    lane change starting at 35 m), one line per run, in three panels; a nonlinear run
    (``bm.lane_change(..., nonlinear=True)``) is labelled so, to draw it beside the linear one.

    Parameters
    ----------
    runs : LaneChange or list of LaneChange
        From :func:`bikemass.lane_change`.
    title : str
        Title (default: what is drawn).
    size : (float, float), optional
        Figure size (width, height) in inches.

    Returns
    -------
    Figure
        A :class:`matplotlib.figure.Figure` (no pyplot; shows itself in Jupyter).

    Raises
    ------
    InputTypeError
        Anything but lane changes.

    See Also
    --------
    lane_change : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")
    >>> fig = bm.plot_lane_change([bm.lane_change(p, v) for v in (4.0, 6.0)])
    >>> [ax.get_ylabel() for ax in fig.axes]
    ['lateral position, m', 'angle, deg', 'steer torque, N m']
    """
    items = _many(runs, LaneChange, "a LaneChange (bm.lane_change) or a list of them")
    fig = new_figure(size or LANE_SIZE)
    lateral, angles, torque = fig.subplots(3, 1, sharex=True)
    for k, run in enumerate(items):
        x = run.distance
        colour = f"C{k}"
        lat = next(name for name in ("front-lateral", "lateral") if name in run.signals)
        if k == 0:
            lateral.plot(x, run.road, color="0.5", lw=3, alpha=0.5, label="road")
        which = f"{run.speed:g} m/s" + (", nonlinear" if run.model == "nonlinear" else "")
        lateral.plot(x, run.signals[lat], color=colour, label=f"{lat}, {which}")
        angles.plot(x, np.degrees(run.signals["roll-angle"]), color=colour, label=f"roll, {which}")
        angles.plot(x, np.degrees(run.signals["steer-angle"]), color=colour, ls="--", label=f"steer, {which}")
        torque.plot(x, run.signals["steer-torque"], color=colour)
    lateral.set_ylabel("lateral position, m")
    angles.set_ylabel("angle, deg")
    torque.set_ylabel("steer torque, N m")
    torque.set_xlabel("distance along the road, m")
    for ax in (lateral, angles, torque):
        ax.grid(True, alpha=0.3)
    lateral.legend(fontsize="x-small")
    angles.legend(fontsize="x-small", ncol=2)
    lateral.set_title(title or "lane change with the rider in the loop")
    return fig


def plot_handling_by_rider(results, title="", size=None, stable_speeds=None):
    """Figure: the HQM peak against speed of several riders (or configurations) of one bicycle,
    over the handling-quality Levels, and beneath it each one's self-stable speeds as a bar.

    ``results``: ``{name: HandlingResult}``; ``stable_speeds``: ``{name: ((start, stop), ...)}``
    (m/s).  Points where the closed loop is unstable or no gains were found are left out.
    """
    if not isinstance(results, dict) or not results or not all(isinstance(r, HandlingResult) for r in results.values()):
        raise wrong_type("results", results, "a mapping {name: HandlingResult}")
    stable_speeds = stable_speeds or {}
    fig = new_figure(size or (7.0, 5.6))
    peaks, bars = fig.subplots(2, 1, sharex=True, height_ratios=(3, 1))
    finite = [r.hqm_peak[r.graded] for r in results.values()]
    top = max([float(f.max()) for f in finite if f.size], default=10.0)
    top = min(max(1.1 * top, 9.0), 40.0)
    _level_bands(peaks, top)
    for k, (name, r) in enumerate(results.items()):
        shown = np.where(r.graded, r.hqm_peak, np.nan)
        peaks.plot(r.speeds, shown, "o-", ms=3, color=f"C{k}", label=name)
        for start, stop in stable_speeds.get(name, ()):
            bars.plot([start, stop], [k, k], color=f"C{k}", lw=6, solid_capstyle="butt")
    if not any(r.graded.any() for r in results.values()):
        peaks.text(0.5, 0.5, "no gains close the loop stably", transform=peaks.transAxes, ha="center",
                   va="center", color="0.3")
    peaks.set_ylim(0, top)
    peaks.set_ylabel("HQM peak")
    peaks.legend(fontsize="x-small", loc="upper right")
    bars.set_yticks(range(len(results)), list(results), fontsize="x-small")
    bars.set_ylim(-0.7, len(results) - 0.3)
    bars.invert_yaxis()
    bars.set_xlabel("speed, m/s")
    bars.set_title("self-stable speeds (no rider control)", fontsize="small")
    for ax in (peaks, bars):
        ax.grid(True, axis="x", alpha=0.3)
    peaks.set_title(title or "handling quality against speed", fontsize="medium")
    return fig
