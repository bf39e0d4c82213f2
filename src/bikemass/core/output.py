"""Writing results: JSON/YAML of plain data, text tables, and atomic file writes.

Every file is written whole or not at all (a temporary file in the same folder,
then ``os.replace``); an existing file keeps its permissions, a symbolic link
stays a link (its target is replaced), and a file this run has read as input
is never replaced.  :func:`check_output` refuses a bad output path before any
work is done; :func:`new_folder` gives a folder that appears complete or not
at all.
"""

import contextlib
import contextvars
import csv
import io
import json
import math
import os
import shutil
import stat
import tempfile
from numbers import Integral, Real
from pathlib import Path

import numpy as np
import yaml

from .errors import InputError, short
from .gate import was_read
from .plain import document_keys, file_form
from .stopping import deferred

_WARNINGS = contextvars.ContextVar("bikemass_warnings", default=None)
"""The list of recorded warnings the command line collects (``None`` outside it)."""


@contextlib.contextmanager
def collect_warnings(caught):
    """While active, :func:`dumps` adds the messages of the recorded ``caught`` warnings to a JSON
    mapping under ``warnings`` (YAML output stays a file bikemass reads back)."""
    token = _WARNINGS.set(caught)
    try:
        yield caught
    finally:
        _WARNINGS.reset(token)


def warning_lines(caught):
    """The distinct messages of recorded warnings ``caught``, in the order first issued (a file read
    twice in one command warns once)."""
    return list(dict.fromkeys(str(w.message) for w in caught))


ZERO = 1e-12
"""Magnitude below which bikemass writes a length, mass, inertia, angle, speed, stiffness or
frequency as 0, in its SI unit (m, kg, kg m^2, rad, m/s, N m/rad, Hz, 1/s; deg too).

Quantities that are zero in exact arithmetic -- the gap at a joint of a chain pose, a met
contact's residual, the lateral CoM and the products Ixy, Iyz of a mirror-symmetric rider or
bicycle -- come out of floating-point arithmetic as rounding noise of about 1e-16 times the
numbers they were computed from, and that noise changes with the CPU, the BLAS kernel and
the thread count.  A bicycle's and a rider's quantities in these units are 1e-3 to 1e4, so
1e-12 lies well above the noise and far below anything measurable.  JSON and YAML documents
(by their ``units`` block), CSV files (by the unit in a column's header) and the command's
own reports apply it (docs/cli.md, "Numbers"); quantities of other units (derivatives,
per-pascal values) are written in full."""

ZERO_UNITS = {"m": 1.0, "mm": 1e3, "kg": 1.0, "kg m^2": 1.0, "rad": 1.0, "deg": 1.0, "m/s": 1.0,
              "N m/rad": 1.0, "Hz": 1.0, "1/s": 1.0}
"""The units :data:`ZERO` applies to -> the threshold's size in that unit (1e-12 m = 1e-9 mm)."""

SIGNIFICANT = 12
"""Significant digits a number is rounded to before a text table formats it (:func:`as_shown`):
a value that sits on a rounding tie in exact arithmetic (-1.23625 shown to 4 decimals) then
rounds the same way on every machine instead of following its last-bit noise."""


FIXED_LIMIT = 1e15
"""From this size on a fixed-point format (``{:.4f}``) shows a float in exponent form instead
(``1e+300``, not a 300-digit integer): past :data:`SIGNIFICANT` digits the rest is noise."""


def as_written(x, unit):
    """The float ``x`` (in ``unit``) as bikemass writes it: 0.0 when below :data:`ZERO` in a
    unit of :data:`ZERO_UNITS` (never -0.0), else ``x`` with every digit."""
    x = float(x)
    scale = ZERO_UNITS.get(unit)
    return 0.0 if scale is not None and abs(x) < ZERO * scale else x


def as_shown(x):
    """The float ``x`` as a text table shows it: rounded to :data:`SIGNIFICANT` significant
    digits, no minus sign on zero (non-finite values unchanged)."""
    x = float(x)
    return float(f"{x:.{SIGNIFICANT}g}") + 0.0 if np.isfinite(x) else x


