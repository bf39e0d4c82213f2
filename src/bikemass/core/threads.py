"""BLAS on one thread for the duration of a small numerical job: ``with one_blas_thread(): ...``.

The FE mode solves and the study's jobs are small (a few thousand DOF at most) and run
beside other work; there a second OpenBLAS thread mostly spins, and on a busy 2-core
machine it stalls ARPACK several-fold at random (docs/fe.md, "Speed").  Inside the block every
BLAS (and OpenMP) thread pool loaded in the process runs one thread; on exit the
previous sizes come back, so the library never changes the process's settings for
good.  Processes forked inside the block (the study's workers) inherit the limit.

The pools are process-wide.  threadpoolctl (>= 3.8) lets one Python thread at a time
resize OpenBLAS's pool: in a second thread entering the block meanwhile the block
changes nothing (it runs on whatever size is set), and the sizes are still restored
once every block has exited.  Cost: ~0.04 ms per block (a cached controller; the scan
for loaded libraries is redone only after new modules are imported), plus up to a few
ms of slower BLAS calls just after the switch on a loaded machine: put the block around
a whole job (a mode solve, a study, a sweep chunk), not around each small call.  Works
as a decorator too: ``@one_blas_thread()``.
"""

import contextlib

from threadpoolctl import get_cached_controller


@contextlib.contextmanager
def one_blas_thread():
    """Run the block (or the decorated function) on one BLAS thread; the previous limits come back on exit."""
    with get_cached_controller().limit(limits=1):
        yield
