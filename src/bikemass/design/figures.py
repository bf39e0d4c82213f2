"""The figure of an optimisation: how the search converged, and the objective around the design."""

import os
from dataclasses import dataclass

import numpy as np

from ..core.errors import InputError, wrong_type
from ..core.results import Result
from .metrics import metric
from .optimise import OptimiseResult, check_spec
from ..plots.figure import Figure
from .problem import Problem
from .spec import OptimiseSpec

SLICE_POINTS = 21
"""Designs along each variable's range in :func:`objective_slices`."""


@dataclass(frozen=True, eq=False)
class Slices(Result):
    """The objective's metric along each variable's whole range through the design, the others held.

    ``positions`` (n,) in [0, 1] of each variable's range (0: its min, 1: its max); ``values``
    (variables, n) the metric there (NaN where no design could be built); ``variables`` their keys;
    ``design`` where the design lies in each range; ``feasible`` (variables, n) whether each design
    meets the spec's constraints."""

    variables: tuple
    positions: np.ndarray
    values: np.ndarray
    design: tuple
    feasible: np.ndarray


def objective_slices(spec: "OptimiseSpec | str | os.PathLike", result: OptimiseResult,
                     points: int = SLICE_POINTS) -> Slices:
    """:class:`Slices` of the objective's metric through ``result``'s design (an
    :class:`~bikemass.design.optimise.OptimiseResult` of ``spec``)."""
    checked = check_spec(spec)
    if not isinstance(points, int) or isinstance(points, bool) or not 3 <= points <= 1000:
        raise InputError("points", repr(points), "a whole number of designs from 3 to 1000")
    problem = Problem(checked)
    target = metric(checked.objective)
    x0 = np.array([result.variables[v.key] for v in checked.variables])
    positions = np.linspace(0.0, 1.0, points)
    values = np.full((len(x0), points), np.nan)
    feasible = np.zeros((len(x0), points), dtype=bool)
    bounds = [(metric(c.metric), c) for c in checked.all_constraints]
    for k, v in enumerate(checked.variables):
        for j, s in enumerate(positions):
            x = x0.copy()
            x[k] = v.low + s * (v.high - v.low)
            try:
                values[k, j] = problem.value(target, x)
                feasible[k, j] = all((c.low is None or problem.value(m, x) >= c.low * (1 - 1e-9))
                                     and (c.high is None or problem.value(m, x) <= c.high * (1 + 1e-9))
                                     for m, c in bounds)
            except InputError:
                pass
    design = tuple(float((x - v.low) / (v.high - v.low)) for x, v in zip(x0, checked.variables))
    return Slices(tuple(v.key for v in checked.variables), positions, values, design, feasible)


def plot_optimisation(result: OptimiseResult, slices: "Slices | None" = None, title: str = "",
                      size: "tuple[float, float] | None" = None) -> Figure:
    """The search of :func:`bikemass.optimise` and the objective around its design, as a Figure.

    Parameters
    ----------
    result : OptimiseResult
        What :func:`bikemass.optimise` returned.
    slices : Slices, optional
        :func:`~bikemass.design.figures.objective_slices` of the same spec: a second panel with the
        objective's metric along each variable's range through the design (dotted where a constraint is
        violated).
    title : str
        The figure's title.
    size : (float, float), optional
        Width and height in inches.

    Returns
    -------
    matplotlib.figure.Figure
        The objective's metric at each design the search asked for (the best feasible so far as a line).

    Raises
    ------
    InputError
        ``result`` not an OptimiseResult.

    See Also
    --------
    optimise : Makes the result.

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.design.spec import DesignVariable, OptimiseSpec
    >>> spec = OptimiseSpec(source="example", bike="benchmark", variables=(DesignVariable("c", 0.02, 0.2),),
    ...                     sense="target", objective="weave-speed", target=5.0)
    >>> fig = bm.plot_optimisation(bm.optimise(spec))
    >>> fig.axes[0].get_ylabel()
    'weave-speed (m/s)'
    """
    if not isinstance(result, OptimiseResult):
        raise wrong_type("result", result, "an OptimiseResult (bm.optimise)")
    unit = result.metric_units[result.metric]
    label = f"{result.metric} ({unit})" if unit not in ("", "1") else result.metric
    panels = 2 if slices is not None else 1
    fig = Figure(figsize=size or (5.2 * panels + 0.6, 4.4), layout="constrained")
    axes = np.atleast_1d(fig.subplots(1, panels))
    ax = axes[0]
    values = np.array([h.objective for h in result.history])
    feasible = np.array([h.violation <= 1e-6 for h in result.history])
    index = np.arange(1, len(values) + 1)
    ax.plot(index[feasible], values[feasible], "o", ms=4, color="tab:blue", label="feasible design")
    if np.any(~feasible):
        ax.plot(index[~feasible], values[~feasible], "x", ms=5, color="tab:red", label="violates a constraint")
    best = np.full(len(values), np.nan)
    sign = 1.0 if result.sense == "maximise" else -1.0
    current = None
    for k, (v, ok) in enumerate(zip(values, feasible)):
        if ok:
            if result.sense == "target":
                better = current is None or abs(v - result.target) < abs(current - result.target)
            else:
                better = current is None or sign * v > sign * current
            current = v if better else current
        best[k] = np.nan if current is None else current
    ax.plot(index, best, "-", color="black", lw=1.2, label="best feasible so far")
    if result.sense == "target":
        ax.axhline(result.target, color="tab:green", lw=1, ls="--", label="target")
    ax.set_xlabel("design asked for by the search")
    ax.set_ylabel(label)
    ax.set_title("Convergence")
    ax.grid(alpha=0.3)
    ax.legend(fontsize="small")
    if slices is not None:
        ax = axes[1]
        colours = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink",
                   "tab:gray", "tab:olive", "tab:cyan")
        for k, key in enumerate(slices.variables):
            colour = colours[k % len(colours)]
            ax.plot(slices.positions, slices.values[k], ":", color=colour, lw=1)
            ax.plot(slices.positions, np.where(slices.feasible[k], slices.values[k], np.nan), "-", color=colour,
                    label=key)
            ax.plot([slices.design[k]], [result.objective], "o", color=colour, ms=6)
        ax.axhline(result.objective, color="black", lw=0.8, ls=":", label="at the design")
        ax.set_xlabel("position in the variable's range (0: min, 1: max)")
        ax.set_ylabel(label)
        ax.set_title("Around the design (dotted: violates a constraint)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize="small")
    if title:
        fig.suptitle(title, fontsize="medium")
    return fig