def formatted(fmt, x):
    """``fmt.format(x)`` as a text table shows a float: from :func:`as_shown`, a value that
    rounds to zero without a minus sign (``-0.0000`` is written ``0.0000``), and a value of
    :data:`FIXED_LIMIT` or more in a fixed-point format in exponent form."""
    x = as_shown(x)
    if np.isfinite(x) and abs(x) >= FIXED_LIMIT and fmt.rstrip("}").endswith("f"):
        return f"{x:.{SIGNIFICANT}g}"
    text = fmt.format(x)
    return fmt.format(0.0) if text == fmt.format(-0.0) else text


def _unit_key(unit):
    """``"1/s (pairs: real, imaginary)"`` -> ``"1/s"``: the unit without its remark."""
    return unit.split(" (")[0].strip() if isinstance(unit, str) else None


def _written_data(obj, units, unit=None):
    """Plain data with every float under a key of ``units`` passed through :func:`as_written`
    (a key without a unit takes its parent's)."""
    if isinstance(obj, dict):
        return {k: _written_data(v, units, _unit_key(units[k]) if k in units else unit) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_written_data(v, units, unit) for v in obj]
    if isinstance(obj, float):
        return as_written(obj, unit)
    return obj


def written(document):
    """A document as bikemass writes it: plain data (:func:`~bikemass.core.plain.plain`) with :data:`ZERO` applied
    to every number under a key of its top-level ``units`` block (a
    :class:`~bikemass.core.units.Quantity` as its text, :func:`~bikemass.core.plain.file_form`)."""
    data = file_form(document)
    if isinstance(data, dict) and isinstance(data.get("units"), dict):
        data = _written_data(data, data["units"])
    return data


def _header_unit(header):
    """``"x (m)"`` -> ``"m"``: the unit a CSV header names in parentheses, else None."""
    header = str(header)
    return header[header.rindex("(") + 1:-1] if header.endswith(")") and "(" in header else None


def csv_text(headers, rows):
    """CSV text: ``None`` as an empty cell, floats in full (``repr``), 0 below :data:`ZERO` in a
    column whose header names a unit of :data:`ZERO_UNITS` (``"x (m)"``)."""
    units = [_header_unit(h) for h in headers]

    def cell(v, unit):
        if v is None:
            return ""
        if isinstance(v, Real) and not isinstance(v, (bool, Integral)):
            return repr(as_written(v, unit))
        return v

    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(headers)
    writer.writerows([[cell(v, u) for v, u in zip(r, units)] for r in rows])
    return buffer.getvalue()


def units_of(obj, units):
    """``{key: unit}`` of every key of ``obj`` (at any depth) that ``units`` declares, in order of
    appearance: ``units`` comes from the types that made the document (a result's
    :meth:`~bikemass.core.results.Result.units`, :func:`~bikemass.core.results.declared_units`, the
    benchmark parameters' :func:`~bikemass.models.parameters.parameter_units`); no unit is guessed
    from a key's name."""
    return {k: units[k] for k in document_keys(obj) if k in units}


def with_units(obj, units):
    """The document ``obj`` (a mapping) with a top-level ``units`` block of the keys it holds that
    ``units`` declares (:func:`units_of`): the one rule by which every JSON/YAML output states its
    units (keys never carry unit suffixes)."""
    return {**obj, "units": units_of(obj, units)}


def strict_json(data):
    """Plain ``data`` with every NaN or infinite float as ``None``: JSON has no such numbers (``null``
    is "no value", as a NaN of a result means: e.g. no hands-free circle at that steer angle)."""
    if isinstance(data, dict):
        return {k: strict_json(v) for k, v in data.items()}
    if isinstance(data, list):
        return [strict_json(v) for v in data]
    if isinstance(data, float) and not math.isfinite(data):
        return None
    return data


def dumps(obj, fmt):
    """Serialise plain data as ``json`` or ``yaml`` text."""
    data = written(obj)
    caught = _WARNINGS.get()
    if caught and fmt == "json" and isinstance(data, dict):
        data = {**data, "warnings": warning_lines(caught)}
    if fmt == "json":
        return json.dumps(strict_json(data), indent=2, allow_nan=False) + "\n"
    if fmt == "yaml":
        return yaml.safe_dump(data, sort_keys=False)
    raise ValueError(f"unknown format {fmt!r}")


