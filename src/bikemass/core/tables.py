"""Results as tables: ``result.to_frame()`` gives a pandas ``DataFrame`` of a result's rows.

A result type lists its tables once, as plain columns (:meth:`Tabular.tables`: ``{name: Table}``,
the first the default), and :meth:`Tabular.to_frame` turns one into a DataFrame: the columns as
given, their units in ``frame.attrs["units"]`` (``{column: unit}``; a column without a unit has
none there) and the result's scalar context (``speed``, ``model``, the critical speeds, ...) in
``frame.attrs`` beside them, with ``frame.attrs["result"]`` the type and ``frame.attrs["table"]`` the
table's name.  Column names carry no units, so ``frame["speed"]`` reads as the CSV's
``speed (m/s)`` column does.

pandas is an optional extra (``pip install 'bikemass[pandas]'``) and is imported only here, only when
a frame is made; the results themselves stay numpy.
"""

from dataclasses import dataclass, field

import numpy as np

from .errors import InputError, short


@dataclass(frozen=True)
class Table:
    """One table of a result: ``columns`` ``{name: 1-D values}`` (all the same length), ``units``
    ``{name: SI unit}`` of the columns holding quantities, ``attrs`` ``{key: plain value}`` of the
    context (scalars, short tuples) that is the same on every row."""

    columns: dict
    units: dict = field(default_factory=dict)
    attrs: dict = field(default_factory=dict)

    def __post_init__(self):
        lengths = {k: len(v) for k, v in self.columns.items()}
        if len(set(lengths.values())) > 1:
            raise ValueError(f"columns of different lengths: {lengths}")
        if set(self.units) - set(self.columns):
            raise ValueError(f"units of no column: {sorted(set(self.units) - set(self.columns))}")


def data_frame(table, result="", name=""):
    """A pandas DataFrame of :class:`Table` ``table`` (``result``: the result type's name, ``name``: the
    table's), with ``attrs`` ``{"result", "table", "units", **table.attrs}``.

    Raises
    ------
    ImportError
        pandas is not installed (``pip install 'bikemass[pandas]'``).
    """
    try:
        # lazy: pandas is an optional extra, loaded only when a table is asked for
        import pandas
    except ImportError as exc:
        raise ImportError("to_frame() needs pandas: pip install 'bikemass[pandas]'") from exc
    columns = {k: np.array(v) if isinstance(v, np.ndarray) else list(v) for k, v in table.columns.items()}
    frame = pandas.DataFrame(columns)
    frame.attrs.update({"result": result, "table": name, "units": dict(table.units), **table.attrs})
    return frame


class Tabular:
    """Mixin of the results with rows: :meth:`to_frame` from :meth:`tables`."""

    def tables(self):
        """``{name: Table}`` of the result's tables, the default first (each type defines its own)."""
        return {}

    def to_frame(self, table=None):
        """The result's rows as a pandas DataFrame (the ``pandas`` extra).

        Parameters
        ----------
        table : str, optional
            Which of the result's tables (:meth:`tables`; default the first).

        Returns
        -------
        pandas.DataFrame
            One column per quantity, names without units; ``frame.attrs["units"]`` gives each
            column's SI unit, ``frame.attrs`` the result's context (speed, model, ...).

        Raises
        ------
        InputError
            ``table`` is not one of the result's tables (a ValueError).
        TypeError
            The result has no rows.
        ImportError
            pandas is not installed.
        """
        tables = self.tables()
        if not tables:
            raise TypeError(f"{type(self).__name__} has no rows to make a table of")
        name = next(iter(tables)) if table is None else table
        if name not in tables:
            raise InputError("table", short(name), f"a {type(self).__name__} table (tables: {', '.join(tables)})")
        return data_frame(tables[name], type(self).__name__, name)


def complex_columns(prefix, values, unit):
    """``{f"{prefix} real": Re, f"{prefix} imaginary": Im}`` of complex ``values`` and their units."""
    values = np.asarray(values)
    columns = {f"{prefix} real": values.real.copy(), f"{prefix} imaginary": values.imag.copy()}
    return columns, {k: unit for k in columns}
