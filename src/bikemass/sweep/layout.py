"""A sweep's folder: its record, its chunk files and the tables assembled from them.

::

    DIR/sweep.json                     the spec's fingerprint (a resumed run must match it)
    DIR/chunks/START-STOP.csv          the lines of results.csv for configurations START..STOP-1
    DIR/results.csv                    the header and every chunk's lines, in index order
    DIR/results.parquet                the same table, one row group per chunk (with pyarrow)

A chunk file is written atomically when its chunk is computed, by whichever process gathers
the chunks; it is the sweep's state: a run of the same spec into the same folder keeps every
chunk file that holds exactly its configurations' lines (the varied values equal to the
spec's, every number readable, nothing but what bikemass writes: no NUL bytes of a crash, no
carriage returns) and computes the rest, whatever engine or chunk size either run
used.  The tables are written last, streamed chunk by chunk: the process that gathers the
chunks holds one chunk at a time, whatever the number of configurations.
"""

import re
import shutil
from dataclasses import dataclass
from pathlib import Path

from ..core.output import write_atomic
from .table import arrow_chunk, header, parquet_writer, read_chunk

CHUNKS = "chunks"
_CHUNK_NAME = re.compile(r"(\d{9,})-(\d{9,})\.csv")


def chunk_path(out, start, stop):
    """The file of chunk ``start .. stop - 1`` in sweep folder ``out``."""
    return Path(out) / CHUNKS / f"{start:09d}-{stop:09d}.csv"


@dataclass(frozen=True)
class Kept:
    """A chunk on disk: configurations ``start .. stop - 1``, how many the model ``refused`` and
    the first refusal ``(index, reason)`` or ``None``."""

    start: int
    stop: int
    refused: int
    first_refusal: tuple

    @property
    def size(self):
        return self.stop - self.start


def numeric_keys(spec):
    """The varied keys whose values are all numbers (read back as floats)."""
    return tuple(v.key for v in spec.variables
                 if v.values is None or all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in v.values))


def _summary(start, stop, errors):
    refused = [i for i, e in enumerate(errors) if e is not None]
    return Kept(start, stop, len(refused), (start + refused[0], errors[refused[0]]) if refused else None)


def _check(path, spec, start, stop):
    """:class:`Kept` of a chunk file that holds exactly the lines of those configurations of
    ``spec`` (ValueError otherwise)."""
    text = path.read_bytes().decode("utf-8")          # as copied into results.csv: no newline translation
    columns = read_chunk(text, spec.keys, numeric_keys(spec), stop - start)
    expected = spec.columns(start, stop)
    if any(columns[k] != list(expected[k]) for k in spec.keys):
        raise ValueError("another configuration's values")
    return _summary(start, stop, columns["error"])


def kept_chunks(out, spec):
    """The chunk files of ``out`` that this sweep can keep, as non-overlapping :class:`Kept` in
    index order; a damaged one (not its configurations' lines) is removed, to be computed again."""
    count = spec.count
    found = []
    for path in (Path(out) / CHUNKS).glob("*.csv"):
        match = _CHUNK_NAME.fullmatch(path.name)
        if match and 0 <= int(match[1]) < int(match[2]) <= count:
            found.append((int(match[1]), -int(match[2]), path))
    kept, covered = [], 0
    for start, minus_stop, path in sorted(found):
        if start < covered:
            continue                                   # overlaps a chunk already kept (an older chunk size)
        try:
            kept.append(_check(path, spec, start, -minus_stop))
        except (OSError, ValueError, UnicodeDecodeError):
            path.unlink(missing_ok=True)
            continue
        covered = -minus_stop
    return kept


def missing_ranges(kept, count):
    """``[(start, stop)]``: the index ranges of ``count`` configurations no :class:`Kept` covers."""
    ranges, at = [], 0
    for k in kept:
        if k.start > at:
            ranges.append((at, k.start))
        at = max(at, k.stop)
    if at < count:
        ranges.append((at, count))
    return ranges


def split(ranges, size):
    """The ranges cut into chunks ``(start, stop)`` of at most ``size`` configurations."""
    return [(a, min(a + size, stop)) for start, stop in ranges for a in range(start, stop, size)]


def write_tables(out, spec, kept):
    """``out/results.csv`` and, with pyarrow, ``out/results.parquet`` from the chunk files of
    ``kept`` (every configuration covered, in index order), streamed one chunk at a time."""
    out = Path(out)

    def csv_body(fh):
        fh.write(header(spec.keys).encode())
        for k in kept:
            with open(chunk_path(out, k.start, k.stop), "rb") as chunk:
                shutil.copyfileobj(chunk, fh)
    write_atomic(out / "results.csv", csv_body)
    arrow = parquet_writer(spec.keys, numeric_keys(spec))
    if arrow is None:
        return
    _, schema = arrow
    # lazy: pyarrow is optional and slow to import; only the Parquet file needs it
    import pyarrow.parquet as pq

    def parquet_body(fh):
        strings = [f.name for f in schema if str(f.type) == "string"]     # numbers: dictionaries only cost time
        with pq.ParquetWriter(fh, schema, use_dictionary=strings) as writer:
            for k in kept:
                writer.write_table(arrow_chunk(chunk_path(out, k.start, k.stop), spec.keys, numeric_keys(spec)))
    write_atomic(out / "results.parquet", parquet_body)
