"""Writing results: JSON/YAML of plain data, text tables, and atomic file writes."""

import json
import os
import tempfile
from collections.abc import Mapping
from pathlib import Path

import numpy as np
import yaml


def plain(obj):
    """Convert numpy scalars/arrays (recursively) into plain Python for JSON/YAML."""
    if isinstance(obj, Mapping):
        return {str(k): plain(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [plain(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return plain(obj.tolist())
    if isinstance(obj, np.generic):
        return obj.item()
    return obj


def dumps(obj, fmt):
    """Serialise plain data as ``json`` or ``yaml`` text."""
    data = plain(obj)
    if fmt == "json":
        return json.dumps(data, indent=2) + "\n"
    if fmt == "yaml":
        return yaml.safe_dump(data, sort_keys=False)
    raise ValueError(f"unknown format {fmt!r}")


def table(headers, rows, floatfmt="{:.3f}"):
    """A plain-text table; floats formatted with ``floatfmt``, ``None`` shown as '-'."""
    def cell(v):
        if v is None:
            return "-"
        if isinstance(v, (float, np.floating)):
            return floatfmt.format(v)
        return str(v)
    text = [[cell(h) for h in headers]] + [[cell(v) for v in r] for r in rows]
    widths = [max(len(r[i]) for r in text) for i in range(len(headers))]
    lines = ["  ".join(c.rjust(w) if i else c.ljust(w) for i, (c, w) in enumerate(zip(r, widths)))
             for r in text]
    lines.insert(1, "  ".join("-" * w for w in widths))
    return "\n".join(lines) + "\n"


def write_atomic(path, data):
    """Write ``data`` (str or bytes) to ``path`` via a temporary file and rename: never half-written."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, mode) as fh:
            fh.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
