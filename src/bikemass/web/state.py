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
SOURCE = "URL"
"""What error messages name as the 'file' of a bad query value."""


@dataclass(frozen=True)
class PageState:
    """One configuration of the page (all values as the user chose them)."""

    bike: str = "jamis"
    rider: str = "relaxed"
    stiffness: str = "infinite"
    combine: str = "exact"
    overrides: tuple = field(default=())
    """``((name, value), ...)``: benchmark parameters typed over the computed ones (SI)."""

    @classmethod
    def from_query(cls, query):
        """State from a mapping of query keys to strings; InputError names a bad key."""
        known = {"bike", "rider", "stiffness", "combine", *NAMES}
        for key in query:
            if key not in known:
                raise InputError(SOURCE, key, "one of bike, rider, stiffness, combine or a "
                                 "benchmark parameter name (w, c, lam, ..., IFyy)")
        values = {k: str(query[k]).strip() for k in ("bike", "rider", "stiffness", "combine") if k in query}
        state = cls(**{k: v for k, v in values.items() if v})
        if state.stiffness not in STIFFNESS_CHOICES:
            raise InputError(SOURCE, "stiffness", f"one of {', '.join(STIFFNESS_CHOICES)}")
        if state.combine not in COMBINE_CHOICES:
            raise InputError(SOURCE, "combine", f"one of {', '.join(COMBINE_CHOICES)}")
        overrides = tuple((name, _number(name, query[name])) for name in NAMES
                          if name in query and str(query[name]).strip() != "")
        return replace(state, overrides=overrides)

    def to_query(self):
        """The query string (without ``?``) that :meth:`from_query` reads back to this state."""
        pairs = [("bike", self.bike), ("rider", self.rider), ("stiffness", self.stiffness)]
        if self.combine != "exact":
            pairs.append(("combine", self.combine))
        pairs += [(name, repr(value)) for name, value in self.overrides]
        return urlencode(pairs)

    def with_overrides(self, values):
        """A copy whose overrides are ``values`` (``{name: float or None}``, None = computed)."""
        kept = tuple((n, _number(n, values[n])) for n in NAMES if values.get(n) is not None)
        return replace(self, overrides=kept)


def _number(name, text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        value = math.nan
    if not math.isfinite(value):
        raise InputError(SOURCE, name, "a finite number in SI units (m, kg, kg m^2, rad)")
    return value
