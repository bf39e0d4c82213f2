"""Running a sweep: chunks of configurations, in this process or on a Dask cluster, streamed to disk.

Each chunk is an index range of the spec's configurations (:class:`~bikemass.sweep.evaluate.Chunk`):
the process or worker that computes it makes its configurations, evaluates them (as arrays when
they change only benchmark parameters) and formats its lines of ``results.csv``; the process
that gathers the chunks writes each to ``DIR/chunks/START-STOP.csv`` as it arrives and keeps
only its index range and refusal count, so its memory does not grow with the sweep.  When every
configuration has its lines, ``DIR/results.csv`` (and ``results.parquet`` with pyarrow) are
assembled from the chunk files (:mod:`bikemass.sweep.layout`, which also says how a run
resumes).  ``DIR/sweep.json`` records the spec's fingerprint, the SHA-256 of every input file
and bikemass's version and code digest: a folder with files but no record, a damaged one,
another spec's, or one whose inputs or bikemass changed since is refused (``restart`` starts
it over).  A sweep whose every configuration the
model refuses is an error (naming the first reason), one with some refused a warning; the rows
keep each reason in ``error``.

Chunk size: the spec's ``chunk`` if it gives one.  Configurations evaluated as arrays (well
under 10 us each) go in chunks of up to :data:`MAX_ARRAY_CHUNK`; costlier ones (a changed
bicycle, rider or stiffness: milliseconds to seconds each) in chunks of up to
:data:`MAX_CHUNK`, so a long sweep loses little when interrupted.  On Dask, equal chunks, one
round per worker thread for array chunks (a task costs the cluster a few milliseconds of
bookkeeping), :data:`TASKS_PER_WORKER` rounds for costly ones (evening out the load), at most
:data:`IN_FLIGHT` tasks per worker thread submitted at a time.  In this process,
:data:`SERIAL_CHUNKS` chunks (the progress bar's steps).

``--workers N`` with a small sweep: its first rows are computed here (:data:`PROBE_SECONDS`), and if the rest would
take less than :data:`WORKER_START` seconds in this process the whole sweep stays here (the
result's ``notes`` say so): starting a local cluster and importing bikemass in its workers
costs more than such a sweep.
"""

import dataclasses
import functools
import hashlib
import importlib
import importlib.util
import json
import os
import pickle
import shutil
import signal
import threading
import time
from collections.abc import Callable
from typing import Any, cast
from contextlib import contextmanager
from pathlib import Path

from .. import __version__
from ..core.errors import InputError, one_line, short, wrong_type
from ..core.gate import read_bytes, record_contents
from ..core.output import holds_files, write_atomic
from ..models.plausibility import warn
from ..scenario.inputs import STIFFNESS_KEY
from .evaluate import Chunk, _scenario, finish_chunk, finish_chunk_pickled
from .layout import CHUNKS, Kept, chunk_path, kept_chunks, missing_ranges, split, write_tables
from .result import SweepResult
from .spec import SweepSpec, read_spec
from .vectorised import takes

DaskClient = Any
"""A ``distributed.Client`` (Dask's, an optional dependency: not imported to annotate)."""

TASKS_PER_WORKER = 12
"""Rounds of chunks per worker thread for costly configurations: a worker that finishes its last
chunk first waits for the others' last, about half a chunk (with 4 rounds, a 16th of a 2-worker
sweep's work: 3 s of a 50 s sweep; with 12, a 48th); a task costs the cluster milliseconds."""
SERIAL_CHUNKS = 20
MAX_CHUNK = 2000
MAX_ARRAY_CHUNK = 100_000
"""Most configurations in one chunk evaluated as arrays: about 100 MB of a worker's memory at
the peak (the stacked matrices and the chunk's text), and 0.2-0.5 s of work."""
IN_FLIGHT = 4
"""Tasks per worker thread handed to the scheduler at a time; the next go out as chunks finish."""
PROBE_STEPS = 10
PROBE_SECONDS = 0.5
"""``--workers N``: the rows computed here to judge a sweep's size come in chunks of a
:data:`PROBE_STEPS`-th of a serial chunk, until :data:`PROBE_SECONDS` have passed (or one serial
chunk is done): a long sweep hands all but about half a second of its work to the workers
(a whole serial chunk, a 20th of the sweep, kept both workers waiting: 3 s of a 60 s sweep)."""
WORKER_START = 3.0
"""Seconds that starting ``--workers`` costs before the first chunk is computed there (a
2-worker LocalCluster and bikemass imported in each: 2.5-3 s on the 2-core machine of
docs/sweep.md).  A sweep whose rest would take less in this process stays here."""


