"""Figures of the nonlinear bicycle: a run beside the linear model's, and the steady turns."""

import numpy as np

from ..handling.time_response import TimeResponse
from .response import NonlinearResponse
from .turn import HandsFreeTurns
from ...core.errors import wrong_type
from ...plots.figure import Figure, new_figure

RUN_SIZE = (7.0, 7.2)
TURNS_SIZE = (6.4, 5.2)
PANELS = (("rad", ("roll-angle", "steer-angle")), ("rad/s", ("roll-rate", "steer-rate")),
          ("m", ("lateral",)), ("m/s", ("forward-speed",)))
"""The panels: a unit and the states drawn in it."""
COLOURS = {"roll-angle": ("#1f77b4", "#8fbbd9"), "steer-angle": ("#d62728", "#eb9394"),
           "roll-rate": ("#1f77b4", "#8fbbd9"), "steer-rate": ("#d62728", "#eb9394"),
           "lateral": ("#2ca02c", "#95cf95"), "forward-speed": ("#9467bd", "#c9b3de")}
"""Each state's colour: (nonlinear, linear: lighter and dashed)."""


def plot_nonlinear_response(response: NonlinearResponse, linear: "TimeResponse | None" = None, title: str = "",
                            size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: the nonlinear run's roll and steer angles, their rates, the lateral position and the
    forward speed against time (s), the linear model's response (dashed) beside it when given.

    Parameters
    ----------
    response : NonlinearResponse
        From ``bm.simulate(..., nonlinear=True)``.
    linear : TimeResponse, optional
        The linear model's response to the same initial conditions and inputs (``bm.simulate``);
        its forward speed is the constant speed it was linearised at.
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
        Anything but a nonlinear response (and a linear one with the states of the Whipple bicycle).

    See Also
    --------
    simulate : What it draws (``nonlinear=True``, and the linear run).
    plot_time_response : A linear run alone.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")
    >>> n = bm.simulate(p, 4.6, initial={"roll-rate": 0.5}, duration=2.0, nonlinear=True)
    >>> fig = bm.plot_nonlinear_response(n, bm.simulate(p, 4.6, initial={"roll-rate": 0.5}, duration=2.0))
    >>> len(fig.axes)                       # rad, rad/s, m, m/s
    4
    """
    if not isinstance(response, NonlinearResponse):
        raise wrong_type("response", response, "a NonlinearResponse (bm.simulate(..., nonlinear=True))")
    if linear is not None and not all(n in getattr(linear, "names", ()) for n in ("roll-angle", "steer-angle",
                                                                                    "roll-rate", "steer-rate",
                                                                                    "lateral")):
        raise wrong_type("linear", linear, "a TimeResponse of the Whipple bicycle (bm.simulate)")
    fig = new_figure(size or RUN_SIZE)
    axes = np.atleast_1d(fig.subplots(len(PANELS), 1, sharex=True))
    for ax, (unit, names) in zip(axes, PANELS):
        for name in names:
            solid, light = COLOURS[name]
            ax.plot(response.time, response[name], color=solid, label=f"{name} (nonlinear)")
            if linear is not None:
                values = linear[name] if name in linear.names else np.full(len(linear.time), linear.speed)
                ax.plot(linear.time, values, color=light, linestyle="--", label=f"{name} (linear)")
        ax.set_ylabel(unit)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="x-small", loc="best")
    axes[-1].set_xlabel("time, s")
    what = "nonlinear and linear" if linear is not None else "nonlinear"
    axes[0].set_title(title or f"{what} Whipple bicycle from {response.speed:g} m/s")
    if response.stopped:
        axes[-1].annotate(response.stopped, (0.01, 0.03), xycoords="axes fraction", fontsize="x-small")
    return fig


def plot_hands_free_turns(turns: HandsFreeTurns, title: str = "", size: "tuple[float, float] | None" = None) -> Figure:
    """Figure: the hands-free circles' speed (m/s) and lean (rad) against the steer angle (rad), the
    linear capsize speed marked.

    Parameters
    ----------
    turns : HandsFreeTurns
        From :func:`bikemass.hands_free_turns`.
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
        Anything but a family of hands-free turns.

    See Also
    --------
    hands_free_turns : What it draws.

    Examples
    --------
    >>> import bikemass as bm
    >>> fig = bm.plot_hands_free_turns(bm.hands_free_turns(bm.parameters("benchmark"), [0.05, 0.1, 0.2]))
    >>> len(fig.axes)                       # m/s, rad
    2
    """
    if not isinstance(turns, HandsFreeTurns):
        raise wrong_type("turns", turns, "a HandsFreeTurns (bm.hands_free_turns)")
    fig = new_figure(size or TURNS_SIZE)
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(turns.steer, turns.speed, color="#1f77b4", marker=".", label="hands-free circle")
    top.axhline(turns.capsize_speed, color="#7f7f7f", linestyle="--", label="linear capsize speed")
    top.set_ylabel("speed, m/s")
    top.legend(fontsize="small", loc="best")
    bottom.plot(turns.steer, turns.roll, color="#d62728", marker=".")
    bottom.set_ylabel("lean, rad")
    bottom.set_xlabel("steer angle, rad")
    for ax in (top, bottom):
        ax.grid(True, alpha=0.3)
    top.set_title(title or "hands-free steady turns of the nonlinear bicycle")
    return fig
