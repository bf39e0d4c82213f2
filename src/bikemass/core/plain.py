"""Plain Python data from values holding numpy scalars and arrays: what JSON and YAML can hold
(:mod:`bikemass.core.output` writes it; :func:`bikemass.core.gate.plain_input` checks Python
input with it as it checks a file).  A :class:`~bikemass.core.units.Quantity` stays one (a reader
takes it as it is); :func:`file_form` writes it as its text for a file."""

from collections.abc import Mapping
from enum import Enum

import numpy as np

from .units import Quantity


def plain(obj):
    """Convert numpy scalars/arrays (recursively) into plain Python for JSON/YAML."""
    if isinstance(obj, Mapping):
        return {str(k): plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return plain(obj.tolist())
    if isinstance(obj, np.generic):
        return obj.item()
    if isinstance(obj, Enum):                   # a string enum (a kind, a direction): its string
        return obj.value
    return obj


def document_keys(obj):
    """Every mapping key of the plain document ``obj``, at any depth, in order of appearance
    (a key before the keys inside its value), each once (a dict's keys)."""
    found = {}

    def walk(value):
        if isinstance(value, Mapping):
            for k, v in value.items():
                found.setdefault(k)
                walk(v)
        elif isinstance(value, (list, tuple)):
            for v in value:
                walk(v)
    walk(obj)
    return found.keys()


def file_form(obj):
    """:func:`plain` data as a file writes it: every :class:`~bikemass.core.units.Quantity` as its
    ``"<number> <unit>"`` text (the one place a typed value becomes text; nothing reads it back).

    Examples
    --------
    >>> from bikemass.core.plain import file_form
    >>> from bikemass.core.units import Quantity
    >>> file_form({"head_tube_angle": Quantity(72.5, "deg"), "stack": 0.585})
    {'head_tube_angle': '72.5 deg', 'stack': 0.585}
    """
    data = plain(obj)

    def text(value):
        if isinstance(value, dict):
            return {k: text(v) for k, v in value.items()}
        if isinstance(value, list):
            return [text(v) for v in value]
        return value.text if isinstance(value, Quantity) else value
    return text(data)