def require(module, extra="sweep"):
    """Import ``module`` or fail with the install command."""
    try:
        return importlib.import_module(module)
    except ImportError:
        raise _missing(module, extra) from None


def require_installed(module, extra="sweep"):
    """Fail with the install command unless ``module`` is installed (found, not imported: a small
    sweep offered workers runs in this process and never needs it)."""
    if importlib.util.find_spec(module) is None:
        raise _missing(module, extra)


def _missing(module, extra):
    return InputError("(environment)", module, f"the {module} package: pip install 'bikemass[{extra}]'")


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
    thread: one round for ``cheap`` configurations (evaluated as arrays), else
    :data:`TASKS_PER_WORKER`, more when needed to stay within :data:`MAX_ARRAY_CHUNK` or
    :data:`MAX_CHUNK`."""
    if fixed:
        return fixed
    largest = MAX_ARRAY_CHUNK if cheap else MAX_CHUNK
    if not slots:
        return max(1, min(largest, -(-count // SERIAL_CHUNKS)))
    rounds = max(1 if cheap else TASKS_PER_WORKER, -(-count // (slots * largest)))
    return max(1, -(-count // (slots * rounds)))


STAMP = "sweep.json"
"""The record of the sweep a folder holds (its spec's fingerprint): a resumed run must match it."""
MAX_STAMP_BYTES = 100_000


@functools.lru_cache(maxsize=1)
def code_digest():
    """SHA-256 (16 hex digits) of bikemass's own source files: what computed a sweep's rows
    besides its inputs (an edited install keeps its version number)."""
    package = Path(__file__).resolve().parents[1]
    digest = hashlib.sha256()
    for path in sorted(package.rglob("*.py")):
        digest.update(path.relative_to(package).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def input_contents(spec):
    """``{resolved path: SHA-256}`` of every file the sweep's configurations are made from: those
    building its base configuration reads (the bicycle and what it builds on, the rider and its
    pose, the members' files, the stiffness file), and every file the spec names (a varied stiffness
    file, ...), found next to the spec."""
    with record_contents() as read:
        scenario = spec.scenario()
        try:
            scenario.build()
        except (InputError, ValueError, ArithmeticError):
            pass                                    # the rows will say why; the files read so far count
        names = [spec.bike, spec.rider, spec.stiffness, *(path for _, path in spec.members)]
        names += [x for v in spec.variables if v.values is not None for x in v.values if isinstance(x, str)]
        for name in names:
            if isinstance(name, str) and Path(name).is_file():
                try:
                    read_bytes(name)
                except InputError:
                    pass                            # unreadable: the configuration that needs it says so
    return dict(sorted(read.items()))


def _record(spec):
    return {"spec": spec.source, "fingerprint": spec.fingerprint(), "keys": list(spec.keys),
            "bikemass": {"version": __version__, "code": code_digest()}, "inputs": input_contents(spec)}


RESTART_HINT = "sweep --restart starts it over, or use another --out"


def _changes(old, new):
    """Why the record ``old`` of a folder does not fit this run's ``new`` (a phrase), or ``None``."""
    if not isinstance(old.get("bikemass"), dict) or not isinstance(old.get("inputs"), dict):
        return "it was made by an earlier bikemass that did not record its input files' content"
    was, now = old["bikemass"], new["bikemass"]
    if was.get("version") != now["version"]:
        return f"it was computed by bikemass {str(was.get('version'))[:40]}, this is {now['version']}"
    if was.get("code") != now["code"]:
        return f"bikemass's code changed since it was computed, at the same version {now['version']}"
    for path in sorted(set(old["inputs"]) | set(new["inputs"])):
        if path not in new["inputs"]:
            return f"{path} was an input of it and is not one now"
        if path not in old["inputs"]:
            return f"{path} is an input now and was not one of it"
        if old["inputs"][path] != new["inputs"][path]:
            return f"{path} changed since it was computed"
    return None


def _check_folder(spec, out, restart=False):
    """Before any work: ``out`` is a new or empty folder, or holds this sweep's own record made
    from the same inputs by the same bikemass (``restart``: any sweep's folder is emptied
    instead of resumed); the record returned.  A folder with files but no record, a damaged
    record, or another spec's is refused: its chunks could be anyone's."""
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise InputError(out, "--out", "a directory (this is a file)")
    stamp = out / STAMP
    record = _record(spec)
    if stamp.is_file():
        if restart:
            _clear(out)
            return record
        old = _read_stamp(stamp)
        if old["fingerprint"] != record["fingerprint"]:
            raise InputError(out, STAMP, f"results of the same spec to resume (this folder holds "
                             f"{short(old.get('spec'))}, a different sweep): use another --out, or --restart to "
                             "replace it")
        why = _changes(old, record)
        if why is not None:
            raise InputError(out, STAMP, f"the same spec, input files and bikemass to resume the sweep (here "
                             f"{why}): {RESTART_HINT}")
    elif out.is_dir() and holds_files(out):
        raise InputError(out, STAMP, f"a new or empty folder, or a sweep's own holding {STAMP} (this one holds "
                         f"other files and no {STAMP}, so its chunks could be another sweep's): use another --out")
    return record


SWEEP_FILES = (STAMP, "results.csv", "results.parquet", "sobol.json")
"""The files of a sweep's folder that ``restart`` removes (with ``chunks/``); figures are rewritten."""


def _clear(out):
    """Empty a sweep's folder of its record, chunks and tables (``restart``)."""
    shutil.rmtree(out / CHUNKS, ignore_errors=True)
    for name in SWEEP_FILES[1:] + SWEEP_FILES[:1]:          # the record last: a failure leaves a sweep's folder
        (out / name).unlink(missing_ok=True)


def _read_stamp(stamp):
    """The record in ``stamp`` (a dict with a ``fingerprint``); InputError if it is damaged."""
    damaged = f"the record bikemass sweep writes (JSON with a fingerprint); this one is damaged: {RESTART_HINT}"
    try:
        if stamp.stat().st_size > MAX_STAMP_BYTES:
            raise ValueError
        record = json.loads(stamp.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        raise InputError(stamp, "(file)", damaged) from None
    if not isinstance(record, dict) or not isinstance(record.get("fingerprint"), str):
        raise InputError(stamp, "(file)", damaged)
    return record


def _prepare(record, out):
    """The folder ``out`` with the sweep's ``record`` written first (a folder with chunks is
    always a sweep's), then ``chunks/``."""
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    if not (out / STAMP).is_file():
        write_atomic(out / STAMP, json.dumps(record, indent=2) + "\n")
    (out / CHUNKS).mkdir(exist_ok=True)
    return out


def _outcome(result, spec, out, created):
    """One outcome for rows the model refused: all of them is an error (InputError naming the first
    reason; a folder this run made is removed), some of them a warning."""
    failed = result.refused
    if not failed:
        return
    first = result.first_refusal[1]
    if failed == len(result):
        if created:
            shutil.rmtree(out, ignore_errors=True)
        raise InputError(spec.source, "vary", f"configurations the model accepts; all {failed} were refused, "
                                              f"the first: {first}")
    warn(f"{spec.source}: {failed} of {len(result)} configurations were refused by the model (see the error "
         f"column of {Path(out) / 'results.csv'}), the first: {first}")


def run_sweep(spec: "SweepSpec | str | os.PathLike", out: "str | os.PathLike", workers: int | None = None,
              scheduler: "str | DaskClient | None" = None,
              progress: "Callable[[int], object] | None" = None, restart: bool = False) -> SweepResult:
    """Evaluate every configuration of a design sweep into a folder (``bm.sweep``).

    Each configuration (a grid or a sample of the varied keys) is built and its weave and capsize
    speeds and stable range found; chunks of configurations run in this process or on Dask, each
    chunk written as it finishes, so an interrupted sweep resumes where it stopped, and no process
    holds a row per configuration (docs/sweep.md).

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
        A local Dask cluster of that many single-threaded worker processes (a sweep that would
        take less here than starting them runs in this process: the result's ``notes`` say so).
    scheduler : str or distributed.Client, optional
        The address of a running Dask scheduler, or a ``distributed.Client`` (used as it is and
        left open: a notebook's cluster serves many sweeps). Neither ``workers`` nor
        ``scheduler``: this process.
    progress : callable, optional
        Called with the number of configurations already finished, then with the number
        finished by each chunk.
    restart : bool
        Start over in a folder holding a sweep (its record, chunks and tables removed) instead of
        resuming it.  A resume needs the same spec, input files of the same content and the same
        bikemass (``sweep.json`` records each file's SHA-256, bikemass's version and a digest of
        its code); anything else is refused unless ``restart``.

    Returns
    -------
    SweepResult
        A sequence of one row (dict) per configuration, read back from the chunk files on demand:
        the varied values, ``weave_speed``, ``capsize_speed``, ``stable_from``, ``stable_to``
        (m/s, ``None`` where there is none), ``total_mass`` (kg) and ``error`` (why the model
        refused it, else ``None``); ``column(name)`` gives a column as an array.

    Raises
    ------
    InputError
        Bad arguments or spec (naming its file and key); ``out`` a file, or a folder holding other
        files than a sweep's own, another spec's sweep, one computed from input files that changed
        since or by another bikemass (without ``restart``), or a damaged ``sweep.json``; a scheduler that
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
    if not isinstance(restart, bool):
        raise wrong_type("restart", restart, "True or False")
    if not hasattr(spec, "configurations"):
        spec = read_spec(spec)
    spec = cast(SweepSpec, spec)                   # a SweepSpec from here on (for the type checker)
    check_keys(spec)
    created = not Path(out).exists() or not holds_files(out)
    record = _check_folder(spec, out, restart)
    spec = dataclasses.replace(spec, inputs=hashlib.sha256(json.dumps(record["inputs"]).encode()).hexdigest())
    gather = _Gathering(spec, progress)
    if scheduler is None and workers is not None:
        gather.out = _prepare(record, out)
        workers = gather.small_enough_here(workers)
    with _engine(workers, scheduler) as (run, slots):       # a cluster that cannot be reached leaves no folder
        if gather.out is None:
            gather.out = _prepare(record, out)
            gather.start()
        size = chunk_size(gather.missing_count(), slots, spec.chunk, cheap=takes(spec.keys))
        gather.collect(run(spec, [Chunk(a, b) for a, b in split(gather.missing(), size)], slots))
    write_tables(gather.out, spec, gather.kept)
    result = SweepResult(gather.out, spec, tuple(gather.kept), tuple(gather.notes))
    _outcome(result, spec, gather.out, created)
    return result


class _Gathering:
    """The gathering process's state of a running sweep: the chunks on disk (index ranges and
    refusal counts only), the progress callback and the notes of the run."""

    def __init__(self, spec, progress):
        self.spec, self.progress, self.out, self.kept, self.notes = spec, progress, None, [], []

    def start(self):
        self.kept = kept_chunks(self.out, self.spec)
        if self.progress:
            self.progress(sum(k.size for k in self.kept))

    def missing(self):
        return missing_ranges(self.kept, self.spec.count)

    def missing_count(self):
        return sum(b - a for a, b in self.missing())

    def add(self, finished):
        chunk = finished.chunk
        write_atomic(chunk_path(self.out, chunk.start, chunk.stop), finished.text)
        self.kept.append(Kept(chunk.start, chunk.stop, finished.refused, finished.first_refusal))
        self.kept.sort(key=lambda k: k.start)
        if self.progress:
            self.progress(chunk.size)

    def collect(self, finished_chunks):
        for finished in finished_chunks:
            self.add(finished)

    def small_enough_here(self, workers):
        """``workers``, or ``None`` (this process) when the rest of the sweep would take less here
        than :data:`WORKER_START`, judged by the first missing chunk computed here."""
        self.start()
        missing = self.missing()
        if not missing:
            return None
        try:                                          # the files read before the clock starts
            _scenario(self.spec.scenario(), self.spec.inputs).parameters()
        except (InputError, ValueError):
            pass                                      # every row says why
        size = chunk_size(self.missing_count(), None, self.spec.chunk, cheap=takes(self.spec.keys))
        step = size if self.spec.chunk else max(1, -(-size // PROBE_STEPS))
        done, seconds, began = [], [], time.perf_counter()
        while missing and sum(done) < size and (not seconds or time.perf_counter() - began < PROBE_SECONDS):
            chunk, start = Chunk(*split(missing, step)[0]), time.perf_counter()
            self.add(finish_chunk(self.spec, chunk))
            done.append(chunk.size)
            seconds.append(time.perf_counter() - start)
            missing = self.missing()
        if not missing:
            return None
        warm = slice(1, None) if len(done) > 1 else slice(None)      # the first chunk pays the caches' warm-up
        rest = sum(seconds[warm]) / sum(done[warm]) * self.missing_count()
        if rest >= WORKER_START:
            return workers
        self.notes.append(f"ran in this process, not on {workers} worker{'s' * (workers > 1)}: the rest of these "
                          f"{self.spec.count} configurations took about {rest:.2g} s here, less than starting "
                          f"the workers (about {WORKER_START:g} s)")
        return None


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


def _in_process(spec, chunks, slots):
    return (finish_chunk(spec, chunk) for chunk in chunks)


@contextmanager
def _engine(workers, scheduler):
    """``(run, slots)``: ``run(spec, chunks, slots)`` yields a :class:`~bikemass.sweep.evaluate.Finished`
    per chunk as chunks finish; ``slots`` = worker threads (``None`` in this process)."""
    if workers is None and scheduler is None:
        yield _in_process, None
        return
    distributed = require("distributed")
    with _client(distributed, workers, scheduler) as client:
        def run(spec, chunks, slots):
            pending, submitted, window = list(reversed(chunks)), [], max(1, IN_FLIGHT * (slots or 1))

            def submit(queue):
                chunk = pending.pop()
                future = client.submit(finish_chunk_pickled, spec, chunk, pure=False)
                submitted.append(future)
                queue.add(future)
            queue = distributed.as_completed(loop=client.loop)
            for _ in range(min(window, len(pending))):
                submit(queue)
            try:
                for future in queue:
                    finished = pickle.loads(future.result())
                    submitted.remove(future)
                    if pending:
                        submit(queue)
                    yield finished
            finally:
                if submitted:                    # interrupted: leave no work behind on a shared cluster
                    client.cancel(submitted)
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
            scheme = distributed.comm.parse_address(scheduler)[0]
            if scheme not in SCHEMES:
                raise ValueError(f"an address tcp://HOST:PORT, ws:// or wss://; {scheme}:// needs more than an "
                                 "address: connect a distributed.Client yourself and pass it to bm.sweep")
            distributed.comm.resolve_address(scheduler)      # a malformed address: one line, no Client made
            client = _connected(distributed, scheduler)
        except Exception as exc:                  # whatever distributed raises while connecting: no scheduler
            raise InputError("--scheduler", scheduler, f"a running Dask scheduler ({one_line(exc, 300)})") from None
        with client:
            yield client
        return
    with local_cluster(workers) as cluster, distributed.Client(cluster, set_as_default=False) as client:
        yield client


SCHEMES = ("tcp", "ws", "wss")
"""The schemes a scheduler address may have: the ones a client reaches with an address alone."""
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


WARM = "bikemass.sweep.evaluate"
"""Imported by every worker of ``--workers N`` as it starts (Dask's ``preload``): the first task
finds bikemass, numpy and scipy loaded.  For a cluster of your own: ``dask worker ADDRESS
--preload bikemass.sweep.evaluate``."""


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
                                        host="127.0.0.1", dashboard_address="127.0.0.1:0", silence_logs=40,
                                        preload=[WARM])


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
