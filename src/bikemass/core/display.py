"""How results show themselves: a one-line ``repr`` and, in Jupyter, a compact HTML table.

A class deriving from :class:`Display` lists its rows once (:meth:`Display.display_rows`: name,
short value, unit) and gets both from them: ``_repr_html_`` (IPython's rich display; a table of
the rows) and :meth:`Display.short_repr` (``Name(key=value unit, ...)``). A dataclass keeps the
``__repr__`` it generates unless it says ``repr=False`` or defines its own, so a result whose
generated ``repr`` runs to screens says ``repr=False``. Values are shortened by :func:`brief`:
arrays by shape and type, long sequences and mappings by their length, floats to six digits.
Nothing here changes state; only the standard library and numpy are imported.
"""

import html
from collections.abc import Mapping
from dataclasses import fields, is_dataclass

import numpy as np

from .tables import Tabular

UNIT = "unit"
"""The dataclass field metadata key holding a field's unit (:func:`bikemass.core.results.quantity`)."""
LONGEST = 60
"""Longest short form (characters) of one value before it is summarised by its type and size."""


def _number(value):
    if isinstance(value, (bool, np.bool_)):
        return str(bool(value))
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    if isinstance(value, (complex, np.complexfloating)):
        return f"{complex(value):.4g}".strip("()")
    return f"{float(value):.6g}"


def brief(value):
    """A short form of ``value`` for a one-line ``repr`` or a table cell (at most about :data:`LONGEST`
    characters): strings as they are, numbers to six significant digits, arrays of more than six
    entries as their shape and type, sequences and mappings too long to show as their length."""
    if value is None or isinstance(value, str):
        text = str(value)
        return text if len(text) <= LONGEST else text[:LONGEST - 3] + "..."
    if isinstance(value, (int, float, complex, np.number, np.bool_)):
        return _number(value)
    if isinstance(value, np.ndarray):
        if 0 < value.ndim <= 2 and value.size <= 6:
            rows = [value] if value.ndim == 1 else value
            text = ", ".join("[" + ", ".join(_number(v) for v in row) + "]" for row in rows)
            text = text if value.ndim == 1 else f"[{text}]"
            if len(text) <= LONGEST:
                return text
        return f"array {value.shape} {value.dtype.kind == 'c' and 'complex' or value.dtype}"
    if isinstance(value, Mapping):
        text = "{" + ", ".join(str(k) for k in value) + "}"
        return text if len(text) <= LONGEST else f"{{{len(value)} keys}}"
    if isinstance(value, (list, tuple)):
        text = "(" + ", ".join(brief(v) for v in value) + ("," if len(value) == 1 else "") + ")"
        if len(text) <= LONGEST:
            return text
        kinds = {type(v).__name__ for v in value}
        return f"({len(value)} {kinds.pop() if len(kinds) == 1 else 'items'})"
    text = repr(value)
    return text if len(text) <= LONGEST else type(value).__name__


def html_table(title, rows):
    """A compact HTML table of ``rows`` = ``[(name, value, unit)]`` under ``title`` (all escaped)."""
    cells = "".join(f"<tr><td style='text-align:left'>{html.escape(str(n))}</td>"
                    f"<td style='text-align:left'>{html.escape(str(v))}</td>"
                    f"<td style='text-align:left'>{html.escape(str(u))}</td></tr>" for n, v, u in rows)
    return (f"<table class='bikemass-result'><caption style='text-align:left'><b>{html.escape(title)}</b>"
            f"</caption><thead><tr><th>field</th><th>value</th><th>unit</th></tr></thead>"
            f"<tbody>{cells}</tbody></table>")


class Display(Tabular):
    """Mixin of the result types: ``_repr_html_`` and :meth:`short_repr` from :meth:`display_rows`;
    ``to_frame()`` (a pandas DataFrame) from the rows a type with rows lists in ``tables()``
    (:mod:`bikemass.core.tables`)."""

    def display_rows(self):
        """``[(name, short value, unit)]`` shown by ``repr`` and the HTML table: by default every
        dataclass field, its unit from the field's ``unit`` metadata
        (:func:`bikemass.core.results.quantity`)."""
        if not is_dataclass(self):
            return []
        return [(f.name, brief(getattr(self, f.name)), f.metadata.get(UNIT, "")) for f in fields(self)]

    def short_repr(self):
        """``Name(key=value unit, ...)`` of :meth:`display_rows` on one line."""
        items = ", ".join(f"{n}={v}{' ' + u if u else ''}" for n, v, u in self.display_rows())
        return f"{type(self).__name__}({items})"

    __repr__ = short_repr

    def _repr_html_(self):
        """The rows as a compact HTML table (Jupyter's rich display of a returned result)."""
        return html_table(type(self).__name__, self.display_rows())
