"""Typed, immutable results: frozen dataclasses whose fields declare their units once.

A result type is a frozen dataclass deriving from :class:`Result`; each field that holds a
quantity is declared with :func:`quantity`, which records its SI unit::

    @dataclass(frozen=True, eq=False)
    class CriticalSpeed(Result):
        speed: float = quantity("m/s", "where the root crosses Re = 0")

Arrays are made read-only and mappings immutable when the result is built; :meth:`Result.to_dict`
gives plain data for JSON/YAML, and :meth:`Result.units` the ``units`` block of that document,
generated from the declarations (nested results contribute their own), never guessed from names.
"""

from dataclasses import MISSING, dataclass, field, fields, is_dataclass
from collections.abc import Mapping

import numpy as np

from .display import UNIT, Display
from .frozen import freeze
from .plain import document_keys


def quantity(unit, doc="", default=MISSING):
    """A dataclass field holding a quantity in ``unit`` (SI; ``""`` for dimensionless)."""
    kwargs = {} if default is MISSING else {"default": default}
    return field(metadata={UNIT: unit, "doc": doc}, **kwargs)


def declared_units(cls):
    """``{field: unit}`` of the fields of the dataclass ``cls`` (or of an instance) declared with
    :func:`quantity`: a result's, or any typed value's that declares its units (a
    :class:`~bikemass.mass.inertia.MassProperties`)."""
    return {f.name: f.metadata[UNIT] for f in fields(cls) if UNIT in f.metadata}


def _plain(value):
    if isinstance(value, Result):
        return value.to_dict()
    if is_dataclass(value) and hasattr(value, "to_dict"):
        return value.to_dict()
    if isinstance(value, Mapping):
        return {str(k): _plain(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return _plain(value.tolist())
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, complex):
        return [value.real, value.imag]
    return value


_FIELD_NAMES = {}
"""``{result type: its field names}``, for :meth:`Result.frozen`."""


@dataclass(frozen=True, eq=False)
class Result(Display):
    """Base of every result type: frozen fields, read-only arrays, units per field; in Jupyter a
    compact HTML table of the fields (:class:`~bikemass.core.display.Display`)."""

    def __post_init__(self):
        for f in fields(self):
            object.__setattr__(self, f.name, freeze(getattr(self, f.name)))

    @classmethod
    def frozen(cls, *values):
        """An instance from ``values`` (every field, in order) that are immutable already (numbers,
        strings, tuples of results): set once, without another freezing pass (the hot paths)."""
        names = _FIELD_NAMES.get(cls)
        if names is None:
            names = _FIELD_NAMES[cls] = tuple(f.name for f in fields(cls))
        if len(values) != len(names):
            raise TypeError(f"{cls.__name__}.frozen takes {len(names)} values, got {len(values)}")
        obj = object.__new__(cls)
        obj.__dict__.update(zip(names, values))
        return obj

    @classmethod
    def field_units(cls):
        """``{field: unit}`` of the fields declared with :func:`quantity`."""
        return declared_units(cls)

    def to_dict(self):
        """Plain data (lists, floats, strings) of every field, nested results included."""
        return {f.name: _plain(getattr(self, f.name)) for f in fields(self)}

    def units(self):
        """The ``units`` block: ``{key: unit}`` of this result's quantities and its nested results'."""
        out = dict(self.field_units())
        for f in fields(self):
            value = getattr(self, f.name)
            items = value if isinstance(value, (list, tuple)) else (value,)
            for item in items:
                if isinstance(item, Result):
                    out.update({k: u for k, u in item.units().items() if k not in out})
        return out

    def document(self):
        """``to_dict()`` with its ``units`` block: what ``--format json|yaml`` writes."""
        return with_declared_units(self.to_dict(), self.units())


def with_declared_units(data, units):
    """The plain document ``data`` (a mapping) with a top-level ``units`` block: the declared
    ``units`` (``{key: unit}``, a result's :meth:`Result.units`) of the keys it holds, none guessed
    from a key's name."""
    keys = document_keys(data)
    return {**data, "units": {k: u for k, u in units.items() if k in keys}}