def table(headers, rows, floatfmt="{:.3f}"):
    """A plain-text table; floats formatted with ``floatfmt`` (by :func:`formatted`: at most
    :data:`SIGNIFICANT` significant digits, no ``-0``), ``None`` shown as '-'."""
    def cell(v):
        if v is None:
            return "-"
        if isinstance(v, (float, np.floating)):
            return formatted(floatfmt, v)
        return str(v)
    text = [[cell(h) for h in headers]] + [[cell(v) for v in r] for r in rows]
    widths = [max(len(r[i]) for r in text) for i in range(len(headers))]
    lines = ["  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths)))
             for r in text]
    lines.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(lines) + "\n"


NAME_MAX = 255
"""Longest file name (bytes) assumed where the file system does not say (Linux, macOS, Windows)."""
TEMPORARY_EXTRA = 16
"""Bytes a temporary name adds to its prefix: tempfile's 8 random characters, the suffix and a dot."""


def _temporary_prefix(target):
    """Prefix of the temporary file or folder written next to ``target`` before it is renamed:
    ``.<name>.``, with the name shortened (kept readable, made unique by a digest of the whole
    name) where the full one would take a legal ``target`` name past the file system's limit."""
    import hashlib                                     # lazy: only for names near the limit
    name = Path(target).name
    try:
        limit = os.pathconf(Path(target).parent if str(Path(target).parent) else ".", "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):
        limit = NAME_MAX
    prefix = f".{name}."
    if len(prefix.encode()) + TEMPORARY_EXTRA <= limit:
        return prefix
    digest = hashlib.sha1(name.encode("utf-8", "surrogateescape")).hexdigest()[:10]
    keep = max(0, limit - TEMPORARY_EXTRA - len(digest) - 3)
    head = name.encode("utf-8", "surrogateescape")[:keep].decode("utf-8", "ignore")
    return f".{head}~{digest}."


def write_atomic(path, data):
    """Write ``data`` (str or bytes, or a function that writes the content to the binary file it
    is given: a large file streamed) to ``path`` via a temporary file and rename: never half-written.

    An existing file keeps its permission bits; a symbolic link keeps pointing where it did and
    its target is replaced.  A file read as input in this run (:func:`bikemass.core.gate.was_read`)
    is refused.  A write that fails (a full disk, a quota, an I/O error) is an InputError naming
    the path, the temporary file removed and the old file left as it was.
    """
    path = Path(path)
    check_output(path)
    target = Path(os.path.realpath(path))
    if was_read(target):
        raise InputError(path, "(output)", "a file other than the command's input (it would be overwritten)")
    streamed = callable(data)
    mode = "wb" if streamed or isinstance(data, bytes) else "w"
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=_temporary_prefix(target), suffix=".tmp")
    except OSError as exc:
        raise InputError(path, "(output)", f"a file in a writable folder ({exc.strerror})") from None
    # a stop signal waits until the file is in place (a streamed one: only for the rename; a stop
    # while it is written removes the temporary file)
    with contextlib.nullcontext() if streamed else deferred():
        try:
            with os.fdopen(fd, mode) as fh:
                data(fh) if streamed else fh.write(data)
            with deferred():
                os.chmod(tmp, _mode_for(target))
                os.replace(tmp, target)
        except BaseException as exc:
            with contextlib.suppress(OSError):
                os.unlink(tmp)
            if isinstance(exc, OSError):     # a full disk, a quota, an I/O error: nothing was replaced
                raise InputError(path, "(output)", f"room to write the file in its folder ({exc.strerror or exc}; "
                                                   "nothing was written)") from None
            raise


def _mode_for(target):
    """Permission bits for a file written at ``target``: its present ones, else 0666 less the umask."""
    try:
        return stat.S_IMODE(os.stat(target).st_mode)
    except OSError:
        return 0o666 & ~_umask()


