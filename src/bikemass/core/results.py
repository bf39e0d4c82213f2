"""Typed, immutable results: frozen dataclasses whose fields declare their units once.

A result type is a frozen dataclass deriving from :class:`Result`; each field that holds a
quantity is declared with :func:`quantity`, which records its SI unit::

    @dataclass(frozen=True, eq=False)
    class CriticalSpeed(Result):
        speed: float = quantity("m/s", "where the root crosses Re = 0")

Arrays are made read-only and mappings immutable when the result is built; :meth:`Result.to_dict`
gives plain data for JSON/YAML, and :meth:`Result.units` the ``units`` block of that document,
generated from the declarations (nested results contribute their own), never guessed from names.
A quantity whose unit follows from the value (a transfer function's gain, in the unit of its
signals) is declared with :func:`quantity_in`, naming the attribute that holds its unit. A field
whose name became one of these methods (``units``, ``document``) was renamed; :class:`renamed_field`
keeps the old name readable for one release, with a DeprecationWarning.
"""

import warnings
from dataclasses import MISSING, dataclass, field, fields, is_dataclass
from collections.abc import Mapping
from enum import Enum

import numpy as np

from .display import UNIT, Display, brief
from .frozen import freeze
from .plain import document_keys


def quantity(unit, doc="", default=MISSING, default_factory=MISSING):
    """A dataclass field holding a quantity in ``unit`` (SI; ``""`` for dimensionless)."""
    kwargs = {} if default is MISSING else {"default": default}
    if default_factory is not MISSING:
        kwargs["default_factory"] = default_factory
    return field(metadata={UNIT: unit, "doc": doc}, **kwargs)


UNIT_OF = "unit_of"
"""The field metadata key naming the attribute that holds a field's unit (:func:`quantity_in`)."""


def quantity_in(attribute, doc="", default=MISSING):
    """A dataclass field holding a quantity whose unit depends on the value: the result's string
    attribute ``attribute`` holds it (a transfer function's gain is in ``gain_unit``, which follows
    from its signals). Declared once like :func:`quantity`; :meth:`Result.units` and the result's
    table read the unit from the instance, :func:`declared_units` (of the class) gives the
    attribute's name."""
    kwargs = {} if default is MISSING else {"default": default}
    return field(metadata={UNIT: attribute, UNIT_OF: attribute, "doc": doc}, **kwargs)


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
    if isinstance(value, Enum):                  # a string enum (a kind, a direction): its string
        return value.value
    return value


_FIELD_NAMES = {}
"""``{result type: its field names}``, for :meth:`Result.frozen`."""


@dataclass(frozen=True, eq=False)
class Result(Display):
    """Base of every result type: frozen fields, read-only arrays, units per field; in Jupyter a
    compact HTML table of the fields (:class:`~bikemass.core.display.Display`)."""

    # the one-line repr of Display.display_rows for a subclass that says repr=False (without this line the
    # dataclass decorator would give Result, and so such a subclass, a repr of no fields: "Sensitivity()")
    __repr__ = Display.short_repr

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

    def instance_units(self):
        """``{field: unit}`` of this result's declared quantities, a unit declared by :func:`quantity_in`
        read from the attribute it names."""
        return {f.name: getattr(self, f.metadata[UNIT_OF]) if UNIT_OF in f.metadata else f.metadata[UNIT]
                for f in fields(self) if UNIT in f.metadata}

    def display_rows(self):
        """``[(name, short value, unit)]`` of every field (:meth:`Display.display_rows`), the units
        of :meth:`instance_units`."""
        units = self.instance_units()
        return [(f.name, brief(getattr(self, f.name)), units.get(f.name, "")) for f in fields(self)]

    def units(self):
        """The ``units`` block: ``{key: unit}`` of this result's quantities and its nested results'."""
        out = self.instance_units()
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


class OldField:
    """What ``result.<old>`` is on a result whose field ``<old>`` was renamed in 0.3 because its name
    is a method of every result now (``units``, ``document``): called, that method (the units block,
    the document); used as the old field (indexed, iterated, compared, ``.items()``), the renamed
    field's value, with a :class:`DeprecationWarning` (for one release)."""

    __slots__ = ("_old", "_call", "_name", "_new")

    def __init__(self, old, call, name, new):
        object.__setattr__(self, "_old", old)
        object.__setattr__(self, "_call", call)
        object.__setattr__(self, "_name", name)
        object.__setattr__(self, "_new", new)

    def __setattr__(self, name, value):
        raise AttributeError("read-only")

    def __call__(self):
        return self._call()

    def _warn(self):
        warnings.warn(f"result.{self._name} as a field is deprecated: read result.{self._new} (result.{self._name}() "
                      "is the method every result has)", DeprecationWarning, stacklevel=3)

    def __getitem__(self, key):
        self._warn()
        return self._old[key]

    def __iter__(self):
        self._warn()
        return iter(self._old)

    def __len__(self):
        self._warn()
        return len(self._old)

    def __contains__(self, key):
        self._warn()
        return key in self._old

    def __eq__(self, other):
        self._warn()
        return self._old == other

    __hash__ = None

    def __getattr__(self, name):
        if name.startswith("_"):
            raise AttributeError(name)
        self._warn()
        return getattr(self._old, name)

    def __repr__(self):
        return repr(self._old)


class renamed_field:
    """The class attribute ``old`` (``units``, ``document``) of a :class:`Result` whose field of that
    name was renamed to ``new``: ``result.<old>()`` runs the result's method ``method`` (what
    ``<old>()`` does on every result), and ``result.<old>`` read as the old field still gives
    ``result.<new>`` with a DeprecationWarning (:class:`OldField`)."""

    def __init__(self, old, new, method):
        self.old, self.new, self.method = old, new, method
        self.__doc__ = (f"``{old}()``: as on every result; ``{old}`` read as a value is the deprecated old "
                        f"name of ``{new}``.")

    def __get__(self, obj, cls=None):
        if obj is None:
            return self
        return OldField(getattr(obj, self.new), getattr(obj, self.method), self.old, self.new)


def renamed_units(new):
    """:class:`renamed_field` ``units`` -> ``new``: ``result.units()`` is the class's ``unit_block()``."""
    return renamed_field("units", new, "unit_block")
