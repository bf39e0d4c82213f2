"""The rows of a finished sweep, read from its chunk files when asked for: a sequence that holds
one chunk at a time, whatever the number of configurations."""

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from ..core.tables import Table, Tabular
from .layout import chunk_path, numeric_keys
from .table import NUMBERS, OUTPUTS, arrow_chunk, parquet_writer, read_chunk


@dataclass(frozen=True, eq=False)
class SweepResult(Sequence, Tabular):
    """The result rows of a sweep in ``folder`` (one ``{key: value, output: value}`` dict per
    configuration, in the spec's order, as ``results.csv`` has them), with the ``notes`` of the
    run (why it ran where it ran), the number ``refused`` by the model and the first refusal
    ``(index, reason)`` or ``None``.

    Rows are read back from the chunk files on demand (one chunk kept), so a sweep of any size
    can be returned; :meth:`column` gives one column as an array.

    Examples
    --------
    >>> import bikemass as bm
    >>> print(bm.SweepResult.__name__, "column" in dir(bm.SweepResult))
    SweepResult True
    """

    folder: object
    spec: object
    chunks: tuple
    notes: tuple = ()

    @property
    def refused(self):
        return sum(k.refused for k in self.chunks)

    @property
    def first_refusal(self):
        return next((k.first_refusal for k in self.chunks if k.first_refusal), None)

    def __len__(self):
        return self.chunks[-1].stop if self.chunks else 0

    def _columns(self, k):
        cached = self.__dict__.get("_cache")
        if cached is None or cached[0] is not k:
            text = chunk_path(self.folder, k.start, k.stop).read_text(encoding="utf-8")
            cached = (k, read_chunk(text, self.spec.keys, numeric_keys(self.spec), k.size))
            object.__setattr__(self, "_cache", cached)
        return cached[1]

    def _rows_of(self, k):
        columns = self._columns(k)
        names = (*self.spec.keys, *OUTPUTS)
        return [dict(zip(names, row)) for row in zip(*(columns[c] for c in names))]

    def __getitem__(self, index):
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        i = index + len(self) if index < 0 else index
        if not 0 <= i < len(self):
            raise IndexError("sweep row index out of range")
        k = next(k for k in self.chunks if k.start <= i < k.stop)
        columns = self._columns(k)
        return {c: columns[c][i - k.start] for c in (*self.spec.keys, *OUTPUTS)}

    def __iter__(self):
        for k in self.chunks:
            yield from self._rows_of(k)

    def __eq__(self, other):
        if not isinstance(other, Sequence) or isinstance(other, (str, bytes)):
            return NotImplemented
        return len(self) == len(other) and all(a == b for a, b in zip(self, other))

    __hash__ = None  # type: ignore[assignment]  # a sequence compared by value is not hashable (as list)

    def tables(self):
        """``{"rows": Table}``: one row per configuration, the varied keys (as the spec names them)
        then the outputs (``weave_speed``, ``capsize_speed``, ``stable_from``, ``stable_to`` in m/s and
        ``total_mass`` in kg, ``nan`` where there is none; ``error``), as ``results.csv`` has them."""
        names = (*self.spec.keys, *OUTPUTS)
        units = {n: "kg" if n == "total_mass" else "m/s" for n in NUMBERS}
        return {"rows": Table(self.columns(names), units, {"folder": str(self.folder), "refused": self.refused})}

    def column(self, name):
        """Column ``name`` of every row: a float array (``nan`` for an empty cell) for the numbers
        and numeric keys, else a list (:meth:`columns`)."""
        return self.columns([name])[name]

    def columns(self, names):
        """``{name: column}`` of every row for each of ``names``, read in one pass over the chunk
        files and kept (8 bytes a row for a number)."""
        cache = self.__dict__.setdefault("_column_cache", {})
        wanted = [n for n in dict.fromkeys(names) if n not in cache]
        if wanted:
            cache.update(self._read_columns(wanted))
        return {n: cache[n] for n in names}

    def _read_columns(self, names):
        numeric = set(NUMBERS) | set(numeric_keys(self.spec))
        parts = {n: [] for n in names}
        arrow = parquet_writer(self.spec.keys, numeric_keys(self.spec)) is not None
        for k in self.chunks:
            if arrow:
                table = arrow_chunk(chunk_path(self.folder, k.start, k.stop), self.spec.keys,
                                    numeric_keys(self.spec), names)
                for n in names:
                    parts[n].append(table.column(n).to_numpy() if n in numeric else table.column(n).to_pylist())
            else:
                columns = self._columns(k)
                for n in names:
                    parts[n].append(np.array([np.nan if x is None else x for x in columns[n]], dtype=float)
                                    if n in numeric else columns[n])
        return {n: (np.concatenate(parts[n]) if parts[n] else np.zeros(0)) if n in numeric
                else [x for part in parts[n] for x in part] for n in names}
