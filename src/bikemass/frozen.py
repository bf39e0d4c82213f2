"""Making values immutable: read-only arrays, read-only mappings, tuples instead of lists."""

from collections.abc import Mapping
from types import MappingProxyType

import numpy as np


def readonly(values, dtype=None):
    """A read-only copy of ``values`` as an array (``None`` stays ``None``)."""
    if values is None:
        return None
    a = np.array(values, dtype=dtype)
    a.setflags(write=False)
    return a


def freeze(value):
    """``value`` with every mapping made read-only, every list a tuple, every array read-only."""
    if isinstance(value, Mapping):
        return MappingProxyType({k: freeze(v) for k, v in value.items()})
    if isinstance(value, (list, tuple)):
        return tuple(freeze(v) for v in value)
    if isinstance(value, np.ndarray):
        return readonly(value)
    return value


def short_repr(obj, *fields):
    """``Name(field=value, ...)`` with each value's own short form: for a one-screen ``repr``."""
    return f"{type(obj).__name__}({', '.join(f'{k}={v}' for k, v in fields)})"
