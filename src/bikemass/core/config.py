"""Reading YAML input with one-line errors that name the file, the key and what was expected.

:func:`load_yaml` reads a file through the input gate (:mod:`bikemass.core.gate`); :class:`Node` wraps a
mapping (or a list) together with its file and key path and offers typed
getters, so every loader reports bad input the same way (:class:`InputError`).
"""

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .errors import InputError, short
from .frozen import freeze, thaw
from .gate import load_data
from .units import DIMENSIONS, UnitError, convert

MAX_MAGNITUDE = 1e12
"""Largest magnitude of any number read (SI): above every physical input (a steel's E is 2e11 Pa),
below where products and squares of inputs overflow."""


def load_yaml(path):
    """Read ``path`` through the input gate (:func:`bikemass.core.gate.load_data`); return a
    :class:`Node` over its top-level mapping."""
    path = Path(path)
    data = load_data(path)
    node = Node(data, path, "")
    if not isinstance(data, dict):
        node.fail("a YAML mapping at the top level")
    return node


@dataclass(frozen=True, eq=False)
class FrozenNode:
    """A :class:`Node` kept inside a result (a rider's pose document): its ``value`` deep-frozen
    (read-only mappings, tuples), its ``source`` and ``key``; :meth:`thaw` gives a working
    :class:`Node` of plain data again."""

    value: object
    source: object
    key: str | None

    @classmethod
    def of(cls, node):
        """The frozen copy of ``node`` (a FrozenNode is returned as it is)."""
        return node if isinstance(node, cls) else cls(freeze(node.value), node.source, node.key)

    def thaw(self):
        """A :class:`Node` over a plain (mutable) copy of the value."""
        return Node(thaw(self.value), self.source, self.key)


class Node:
    """A value read from YAML with its origin (file and dotted key path)."""

    def __init__(self, value, source, key):
        self.value, self.source, self.key = value, source, key

    # -- navigation ---------------------------------------------------------
    def fail(self, expected, key=None):
        """Raise :class:`InputError` for this node (or for ``key`` below it)."""
        raise InputError(self.source, self._path(key) if key is not None else (self.key or "(top)"), expected)

    def _path(self, key):
        return f"{self.key}.{key}" if self.key else str(key)

    def mapping(self):
        """This value as a dict, or an error."""
        if not isinstance(self.value, dict):
            self.fail(f"a mapping, got {type(self.value).__name__}")
        return self.value

    def has(self, key):
        return key in self.mapping()

    def get(self, key, default=None):
        """Child node ``key``; if absent return ``default`` wrapped (``None`` allowed)."""
        m = self.mapping()
        return Node(m.get(key, default), self.source, self._path(key))

    def __getitem__(self, key):
        m = self.mapping()
        if key not in m:
            self.fail("a required key that is missing", key)
        return Node(m[key], self.source, self._path(key))

    def items(self):
        """(key, child node) pairs of a mapping."""
        return [(k, Node(v, self.source, self._path(k))) for k, v in self.mapping().items()]

    def elements(self):
        """Child nodes of a list."""
        if not isinstance(self.value, list):
            self.fail(f"a list, got {type(self.value).__name__}")
        return [Node(v, self.source, f"{self.key}[{i}]") for i, v in enumerate(self.value)]

    def check_keys(self, required=(), optional=()):
        """Fail on a missing required key or on any key not in ``required`` + ``optional``."""
        m = self.mapping()
        for k in required:
            if k not in m:
                self.fail("a required key that is missing", k)
        allowed = set(required) | set(optional)
        for k in m:
            if k not in allowed:
                self.fail(f"no such key (allowed: {', '.join(sorted(allowed))})", k)
        return self

    # -- typed values -------------------------------------------------------
    @property
    def missing(self):
        return self.value is None

    def number(self, dimension, positive=False, nonnegative=False, bare_unit=None, unit=None):
        """A float of ``dimension`` (see :mod:`bikemass.core.units`) in SI, or in ``unit`` if given."""
        try:
            x = convert(self.value, dimension, unit or DIMENSIONS[dimension][0], bare_unit=bare_unit)
        except (UnitError, OverflowError) as exc:
            self.fail(str(exc))
        if not np.isfinite(x):
            self.fail(f"a finite number, got {short(self.value)}")
        if abs(x) > MAX_MAGNITUDE:
            self.fail(f"a number of magnitude at most {MAX_MAGNITUDE:g} (SI), got {short(self.value)}")
        if positive and not x > 0:
            self.fail(f"a positive number, got {short(self.value)}")
        if nonnegative and x < 0:
            self.fail(f"a number >= 0, got {short(self.value)}")
        return x

    def vector(self, dimension, size=3):
        """A float array of length ``size`` in SI of ``dimension`` (each entry may carry a unit)."""
        if not isinstance(self.value, list) or len(self.value) != size:
            self.fail(f"a list of {size} numbers, got {short(self.value)}")
        return np.array([e.number(dimension) for e in self.elements()])

    def matrix(self, dimension, shape):
        """A float array of ``shape`` (rows of numbers) in SI of ``dimension``."""
        rows = self.elements()
        if len(rows) != shape[0]:
            self.fail(f"a {shape[0]}x{shape[1]} matrix (list of {shape[0]} rows)")
        return np.array([r.vector(dimension, shape[1]) for r in rows])

    def string(self, choices=None):
        """A string, optionally one of ``choices``."""
        if not isinstance(self.value, str):
            self.fail(f"a string, got {short(self.value)}")
        if choices is not None and self.value not in choices:
            self.fail(f"one of {', '.join(choices)}, got {short(self.value)}")
        return self.value

    def boolean(self):
        if not isinstance(self.value, bool):
            self.fail(f"true or false, got {short(self.value)}")
        return self.value
