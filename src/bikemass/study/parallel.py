"""Work spread over processes: a forked process pool where the platform has ``fork``, else inline.

Forked workers inherit everything loaded before the pool starts (modules, the
study's cached inputs), so a job costs only its own computation and the pickling
of its result.  Workers ignore SIGINT (the parent handles Ctrl-C); if the block
using the pool ends with an exception (an error, Ctrl-C, SIGTERM turned into an
exception by the command line), the workers are terminated at once rather than
left running, and the pool is joined so no process outlives the call.  Stop
signals are held back while the workers are forked and while they are shut down.
"""

import multiprocessing
from concurrent.futures import Future

from ..core.stopping import deferred, worker_signals


class InlineExecutor:
    """The executor interface run in this process: ``submit`` computes at once."""

    def submit(self, fn, *args):
        future = Future()
        future.set_result(fn(*args))
        return future

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False


class _Pending:
    """A submitted job: ``result()`` waits for it (and re-raises its exception)."""

    def __init__(self, async_result):
        self._async = async_result

    def result(self):
        return self._async.get()


class PoolExecutor:
    """``submit(fn, *args).result()`` on a forked :class:`multiprocessing.pool.Pool`; the workers
    are closed and joined on a normal exit, terminated and joined on an exception."""

    def __init__(self, workers):
        self.workers = workers
        self._pool = None

    def __enter__(self):
        context = multiprocessing.get_context("fork")
        with deferred():                 # never interrupt a fork half-way (locks would stay held)
            self._pool = context.Pool(self.workers, initializer=worker_signals)
        return self

    def submit(self, fn, *args):
        return _Pending(self._pool.apply_async(fn, args))

    def __exit__(self, kind, value, traceback):
        with deferred():
            if kind is None:
                self._pool.close()
            else:
                self._pool.terminate()
            self._pool.join()
        return False


def executor(workers):
    """A pool of ``workers`` forked processes, or :class:`InlineExecutor` for 1 worker or no fork."""
    if workers > 1 and "fork" in multiprocessing.get_all_start_methods():
        return PoolExecutor(workers)
    return InlineExecutor()
