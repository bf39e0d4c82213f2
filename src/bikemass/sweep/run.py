"""Running a sweep: chunks of configurations, in this process or on a Dask cluster, kept on disk.

``DIR/chunks/START-STOP.json`` holds the result rows of configurations ``START..STOP-1``
(written atomically as each chunk finishes), so an interrupted sweep resumes where it
stopped, whatever engine or chunk size the next run uses; ``DIR/sweep.json`` records the
spec's fingerprint and a resumed run must match it (a folder with files but no record, or a
damaged one, is refused: its chunks could be any sweep's; a damaged chunk file is computed
again).  A sweep whose every configuration the model refuses is an error (naming the first
reason), one with some refused a warning; the rows keep each reason in ``error``.  When every configuration has its row,
``DIR/results.csv`` (and ``results.parquet`` when pyarrow is installed) holds one row per
configuration in the spec's order, the same whichever engine computed it.

Chunk size: the spec's ``chunk`` if it gives one.  Otherwise, on Dask, equal chunks, as
many per worker thread as the configurations' cost calls for: a task costs the cluster a
few milliseconds of bookkeeping (about 5 ms of CPU on a small 2-core machine), so
configurations that only change benchmark parameters (well under a millisecond each) go
out as one chunk per worker thread, and costlier ones (a changed bicycle, rider or
stiffness: tens to hundreds of milliseconds each) as :data:`TASKS_PER_WORKER` per worker
thread, which evens out the load.  In this process, :data:`SERIAL_CHUNKS` chunks (the
progress bar's steps).  Never more than :data:`MAX_CHUNK` configurations a chunk, so a long
sweep loses little when interrupted.
"""

import signal
import importlib
import json
import os
import pickle
import re
import shutil
import threading
from collections.abc import Callable
from contextlib import contextmanager
from pathlib import Path

from ..core.errors import InputError, short, wrong_type
from ..core.output import write_atomic
from ..models.parameters import NAMES
from ..scenario.inputs import STIFFNESS_KEY
from .evaluate import Chunk, finish_chunk, finish_chunk_pickled, OUTPUTS
from .spec import SweepSpec, read_spec
from ..models.plausibility import warn
from .table import csv_lines, write_results

TASKS_PER_WORKER = 4
SERIAL_CHUNKS = 20
MAX_CHUNK = 2000
_CHUNK_NAME = re.compile(r"(\d+)-(\d+)\.json")


def require(module, extra="sweep"):
    """Import ``module`` or fail with the install command."""
    try:
        return importlib.import_module(module)
    except ImportError:
        raise InputError("(environment)", module, f"the {module} package: pip install 'bikemass[{extra}]'") from None


def check_keys(spec):
    """Every varied key names an input of the spec's bicycle or rider, and the spec's stiffness
    (and each stiffness name it varies) is one the bicycle and the model take (InputError
    otherwise): a misspelt choice fails once here instead of on every row."""
    scenario = spec.scenario()
    for key in spec.keys:
        if key != STIFFNESS_KEY:
            scenario.value(key)
    choices = [("stiffness", spec.stiffness)] + [(f"vary.{STIFFNESS_KEY}", value) for variable in spec.variables
                                                 if variable.key == STIFFNESS_KEY for value in variable.values
                                                 if isinstance(value, str)]
    for key, choice in choices:
        try:
            scenario.check_stiffness(choice)
        except InputError as exc:
            raise InputError(spec.source, key, f"{exc.expected} (got {short(choice)}: {exc.source}: {exc.key})") from None


