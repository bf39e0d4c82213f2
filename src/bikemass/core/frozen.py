"""Making values immutable: read-only arrays, read-only mappings, tuples instead of lists."""

from collections.abc import Mapping

import numpy as np


class FrozenMap(Mapping):
    """A read-only mapping (unlike ``types.MappingProxyType`` it pickles, so values holding it
    cross process boundaries)."""

    __slots__ = ("_data",)

    def __init__(self, data=()):
        object.__setattr__(self, "_data", dict(data))

    def __getitem__(self, key):
        return self._data[key]

    def __iter__(self):
        return iter(self._data)

    def __len__(self):
        return len(self._data)

    def __setattr__(self, name, value):
        raise AttributeError("FrozenMap is read-only")

    def __reduce__(self):
        return FrozenMap, (self._data,)

    def __hash__(self):
        return hash(frozenset(self._data.items()))

    def __repr__(self):
        return f"FrozenMap({self._data!r})"


class LazyMap(FrozenMap):
    """A :class:`FrozenMap` whose items are made by ``make()`` (a mapping) when first read, then kept:
    the expensive part of a result that many callers never read (a stability result's marginal and
    per-mode ranges) costs nothing until it is.  ``make`` must be pure (two threads reading at once
    may both call it; either result is the same).  Pickles as the FrozenMap of its items."""

    __slots__ = ("_make",)

    def __init__(self, make):
        object.__setattr__(self, "_data", None)
        object.__setattr__(self, "_make", make)

    def _items(self):
        data = self._data
        if data is None:
            data = dict(self._make())
            object.__setattr__(self, "_data", data)
            object.__setattr__(self, "_make", None)          # what it held is no longer needed
        return data

    def __getitem__(self, key):
        return self._items()[key]

    def __iter__(self):
        return iter(self._items())

    def __len__(self):
        return len(self._items())

    def __reduce__(self):
        return FrozenMap, (self._items(),)

    def __repr__(self):
        return f"FrozenMap({self._items()!r})"


def readonly(values, dtype=None):
    """A read-only copy of ``values`` as an array (``None`` stays ``None``)."""
    if values is None:
        return None
    a = np.array(values, dtype=dtype)
    a.setflags(write=False)
    return a


def freeze(value):
    """``value`` with every mapping made read-only, every list a tuple, every array read-only
    (what is immutable already is returned as it is)."""
    if isinstance(value, FrozenMap):
        return value
    if isinstance(value, Mapping):
        return FrozenMap({k: freeze(v) for k, v in value.items()})
    if isinstance(value, (list, tuple)):
        items = tuple(freeze(v) for v in value)
        same = isinstance(value, tuple) and all(a is b for a, b in zip(items, value))
        return value if same else items
    if isinstance(value, np.ndarray):
        return value if not value.flags.writeable else readonly(value)
    return value


def thaw(value):
    """A plain mutable copy of what :func:`freeze` made: mappings as dicts, tuples and lists as
    lists (as YAML reads them), arrays and everything else as they are."""
    if isinstance(value, Mapping):
        return {k: thaw(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [thaw(v) for v in value]
    return value


def frozen_fields(obj, *names):
    """In ``__post_init__`` of a frozen dataclass: make the fields ``names`` immutable."""
    for name in names:
        object.__setattr__(obj, name, freeze(getattr(obj, name)))


def short_repr(obj, *fields):
    """``Name(field=value, ...)`` with each value's own short form: for a one-screen ``repr``."""
    return f"{type(obj).__name__}({', '.join(f'{k}={v}' for k, v in fields)})"
