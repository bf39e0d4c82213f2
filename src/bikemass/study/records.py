"""Stable speed ranges as flat records: the ``stability_ranges*.json`` files.

One record per stable range: ``{"bike", "rider", "stiffness", "mode", "criterion",
"start", "stop", "range"}`` (m/s), and one record with ``start = stop = range = None``
where a mode has no stable range.  ``mode``: ``overall`` (every eigenvalue), ``weave``
(both weave roots, "weave 1" and "weave 2" of the thesis's tables, stable at once),
``capsize``, ``caster``; ``criterion``: ``strict`` or ``marginal``.
"""

from ..analysis.engine.ranges import intersect
from .runs import CRITERIA

RECORD_MODES = {"overall": ("overall",), "weave": ("weave 1", "weave 2"), "capsize": ("capsize",),
                "caster": ("caster",)}
"""Record mode -> the labelled modes that must all be stable."""


def mode_ranges(ranges, mode):
    """Ranges where every labelled mode of record ``mode`` is stable (``ranges``: ``{mode: [...]}``)."""
    labels = RECORD_MODES[mode]
    out = ranges[labels[0]]
    for label in labels[1:]:
        out = intersect(out, ranges[label])
    return out


def records(outcomes, kind):
    """Records of a run's ``{configuration: Outcome}``; ``kind`` ``grid`` or ``exact`` ranges."""
    out = []
    for c, outcome in outcomes.items():
        for criterion in CRITERIA:
            for mode in RECORD_MODES:
                base = {"bike": c.bike, "rider": c.rider, "stiffness": c.stiffness, "mode": mode,
                        "criterion": criterion}
                found = mode_ranges(outcome.ranges[kind][criterion], mode)
                if not found:
                    out.append({**base, "start": None, "stop": None, "range": None})
                for start, stop in found:
                    out.append({**base, "start": start, "stop": stop, "range": round(stop - start, 12)})
    return out