def check_output(path, suffixes=None, inputs=(), what="an output file", option="(file)"):
    """Refuse (:class:`InputError`) an output path that cannot be written, before any work:
    a folder, a parent that is a file or not writable, a suffix not in ``suffixes``, or one of
    the command's ``inputs`` (paths or names; those that are existing files are compared), or a
    path the system refuses (a name too long, ...)."""
    try:
        _check_output(Path(path), suffixes, inputs, what, option)
    except OSError as exc:
        raise InputError(path, option, f"{what} path the system accepts ({exc.strerror or type(exc).__name__})") from None


def _check_output(path, suffixes, inputs, what, option):
    if suffixes is not None and path.suffix.lower() not in suffixes:
        raise InputError(path, option, f"{what} name ending in {', '.join(suffixes)}, "
                                         f"got {short(path.suffix or path.name, 30)}")
    target = Path(os.path.realpath(path))
    if target.is_dir():
        raise InputError(path, option, f"{what}, got a folder")
    if target.exists() and not target.is_file():
        raise InputError(path, option, f"{what}, got something that is not a regular file")
    for source in inputs:
        if source and target.exists() and os.path.isfile(source) and os.path.samefile(source, target):
            raise InputError(path, option, f"{what} other than the input {short(str(source), 80)} "
                                             "(it would be overwritten)")
    _check_folder(target.parent, path, option)


def _check_folder(folder, path, option):
    """The nearest existing ancestor of ``folder`` must be a folder we may create files in."""
    existing = folder
    while not existing.exists():
        if existing == existing.parent:
            break
        existing = existing.parent
    if not existing.is_dir():
        raise InputError(path, option, f"a path inside a folder, but {short(str(existing), 80)} is a file")
    try:
        fd, probe = tempfile.mkstemp(dir=existing, prefix=".bikemass-probe-")   # the only sure test
        os.close(fd)
        os.unlink(probe)
    except OSError as exc:
        raise InputError(path, option, f"a path in a writable folder, but {short(str(existing), 80)} "
                                       f"is not ({exc.strerror or type(exc).__name__})") from None


STUDY_MARK = "report.md"
"""A folder holding this file is taken to be an earlier run's output, which :func:`new_folder` may replace."""


def holds_files(folder):
    """Whether ``folder`` holds a file anywhere in it: empty folders alone (what a run stopped
    by a full disk may leave) are no content to protect."""
    return any(files for _, _, files in os.walk(folder))


def check_folder(out, mark=STUDY_MARK, option="(folder)"):
    """Refuse an output folder that :func:`new_folder` could not replace safely."""
    out = Path(out)
    if out.exists() or out.is_symlink():
        if not out.is_dir():
            raise InputError(out, option, "an output folder, got a file")
        if holds_files(out) and not (out / mark).is_file():
            raise InputError(out, option, f"a new or empty folder, or an earlier output folder holding "
                                              f"{mark} (this one holds other files; nothing was changed)")
    _check_folder(out.resolve().parent, out, option)


@contextlib.contextmanager
def new_folder(out, mark=STUDY_MARK):
    """Yield a temporary folder next to ``out`` to write into; on success it replaces ``out`` (an
    earlier output folder is removed), on any failure or interruption it is removed instead.
    So ``out`` is always one run's complete output, never a mix of two or a partial one."""
    out = Path(out)
    check_folder(out, mark)
    parent = out.resolve().parent
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(dir=parent, prefix=_temporary_prefix(out), suffix=".tmp"))
    try:
        yield tmp
        with deferred():
            os.chmod(tmp, 0o777 & ~_umask())
            old = None
            if out.exists():
                check_folder(out, mark)
                old = Path(tempfile.mkdtemp(dir=parent, prefix=_temporary_prefix(out), suffix=".old"))
                os.replace(out, old / "previous")
            os.replace(tmp, out)
            if old is not None:
                shutil.rmtree(old, ignore_errors=True)
    except BaseException:
        with deferred():
            shutil.rmtree(tmp, ignore_errors=True)
        raise


def _umask():
    umask = os.umask(0)
    os.umask(umask)
    return umask
