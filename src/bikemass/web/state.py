"""The web page's state as a URL query string, and back.

Everything the page shows follows from one :class:`PageState`: which bicycle,
rider and rear-frame stiffness, how rider and frame combine, and any benchmark
parameter the user typed over the computed one.  The same query string drives
the page (``/?bike=jamis&rider=relaxed&stiffness=steel``), the JSON API
(``/api/stability?...``) and the downloads, so a link reproduces a result.
"""

import math
import re
from itertools import combinations
from dataclasses import dataclass, field, replace
from urllib.parse import urlencode

from ..core.config import MAX_MAGNITUDE
from ..core.errors import InputError
from ..models.parameters import NAMES
from ..models.registry import BASE, MEMBERS, parse_model

NAME_PATTERN = re.compile(r"[A-Za-z0-9][A-Za-z0-9_.@-]{0,99}")
"""What a name in the query may look like (a shipped name, a size, a material): no paths."""
COMBINE_CHOICES = ("exact", "thesis")
"""Rider + rear frame: parallel-axis theorem, or the thesis's Eq. 3.6."""
TEXT_KEYS = ("bike", "size", "rider", "stiffness", "combine", "model", "sex", "hands")
"""Query keys holding names."""
BODY_RIDER = "body"
"""``rider=body``: a rider built from ``height`` (m), ``mass`` (kg), ``sex`` and the grip ``hands``."""
BODY_NUMBERS = {"height": ("m", 1.0, 2.5), "mass": ("kg", 20.0, 250.0)}
"""Body query numbers: unit and the accepted range."""
SEXES = ("male", "female")
HANDS = ("tops", "hoods", "drops", "aero")
MODEL_CHOICES = (BASE, *("+".join(c) for n in range(1, len(MEMBERS) + 1) for c in combinations(MEMBERS, n)))
"""Every member combination of the model family, by its canonical name (the Whipple bicycle first)."""
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
    """``infinite`` or a material: a shipped one or the frame's own (:meth:`~.engine.Engine.materials`)."""
    combine: str = "exact"
    model: str = BASE
    """The linear model: ``whipple`` or members of the family joined by ``+`` (:data:`MODEL_CHOICES`)."""
    height: float = 1.80
    """Rider height (m) when ``rider`` is ``body``."""
    mass: float = 75.0
    """Rider mass (kg) when ``rider`` is ``body``."""
    sex: str = "male"
    hands: str = "hoods"
    """The grip the hands hold when ``rider`` is ``body``."""
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
            if key not in TEXT_KEYS + NAMES + tuple(BODY_NUMBERS) and \
                    key.removeprefix(CHART_PREFIX) not in CHART_KEYS:
                raise InputError(SOURCE, key, "one of bike, size, rider, stiffness, combine, model, height, mass, "
                                 "sex, hands, a benchmark parameter name (w, c, lam, ..., IFyy) or "
                                 "chart.<key> (chart.stack, ...)")
        values = {k: str(query[k]).strip() for k in TEXT_KEYS if k in query}
        values.update({k: _body_number(k, query[k]) for k in BODY_NUMBERS if str(query.get(k, "")).strip()})
        state = cls(**{k: v for k, v in values.items() if v})
        for key, choices in (("sex", SEXES), ("hands", HANDS)):
            if getattr(state, key) not in choices:
                raise InputError(SOURCE, key, f"one of {', '.join(choices)}")
        if not NAME_PATTERN.fullmatch(state.stiffness):
            raise InputError(SOURCE, "stiffness", "infinite or a material name (letters, digits, '_', '-')")
        if state.combine not in COMBINE_CHOICES:
            raise InputError(SOURCE, "combine", f"one of {', '.join(COMBINE_CHOICES)}")
        try:
            # '+' joins members; in a query string it arrives as a space (rider-lean+tyre as written)
            state = replace(state, model=parse_model(re.sub(r"\s+", "+", state.model)).name)
        except InputError:
            raise InputError(SOURCE, "model", f"one of {', '.join(MODEL_CHOICES)}") from None
        overrides = tuple((name, _number(name, query[name])) for name in NAMES
                          if name in query and str(query[name]).strip() != "")
        chart = tuple((key, _number(CHART_PREFIX + key, query[CHART_PREFIX + key])) for key in CHART_KEYS
                      if str(query.get(CHART_PREFIX + key, "")).strip() != "")
        return replace(state, overrides=overrides, chart=chart)

    def to_query(self):
        """The query string (without ``?``) that :meth:`from_query` reads back to this state."""
        pairs = [("bike", self.bike)] + ([("size", self.size)] if self.size else [])
        pairs += [("rider", self.rider)]
        if self.rider == BODY_RIDER:
            pairs += [("height", repr(self.height)), ("mass", repr(self.mass)), ("sex", self.sex),
                      ("hands", self.hands)]
        pairs += [("stiffness", self.stiffness)]
        if self.combine != "exact":
            pairs.append(("combine", self.combine))
        if self.model != BASE:
            pairs.append(("model", self.model))
        pairs += [(CHART_PREFIX + key, repr(value)) for key, value in self.chart]
        pairs += [(name, repr(value)) for name, value in self.overrides]
        return urlencode(pairs)

    @property
    def bicycle_key(self):
        """``(bike, size, chart)``: what fixes the bicycle (hashable, for caches)."""
        return self.bike, self.size, self.chart

    @property
    def rider_key(self):
        """The rider's pose name, or for a body rider ``("body", height, mass, sex, hands)``."""
        if self.rider == BODY_RIDER:
            return BODY_RIDER, self.height, self.mass, self.sex, self.hands
        return self.rider

    def with_body(self, height, mass, sex, hands):
        """A copy with the body rider's height (m), mass (kg), sex and grip (texts or numbers)."""
        for key, value, choices in (("sex", sex, SEXES), ("hands", hands, HANDS)):
            if value not in choices:
                raise InputError(SOURCE, key, f"one of {', '.join(choices)}")
        return replace(self, height=_body_number("height", height), mass=_body_number("mass", mass),
                       sex=sex, hands=hands)

    def with_overrides(self, values):
        """A copy whose overrides are ``values`` (``{name: float or None}``, None = computed)."""
        kept = tuple((n, _number(n, values[n])) for n in NAMES if values.get(n) is not None)
        return replace(self, overrides=kept)

    def with_chart(self, values):
        """A copy whose chart edits are ``values`` (``{key: mm or deg, or None}``, None = the file's)."""
        kept = tuple((k, _number(CHART_PREFIX + k, values[k])) for k in CHART_KEYS if values.get(k) is not None)
        return replace(self, chart=kept)


def _body_number(name, text):
    unit, low, high = BODY_NUMBERS[name]
    value = _number(name, text)
    if not low <= value <= high:
        raise InputError(SOURCE, name, f"a {name} between {low:g} and {high:g} {unit}")
    return value


def _number(name, text):
    try:
        value = float(text)
    except (TypeError, ValueError):
        value = math.nan
    if not (math.isfinite(value) and abs(value) <= MAX_MAGNITUDE):
        expected = ("a finite number (deg)" if name.removeprefix(CHART_PREFIX) in CHART_ANGLES else
                    "a finite number (mm)" if name.startswith(CHART_PREFIX) else
                    "a finite number in SI units (m, kg, kg m^2, rad)")
        raise InputError(SOURCE, name, f"{expected} of magnitude at most {MAX_MAGNITUDE:g}")
    return value
