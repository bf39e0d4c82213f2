"""Stopping a command cleanly on SIGINT (Ctrl-C) and SIGTERM.

While :func:`stop_on_signals` is active, SIGINT raises ``KeyboardInterrupt`` and SIGTERM
raises :class:`Terminated` in the main thread, so every ``with`` block on the way out
cleans up (worker pools terminated, temporary files and folders removed).  Some
libraries swallow any exception raised while they import or call out (``except
BaseException``); so that a stop request is not lost there, the signal is sent again
every :data:`RETRY` seconds until the exception reaches the command line.

The handler runs in the main thread between any two bytecodes, so also while the main thread
is inside the handler itself (a second signal close behind the first): it never waits for a lock
(a non-reentrant lock taken twice by one thread never comes free), and a signal that arrives
while a stop is already on its way out (less than :data:`RETRY` seconds after it) raises nothing
more, so the first one's clean-up and its one line are not cut short.
"""

import contextlib
import os
import signal
import threading

RETRY = 1.0
"""Seconds between repeats of a stop signal that has not yet ended the command."""


class Terminated(BaseException):
    """SIGTERM received."""


class _Handler:
    def __init__(self):
        self.timer = None
        self.lock = threading.Lock()

    def __call__(self, signum, frame):
        # never blocks: if the lock is held, this thread holds it (a signal arrived inside this
        # handler, which is raising a stop already) or the timer thread does (it is about to send
        # the signal again); either way a stop is on its way, so this signal adds nothing
        if not self.lock.acquire(blocking=False):
            return
        try:
            if self.timer is not None:
                # a stop raised less than RETRY s ago is still on its way out (raising again would
                # interrupt its clean-up); if something swallowed it, the timer sends it again
                return
            self.timer = threading.Timer(RETRY, self._repeat, (signum,))
            self.timer.daemon = True
            self.timer.start()
        finally:
            self.lock.release()
        raise KeyboardInterrupt() if signum == signal.SIGINT else Terminated()

    def _repeat(self, signum):
        with self.lock:
            self.timer = None
        os.kill(os.getpid(), signum)

    def cancel(self):
        with self.lock:
            timer, self.timer = self.timer, None
        if timer is not None:
            timer.cancel()
            with contextlib.suppress(RuntimeError):    # a start cut short by a second signal
                timer.join()


@contextlib.contextmanager
def stop_on_signals():
    """SIGINT -> KeyboardInterrupt, SIGTERM -> :class:`Terminated` (repeated until they land);
    the previous handlers are restored on exit.  Does nothing outside the main thread."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    handler = _Handler()
    signals = (signal.SIGINT, signal.SIGTERM)
    previous = {s: signal.signal(s, handler) for s in signals}
    try:
        yield
    finally:
        for s in signals:
            signal.signal(s, signal.SIG_IGN)
        handler.cancel()
        for s, h in previous.items():
            signal.signal(s, h)


STOP_SIGNALS = {signal.SIGINT, signal.SIGTERM}


@contextlib.contextmanager
def deferred():
    """Hold SIGINT and SIGTERM back while the block runs (forking workers, cleaning up, renaming
    into place): they are delivered, and raise, right after it.  A no-op where the platform
    cannot block signals."""
    if not hasattr(signal, "pthread_sigmask"):
        yield
        return
    previous = signal.pthread_sigmask(signal.SIG_BLOCK, STOP_SIGNALS)
    try:
        yield
    finally:
        signal.pthread_sigmask(signal.SIG_SETMASK, previous)


def worker_signals():
    """For a forked worker process: ignore SIGINT (the parent decides), die on SIGTERM."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if hasattr(signal, "pthread_sigmask"):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, STOP_SIGNALS)
