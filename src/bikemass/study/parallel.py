"""Work spread over processes: a forked process pool where the platform has ``fork``, else inline.

Forked workers inherit everything loaded before the pool starts (modules, the
study's cached inputs), so a job costs only its own computation and the pickling
of its result.
"""

import multiprocessing
from concurrent.futures import Future, ProcessPoolExecutor


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


def executor(workers):
    """A pool of ``workers`` forked processes, or :class:`InlineExecutor` for 1 worker or no fork."""
    if workers > 1 and "fork" in multiprocessing.get_all_start_methods():
        return ProcessPoolExecutor(workers, mp_context=multiprocessing.get_context("fork"))
    return InlineExecutor()
