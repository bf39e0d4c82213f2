"""Running a sweep: chunks of configurations, in this process or on a Dask cluster, kept on disk.

``DIR/chunks/NNNNNN.json`` holds each finished chunk (written atomically), so an interrupted
sweep resumes where it stopped; ``DIR/sweep.json`` records the spec's fingerprint and a
resumed run must match it.  When every chunk is there, ``DIR/results.csv`` (and
``results.parquet`` when pyarrow is installed) holds one row per configuration in the spec's
order, the same whichever engine computed it.
"""

import json
from pathlib import Path

from ..errors import InputError
from ..output import write_atomic
from .evaluate import OUTPUTS, evaluate_chunk

ENGINES = ("serial", "local", "scheduler")


def require(module, extra="sweep"):
    """Import ``module`` or fail with the install command."""
    import importlib
    try:
        return importlib.import_module(module)
    except ImportError:
        raise InputError("(environment)", module, f"the {module} package: pip install 'bikemass[{extra}]'") from None


def check_keys(spec):
    """Every varied key names an input of the spec's bicycle or rider (InputError otherwise)."""
    from ..analysis.inputs import STIFFNESS_KEY, Model, get_path
    model = Model(spec.bike, spec.rider, spec.stiffness, spec.combine, origin=spec.source)
    for key in spec.keys:
        if key != STIFFNESS_KEY:
            get_path(model, key)


def _chunks(configurations, size):
    return [configurations[i:i + size] for i in range(0, len(configurations), size)]


def _prepare(spec, out):
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(out, "--out", "a directory (this is a file)")
    (out / "chunks").mkdir(parents=True, exist_ok=True)
    stamp = out / "sweep.json"
    record = {"spec": spec.source, "fingerprint": spec.fingerprint(), "keys": list(spec.keys)}
    if stamp.is_file():
        old = json.loads(stamp.read_text())
        if old.get("fingerprint") != record["fingerprint"]:
            raise InputError(out, "sweep.json", f"results of the same spec to resume (this folder holds "
                             f"{old.get('spec')}, a different sweep): use another --out")
    else:
        write_atomic(stamp, json.dumps(record, indent=2) + "\n")
    return out


def _chunk_path(out, i):
    return out / "chunks" / f"{i:06d}.json"


def _save_chunk(out, i, rows):
    write_atomic(_chunk_path(out, i), json.dumps(rows))


def run_sweep(spec, out, workers=None, scheduler=None, progress=None):
    """Evaluate every configuration of ``spec`` (a :class:`~bikemass.sweep.spec.SweepSpec` or a spec
    file) into folder ``out``; returns the result rows (dicts, one per configuration).

    ``workers``: a local Dask cluster of that many single-threaded worker processes;
    ``scheduler``: the address of a running Dask scheduler; neither: this process.
    ``progress(n)`` is called with the number of configurations finished by each chunk.
    """
    if not hasattr(spec, "configurations"):
        from .spec import read_spec
        spec = read_spec(spec)
    check_keys(spec)
    out = _prepare(spec, out)
    configurations = spec.configurations()
    chunks = _chunks(configurations, spec.chunk)
    todo = [i for i in range(len(chunks)) if not _chunk_path(out, i).is_file()]
    if progress:
        progress(len(configurations) - sum(len(chunks[i]) for i in todo))
    setup = (spec.bike, spec.rider, spec.stiffness, spec.combine, spec.source)
    if workers is None and scheduler is None:
        for i in todo:
            _save_chunk(out, i, evaluate_chunk(setup, chunks[i], spec.max_speed))
            if progress:
                progress(len(chunks[i]))
    else:
        _run_dask(setup, spec, chunks, todo, out, workers, scheduler, progress)
    rows = []
    for i, chunk in enumerate(chunks):
        results = json.loads(_chunk_path(out, i).read_text())
        rows += [{**config, **result} for config, result in zip(chunk, results)]
    write_results(rows, spec.keys, out)
    return rows


def _run_dask(setup, spec, chunks, todo, out, workers, scheduler, progress):
    distributed = require("distributed")
    if scheduler is not None:
        try:
            client = distributed.Client(scheduler, timeout="10s")
        except (OSError, TimeoutError) as exc:
            raise InputError("--scheduler", scheduler, f"a running Dask scheduler ({exc})") from None
        cluster = None
    else:
        cluster = distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                           host="127.0.0.1", dashboard_address="127.0.0.1:0", silence_logs=40)
        client = distributed.Client(cluster)
    try:
        futures = {client.submit(evaluate_chunk, setup, chunks[i], spec.max_speed, pure=False): i for i in todo}
        for future in distributed.as_completed(futures):
            i = futures[future]
            _save_chunk(out, i, future.result())
            if progress:
                progress(len(chunks[i]))
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def _cell(value):
    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    text = str(value)
    return '"' + text.replace('"', '""') + '"' if any(c in text for c in ',"\n') else text


def write_results(rows, keys, out):
    """``results.csv`` (full precision, empty = none) and, with pyarrow, ``results.parquet``."""
    columns = list(keys) + list(OUTPUTS)
    lines = [",".join(columns)] + [",".join(_cell(r.get(c)) for c in columns) for r in rows]
    write_atomic(Path(out) / "results.csv", "\n".join(lines) + "\n")
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        return
    from io import BytesIO
    table = pa.table({c: [r.get(c) for r in rows] for c in columns})
    buf = BytesIO()
    pq.write_table(table, buf)
    write_atomic(Path(out) / "results.parquet", buf.getvalue())
