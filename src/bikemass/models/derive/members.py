"""The members of the model family that the derivation knows: the registered members with a derivation
(:mod:`bikemass.models.members`), in their canonical order."""

from itertools import combinations

from ..registry import SPECS

DERIVED = tuple(spec.name for spec in SPECS if spec.derived)
"""The names of the members with a derivation, in canonical order."""

COMBINATIONS = tuple(c for n in range(len(DERIVED) + 1) for c in combinations(DERIVED, n))
"""The member combinations the package ships (``()`` is the Whipple bicycle): every combination of the
members with a derivation (a member without one changes the equations of whichever it joins)."""


def members(names):
    """New derivation objects for the derived members of ``names`` (canonical order)."""
    return [spec.derivation()() for spec in SPECS if spec.derived and spec.name in names]
