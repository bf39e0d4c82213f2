"""A sweep's results table: one CSV line per configuration, written a chunk at a time.

Columns: the varied keys (as named in the spec), then :data:`OUTPUTS`.  Numbers are written in
full (``repr``: they read back to the same float), a missing value as an empty cell.  A chunk's
lines are formatted where it was computed (a Dask worker formats its own,
:func:`chunk_text`); ``results.csv`` is the header and the chunk files' text in index order,
copied file by file (:mod:`bikemass.sweep.layout`), and ``results.parquet`` (with pyarrow) one
row group per chunk read back by :func:`read_chunk`: no process holds the whole table.
"""

import csv
import io
from dataclasses import dataclass

import numpy as np

NUMBERS = ("weave_speed", "capsize_speed", "stable_from", "stable_to", "total_mass")
OUTPUTS = NUMBERS + ("error",)
"""The outputs of a configuration (:func:`bikemass.sweep.evaluate.evaluate`), the last columns."""


@dataclass(frozen=True)
class Outcomes:
    """Outcomes of B configurations as columns.

    Attributes
    ----------
    values : dict
        ``{output: (B,) float array}`` for :data:`NUMBERS` (speeds in m/s, total mass in kg;
        ``nan`` where a row has no such speed, or was refused).
    errors : list
        B entries: ``None``, or the one-line reason a refused row was refused.
    """

    values: dict
    errors: list

    def rows(self):
        """The outcomes as :func:`bikemass.sweep.evaluate.evaluate` returns them: one dict per row,
        ``None`` for a missing number."""
        columns = [[None if x != x else x for x in self.values[k].tolist()] for k in NUMBERS]
        return [dict(zip(OUTPUTS, (*row, error))) for *row, error in zip(*columns, self.errors)]


def header(keys):
    """The first line of ``results.csv`` (with its newline)."""
    return ",".join((*keys, *OUTPUTS)) + "\n"


def _cell(value):
    if value is None:
        return ""
    if type(value) is float:
        return repr(value)
    text = str(value)
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n\r') else text


def _float_cells(columns):
    """Cells of float columns (``nan``: no value, an empty cell), each distinct value formatted
    once: a grid's values and a sweep's masses repeat, and a stable range's ends are mostly the
    crossings' own speeds, so a chunk formats about two numbers a row instead of seven."""
    if not columns:
        return []
    values = np.concatenate([np.asarray(c, dtype=float) for c in columns])
    distinct, index = np.unique(values, return_inverse=True)
    cells = np.array(["" if x != x else repr(x) for x in distinct.tolist()], dtype=object)[index.reshape(-1)]
    for i in np.flatnonzero(values == 0).tolist():
        cells[i] = repr(values[i].item())              # 0.0 and -0.0 are one value to np.unique
    return [part.tolist() for part in np.split(cells, len(columns))]


BATCH = 8192
"""Rows formatted together (their temporaries reused from the heap, as in
:data:`bikemass.sweep.vectorised.BATCH`)."""


def chunk_text(keys, columns, outcomes):
    """The lines (each with its newline) of ``results.csv`` for one chunk: ``columns`` the varied
    values (``{key: list}``), ``outcomes`` a :class:`~bikemass.sweep.vectorised.Outcomes`."""
    count = len(outcomes.errors)
    if count <= BATCH:
        return _batch_text(keys, columns, outcomes)
    return "".join(_batch_text(keys, {k: v[a:a + BATCH] for k, v in columns.items()},
                               Outcomes({k: v[a:a + BATCH] for k, v in outcomes.values.items()},
                                     outcomes.errors[a:a + BATCH]))
                   for a in range(0, count, BATCH))


def _batch_text(keys, columns, outcomes):
    floats = [k for k in keys if set(map(type, columns[k])) <= {float}]
    formatted = dict(zip((*floats, *NUMBERS), _float_cells([*(columns[k] for k in floats),
                                                             *(outcomes.values[k] for k in NUMBERS)])))
    cells = [formatted[k] if k in formatted else [_cell(v) for v in columns[k]] for k in keys]
    cells += [formatted[k] for k in NUMBERS]
    cells.append([_cell(e) for e in outcomes.errors])
    return "\n".join(map(",".join, zip(*cells))) + "\n" if cells[0] else ""


def read_chunk(text, keys, numeric_keys, count):
    """``{column: list}`` of the lines of one chunk file (``count`` of them; floats for the
    ``numeric_keys`` and the numbers, ``None`` for an empty cell; strings otherwise).
    ValueError if the text is not ``count`` such lines as bikemass writes them (a damaged chunk
    file: NUL bytes, as a crash or a full disk leaves; carriage returns ending lines, which
    bikemass never writes and ``results.csv`` would copy; a field too long for the csv module)."""
    if "\0" in text:
        raise ValueError("not the lines bikemass writes (NUL bytes)")
    try:
        rows = list(csv.reader(io.StringIO(text, newline="")))
    except csv.Error as exc:
        raise ValueError(f"not CSV lines ({exc})") from None
    if "\r" in text and text.count("\r") != sum(cell.count("\r") for row in rows for cell in row):
        raise ValueError("not the lines bikemass writes (carriage returns ending lines)")
    width = len(keys) + len(OUTPUTS)
    if len(rows) != count or any(len(r) != width for r in rows):
        raise ValueError("not the lines of this chunk")
    columns = {c: list(v) for c, v in zip((*keys, *OUTPUTS), zip(*rows))} if rows else \
        {c: [] for c in (*keys, *OUTPUTS)}
    for c in (*numeric_keys, *NUMBERS):
        columns[c] = [float(x) if x else None for x in columns[c]]
    columns["error"] = [x or None for x in columns["error"]]
    return columns


def arrow_chunk(path, keys, numeric_keys, names=None):
    """The chunk file ``path`` as a pyarrow Table (typed as :func:`parquet_writer`'s schema; an
    empty cell null; only the columns ``names`` if given), parsed by pyarrow's CSV reader;
    ``None`` without pyarrow."""
    arrow = parquet_writer(keys, numeric_keys)
    if arrow is None:
        return None
    # lazy: pyarrow is optional (the sweep extra) and slow to import; only reading a table back needs it
    import pyarrow.csv as pc
    pa, schema = arrow
    return pc.read_csv(path, read_options=pc.ReadOptions(column_names=schema.names, use_threads=False),
                       parse_options=pc.ParseOptions(newlines_in_values=True),
                       convert_options=pc.ConvertOptions(column_types=schema, strings_can_be_null=True,
                                                         include_columns=names))


def parquet_writer(keys, numeric_keys):
    """``(pyarrow, schema)`` of ``results.parquet``, or ``None`` without pyarrow."""
    try:
        # lazy: pyarrow is optional (the sweep extra) and slow to import; only the Parquet file needs it
        import pyarrow as pa
    except ImportError:
        return None
    fields = [pa.field(k, pa.float64() if k in numeric_keys else pa.string()) for k in keys]
    fields += [pa.field(k, pa.float64()) for k in NUMBERS] + [pa.field("error", pa.string())]
    return pa, pa.schema(fields)