def chunk_size(count, slots=None, fixed=None, cheap=False):
    """Configurations per chunk for ``count`` of them: ``fixed`` if given; in this process, or
    on a cluster with no worker yet (``slots`` None or 0), :data:`SERIAL_CHUNKS` chunks; on
    ``slots`` worker threads, chunks of (nearly) equal size in rounds of at most one per
    thread: one round for ``cheap`` configurations, else :data:`TASKS_PER_WORKER`, more when
    needed to stay within :data:`MAX_CHUNK`."""
    if fixed:
        return fixed
    if not slots:
        return max(1, min(MAX_CHUNK, -(-count // SERIAL_CHUNKS)))
    rounds = max(1 if cheap else TASKS_PER_WORKER, -(-count // (slots * MAX_CHUNK)))
    return max(1, -(-count // (slots * rounds)))


def parameters_only(spec):
    """True if every varied key is one of the 26 benchmark parameters: each configuration is
    then a set of parameters to critical speeds, well under a millisecond."""
    return all(key in NAMES for key in spec.keys)


def _missing_chunks(done, count, size):
    """:class:`Chunk` index ranges (at most ``size`` long) covering the indices not in ``done``."""
    chunks, start = [], None
    for i in range(count + 1):
        if i < count and not done[i]:
            if start is None:
                start = i
            if i + 1 - start == size:
                chunks.append((start, i + 1))
                start = None
        elif start is not None:
            chunks.append((start, i))
            start = None
    return chunks


STAMP = "sweep.json"
"""The record of the sweep a folder holds (its spec's fingerprint): a resumed run must match it."""
MAX_STAMP_BYTES = 100_000


def _record(spec):
    return {"spec": spec.source, "fingerprint": spec.fingerprint(), "keys": list(spec.keys)}


def _check_folder(spec, out):
    """Before any work: ``out`` is a new or empty folder, or holds this sweep's own record (a
    missing or damaged record, or another spec's, is refused: its chunks could be anyone's)."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(out, "--out", "a directory (this is a file)")
    stamp = out / STAMP
    if stamp.is_file():
        old = _read_stamp(stamp)
        if old["fingerprint"] != _record(spec)["fingerprint"]:
            raise InputError(out, STAMP, f"results of the same spec to resume (this folder holds "
                             f"{short(old.get('spec'))}, a different sweep): use another --out")
    elif out.is_dir() and any(out.iterdir()):
        raise InputError(out, STAMP, f"a new or empty folder, or a sweep's own holding {STAMP} (this one holds "
                         f"other files and no {STAMP}, so its chunks could be another sweep's): use another --out")


def _read_stamp(stamp):
    """The record in ``stamp`` (a dict with a ``fingerprint``); InputError if it is damaged."""
    damaged = ("the record bikemass sweep writes (JSON with a fingerprint); this one is damaged: remove the "
               "folder or use another --out")
    try:
        if stamp.stat().st_size > MAX_STAMP_BYTES:
            raise ValueError
        record = json.loads(stamp.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        raise InputError(stamp, "(file)", damaged) from None
    if not isinstance(record, dict) or not isinstance(record.get("fingerprint"), str):
        raise InputError(stamp, "(file)", damaged)
    return record


def _prepare(spec, out):
    out = Path(out)
    (out / "chunks").mkdir(parents=True, exist_ok=True)
    if not (out / STAMP).is_file():
        write_atomic(out / STAMP, json.dumps(_record(spec), indent=2) + "\n")
    return out


def _valid_rows(rows, count):
    """True if ``rows`` (read from a chunk file) are ``count`` result rows as :func:`evaluate` writes
    them; a damaged chunk file is computed again."""
    return isinstance(rows, list) and len(rows) == count and all(
        isinstance(r, dict) and set(r) == set(OUTPUTS)
        and all(r[k] is None or (isinstance(r[k], (int, float)) and not isinstance(r[k], bool))
                for k in OUTPUTS if k != "error")
        and (r["error"] is None or isinstance(r["error"], str)) for r in rows)


def _finished(out, count):
    """``[rows or None]`` per configuration, from the chunk files of an earlier run of this sweep."""
    results = [None] * count
    for path in (out / "chunks").glob("*.json"):
        match = _CHUNK_NAME.fullmatch(path.name)
        if not match:
            continue
        start, stop = int(match[1]), int(match[2])
        try:
            rows = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            continue
        if 0 <= start < stop <= count and _valid_rows(rows, stop - start):
            results[start:stop] = rows
    return results


def _outcome(rows, spec, out, created):
    """One outcome for rows the model refused: all of them is an error (InputError naming the first
    reason; a folder this run made is removed), some of them a warning."""
    failed = [r["error"] for r in rows if r["error"]]
    if not failed:
        return
    if len(failed) == len(rows):
        if created:
            shutil.rmtree(out, ignore_errors=True)
        raise InputError(spec.source, "vary", f"configurations the model accepts; all {len(rows)} were refused, "
                                              f"the first: {failed[0]}")
    warn(f"{spec.source}: {len(failed)} of {len(rows)} configurations were refused by the model (see the error "
         f"column of {Path(out) / 'results.csv'}), the first: {failed[0]}")


def run_sweep(spec: "SweepSpec | str | os.PathLike", out: "str | os.PathLike", workers: int | None = None,
              scheduler: "str | distributed.Client | None" = None,
              progress: "Callable[[int], object] | None" = None) -> list[dict]:
    """Evaluate every configuration of a design sweep into a folder (``bm.sweep``).

    Each configuration (a grid or a sample of the varied keys) is built and its weave and capsize
    speeds and stable range found; chunks of configurations run in this process or on Dask, each
    chunk written as it finishes, so an interrupted sweep resumes where it stopped.

    Parameters
    ----------
    spec : SweepSpec, str or os.PathLike
        A sweep YAML file (``bike``, ``vary``, optional ``rider``, ``stiffness``, ``sample``,
        ``max_speed``, ... : docs/analysis.md) or a read
        :class:`~bikemass.sweep.spec.SweepSpec`.
    out : str or os.PathLike
        The folder for ``results.csv``, ``results.parquet``, ``sweep.json`` and ``chunks/``
        (created; an earlier run of the same spec there is resumed).
    workers : int, optional
        A local Dask cluster of that many single-threaded worker processes.
    scheduler : str or distributed.Client, optional
        The address of a running Dask scheduler, or a ``distributed.Client`` (used as it is and
        left open: a notebook's cluster serves many sweeps). Neither ``workers`` nor
        ``scheduler``: this process.
    progress : callable, optional
        Called with the number of configurations already finished, then with the number
        finished by each chunk.

    Returns
    -------
    list of dict
        One row per configuration: the varied values, ``weave_speed``, ``capsize_speed``,
        ``stable_from``, ``stable_to`` (m/s, ``None`` where there is none), ``total_mass``
        (kg) and ``error`` (why the model refused it, else ``None``).

    Raises
    ------
    InputError
        Bad arguments or spec (naming its file and key); ``out`` a file, or a folder holding other
        files than a sweep's own, another spec's sweep or a damaged ``sweep.json``; a scheduler that
        cannot be reached; the model refusing every configuration (the first reason named; a folder
        this call made is removed).

    Warns
    -----
    BikemassWarning
        The model refused some configurations (each row keeps its reason in ``error``).

    See Also
    --------
    sensitivity, uncertainty : Local derivatives and spreads instead of a grid.

    Examples
    --------
    >>> import os, tempfile
    >>> import bikemass as bm
    >>> folder = tempfile.mkdtemp()
    >>> spec = os.path.join(folder, "trail.yaml")             # the trail c in m
    >>> _ = open(spec, "w").write("{bike: benchmark, vary: {c: [0.04, 0.08, 0.12]}}")
    >>> for row in bm.sweep(spec, os.path.join(folder, "out")):      # c = 0.08 m is the benchmark
    ...     print(f"c {row['c']:.2f} m: stable {row['stable_from']:.4f}..{row['stable_to']:.4f} m/s")
    c 0.04 m: stable 3.7529..4.7672 m/s
    c 0.08 m: stable 4.2924..6.0243 m/s
    c 0.12 m: stable 4.6965..7.1149 m/s
    """
    _check_arguments(spec, out, workers, progress)
    if not hasattr(spec, "configurations"):
        spec = read_spec(spec)
    check_keys(spec)
    _check_folder(spec, out)
    created = not Path(out).exists() or not any(Path(out).iterdir())
    with _engine(workers, scheduler) as (run, slots):       # a cluster that cannot be reached leaves no folder
        out = _prepare(spec, out)
        configurations = spec.configurations()
        results = _finished(out, len(configurations))
        done = [r is not None for r in results]
        if progress:
            progress(sum(done))
        setup = spec.scenario()
        lines = [None] * len(configurations)
        size = chunk_size(done.count(False), slots, spec.chunk, cheap=parameters_only(spec))
        chunks = [Chunk(a, configurations[a:b], spec.units)
                  for a, b in _missing_chunks(done, len(configurations), size)]
        for chunk, (rows, text, chunk_lines) in run(setup, chunks, spec.max_speed, spec.keys):
            write_atomic(out / "chunks" / f"{chunk.start:09d}-{chunk.stop:09d}.json", text)
            results[chunk.start:chunk.stop] = rows
            lines[chunk.start:chunk.stop] = chunk_lines
            if progress:
                progress(len(rows))
    for i in (i for i, kept in enumerate(done) if kept):           # rows from an earlier run's chunk files
        lines[i] = csv_lines(spec.keys, configurations[i:i + 1], results[i:i + 1])[0]
    rows = [{**config, **result} for config, result in zip(configurations, results)]
    write_results(rows, spec.keys, out, lines)
    _outcome(rows, spec, out, created)
    return rows


def max_workers():
    """Most local worker processes a sweep starts: 4 per core."""
    return 4 * (os.cpu_count() or 1)


def _check_arguments(spec, out, workers, progress):
    """InputError for arguments :func:`run_sweep` cannot use (before any folder is made)."""
    if not isinstance(spec, (str, os.PathLike, SweepSpec)):
        raise wrong_type("spec", spec, "a sweep spec file or a SweepSpec")
    if not isinstance(out, (str, os.PathLike)):
        raise wrong_type("out", out, "an output folder path")
    if workers is not None and (isinstance(workers, bool) or not isinstance(workers, int)
                                or not 1 <= workers <= max_workers()):
        raise InputError("--workers", workers, f"from 1 to {max_workers()} worker processes (4 per core at most)")
    if progress is not None and not callable(progress):
        raise wrong_type("progress", progress, "a function of the number of finished configurations")


QUIET_CLUSTER = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "2s",
    "distributed.worker.memory.monitor-interval": "1s",
}
"""Dask settings of the local cluster ``--workers N`` starts: the workers' statistical
profiler off and the event-loop health check, system monitor and memory monitor run less
often.  With Dask's defaults an idle 2-worker LocalCluster keeps about a quarter of a core
busy, which a CPU-bound sweep on a small machine pays for; with these, about 3 %.
docs/analysis.md#bikemass-sweep ("Engines") shows the same settings as environment variables for
``dask scheduler`` and ``dask worker``."""


@contextmanager
def _engine(workers, scheduler):
    """``(run, slots)``: ``run(setup, chunks, max_speed, keys)`` yields ``(chunk, finish_chunk(...))``
    as chunks finish; ``slots`` = worker threads (``None`` in this process)."""
    if workers is None and scheduler is None:
        yield (lambda setup, chunks, vmax, keys: ((c, finish_chunk(setup, c, vmax, keys)) for c in chunks)), None
        return
    distributed = require("distributed")
    with _client(distributed, workers, scheduler) as client:
        def run(setup, chunks, vmax, keys):
            n = len(chunks)
            futures = client.map(finish_chunk_pickled, [setup] * n, chunks, [vmax] * n, [keys] * n, pure=False)
            owner = {future.key: chunk for future, chunk in zip(futures, chunks)}
            finished = 0
            try:
                for future in distributed.as_completed(futures, loop=client.loop):
                    yield owner[future.key], pickle.loads(future.result())
                    finished += 1
            finally:
                if finished < len(futures):     # interrupted: leave no work behind on a shared cluster
                    client.cancel(futures)
        yield run, sum(client.nthreads().values())


@contextmanager
def _client(distributed, workers, scheduler):
    """A Dask client: ``scheduler`` itself if it is one (left open), a new one connected to the
    address ``scheduler``, or one of a new local cluster of ``workers`` processes."""
    if isinstance(scheduler, distributed.Client):
        if scheduler.asynchronous:
            raise InputError("scheduler", "an asynchronous Client", "a synchronous distributed.Client "
                             "(run_sweep blocks until the sweep is done)")
        yield scheduler
        return
    if scheduler is not None:
        try:
            if not isinstance(scheduler, str):
                raise ValueError(f"an address string or a distributed.Client, got {type(scheduler).__name__}")
            distributed.comm.resolve_address(scheduler)      # a malformed address: one line, no Client made
            client = _connected(distributed, scheduler)
        except (OSError, TimeoutError, ValueError) as exc:
            raise InputError("--scheduler", scheduler, f"a running Dask scheduler ({exc})") from None
        with client:
            yield client
        return
    with local_cluster(workers) as cluster, distributed.Client(cluster, set_as_default=False) as client:
        yield client


CONNECT_DEADLINE = 20
"""Seconds a scheduler has to answer (distributed's own 10 s timeout does not bound a listener that
accepts the connection and never speaks)."""


def _connected(distributed, address):
    """A ``distributed.Client`` of the scheduler at ``address``, made in a thread of its own and
    given up after :data:`CONNECT_DEADLINE` seconds (TimeoutError); the thread is a daemon, so a
    connection that never ends does not keep the process alive."""
    box = {}

    def connect():
        try:
            box["client"] = distributed.Client(address, timeout="10s", set_as_default=False)
        except BaseException as exc:           # handed to the caller's thread
            box["error"] = exc
    thread = threading.Thread(target=connect, name="bikemass-connect", daemon=True)
    thread.start()
    thread.join(CONNECT_DEADLINE)
    if thread.is_alive():
        raise TimeoutError(f"no answer within {CONNECT_DEADLINE} s")
    if "error" in box:
        raise box["error"]
    return box["client"]


def local_cluster(workers):
    """The Dask cluster of ``--workers N``: ``workers`` single-threaded worker processes on
    loopback, with :data:`QUIET_CLUSTER`'s settings.  The workers are started with SIGINT
    ignored, which they keep: a Ctrl-C in the terminal reaches the whole process group, and
    the command (this process) stops them itself, so they print nothing of their own."""
    # lazy: dask is optional (the sweep extra) and slow to import; only --workers needs it
    import dask
    distributed = require("distributed")
    with dask.config.set(QUIET_CLUSTER), _workers_ignore_sigint():
        return distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                        host="127.0.0.1", dashboard_address="127.0.0.1:0", silence_logs=40)


@contextmanager
def _workers_ignore_sigint():
    """SIGINT ignored while the block starts worker processes (an ignored signal stays ignored in
    a process started from this one); the previous handler back afterwards.  In the main thread
    only (elsewhere signal handlers cannot change); a Ctrl-C during the block is not seen."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
