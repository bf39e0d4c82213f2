"""A sweep's results table: one CSV line per configuration, ``results.csv`` and ``results.parquet``.

Columns: the varied keys (as named in the spec), then :data:`OUTPUTS`.
Numbers are written in full (``repr``: they read back to the same float), a missing value
as an empty cell.  Lines are formatted where their chunk was computed (a Dask worker
formats its own); only rows kept from an earlier run's chunk files are formatted by the
process that writes the table.
"""

from io import BytesIO
from pathlib import Path

from ..core.output import write_atomic

OUTPUTS = ("weave_speed", "capsize_speed", "stable_from", "stable_to", "total_mass", "error")
"""The outputs of a configuration (:func:`bikemass.sweep.evaluate.evaluate`), the last columns."""


def _cell(value):
    if value is None:
        return ""
    if type(value) is float:
        return repr(value)
    text = str(value)
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n\r') else text


def csv_lines(keys, configurations, results):
    """CSV lines (no newline) of ``configurations`` (``{key: value}``) and their result rows."""
    return [",".join([*(_cell(c.get(k)) for k in keys), *(_cell(r.get(o)) for o in OUTPUTS)])
            for c, r in zip(configurations, results)]


def write_results(rows, keys, out, lines):
    """``out/results.csv`` (the header, then ``lines``: :func:`csv_lines`, one per row) and, with
    pyarrow, ``out/results.parquet``; ``rows`` are dicts of the varied keys and the outputs."""
    columns = list(keys) + list(OUTPUTS)
    write_atomic(Path(out) / "results.csv", "\n".join([",".join(columns), *lines]) + "\n")
    try:
        # lazy: pyarrow is optional (the sweep extra) and slow to import; only the Parquet file needs it
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        return
    table = pa.table({c: [r.get(c) for r in rows] for c in columns})
    buf = BytesIO()
    pq.write_table(table, buf)
    write_atomic(Path(out) / "results.parquet", buf.getvalue())
