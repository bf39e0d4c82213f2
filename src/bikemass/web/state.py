"""The web page's state as a URL query string, and back.

Everything the page shows follows from one :class:`PageState`: which bicycle,
rider and rear-frame stiffness, how rider and frame combine, and any benchmark
parameter the user typed over the computed one.  The same query string drives
the page (``/?bike=jamis&rider=relaxed&stiffness=steel``), the JSON API
(``/api/stability?...``) and the downloads, so a link reproduces a result.
"""

import math
from dataclasses import dataclass, field, replace
from urllib.parse import urlencode

from ..errors import InputError
from ..parameters import NAMES

STIFFNESS_CHOICES = ("infinite", "steel", "titanium", "aluminum")
"""Rear-frame stiffness choices offered by the page (a rigid frame or a shipped material)."""
COMBINE_CHOICES = ("exact", "thesis")
"""Rider + rear frame: parallel-axis theorem, or the thesis's Eq. 3.6."""
TEXT_KEYS = ("bike", "size", "rider", "stiffness", "combine")
"""Query keys holding names."""
CHART_PREFIX = "chart."
CHART_KEYS = ("stack", "reach", "head_tube_angle", "seat_tube_angle", "head_tube_length",
              "seat_tube_length", "chainstay_length", "bb_drop", "fork_offset")
"""Chart values a user can type over (``chart.<key>``): mm, and degrees for the two angles."""
CHART_ANGLES = ("head_tube_angle", "seat_tube_angle")
SOURCE = "URL"
"""What error messages name as the 'file' of a bad query value."""


@dataclass(frozen=True)
class PageState:
    """One configuration of the page (all values as the user chose them)."""

    bike: str = "jamis"
    rider: str = "relaxed"
    stiffness: str = "infinite"
    combine: str = "exact"
    size: str = ""
    """Size of a size-run bicycle file ("" = its first size)."""
    chart: tuple = field(default=())
    """``((key, value), ...)``: geometry-chart values typed over the bicycle's (mm, deg)."""
    overrides: tuple = field(default=())
    """``((name, value), ...)``: benchmark parameters typed over the computed ones (SI)."""

    @classmethod
    def from_query(cls, query):
        """State from a mapping of query keys to strings; InputError names a bad key."""
        for key in query:
            if key not in TEXT_KEYS + NAMES and key.removeprefix(CHART_PREFIX) not in CHART_KEYS:
                raise InputError(SOURCE, key, "one of bike, size, rider, stiffness, combine, a benchmark "
                                 "parameter name (w, c, lam, ..., IFyy) or chart.<key> (chart.stack, ...)")
        values = {k: str(query[k]).strip() for k in TEXT_KEYS if k in query}
        state = cls(**{k: v for k, v in values.items() if v})
        if state.stiffness not in STIFFNESS_CHOICES:
            raise InputError(SOURCE, "stiffness", f"one of {', '.join(STIFFNESS_CHOICES)}")
        if state.combine not in COMBINE_CHOICES:
            raise InputError(SOURCE, "combine", f"one of {', '.join(COMBINE_CHOICES)}")
        overrides = tuple((name, _number(name, query[name])) for name in NAMES
                          if name in query and str(query[name]).strip() != "")
        chart = tuple((key, _number(CHART_PREFIX + key, query[CHART_PREFIX + key])) for key in CHART_KEYS
                      if str(query.get(CHART_PREFIX + key, "")).strip() != "")
        return replace(state, overrides=overrides, chart=chart)

    def to_query(self):
        """The query string (without ``?``) that :meth:`from_query` reads back to this state."""
        pairs = [("bike", self.bike)] + ([("size", self.size)] if self.size else [])
        pairs += [("rider", self.rider), ("stiffness", self.stiffness)]
        if self.combine != "exact":
            pairs.append(("combine", self.combine))
        pairs += [(CHART_PREFIX + key, repr(value)) for key, value in self.chart]
        pairs += [(name, repr(value)) for name, value in self.overrides]
        return urlencode(pairs)

    @property
    def bicycle_key(self):
        """``(bike, size, chart)``: what fixes the bicycle (hashable, for caches)."""
        return self.bike, self.size, self.chart

    def with_overrides(self, values):
        """A copy whose overrides are ``values`` (``{name: float or None}``, None = computed)."""
        kept = tuple((n, _number(n, values[n])) for n in NAMES if values.get(n) is not None)
        return replace(self, overrides=kept)

    def with_chart(self, values):
        """A copy whose chart edits are ``values`` (``{key: mm or deg, or None}``, None = the file's)."""
        kept = tuple((k, _number(CHART_PREFIX + k, values[k])) for k in CHART_KEYS if values.get(k) is not None)
        return replace(self, chart=kept)


def _number(name, text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        value = math.nan
    if not math.isfinite(value):
        expected = ("a finite number (deg)" if name.removeprefix(CHART_PREFIX) in CHART_ANGLES else
                    "a finite number (mm)" if name.startswith(CHART_PREFIX) else
                    "a finite number in SI units (m, kg, kg m^2, rad)")
        raise InputError(SOURCE, name, expected)
    return value
