"""BLAS on one thread inside the FE solves, the study and the sweep, and the previous limit back afterwards.

Every test first sets the BLAS pools to 2 threads itself (scoped), so "limited to one" and
"restored" are observable on any machine, whatever its core count or OPENBLAS_NUM_THREADS
(where no resizable BLAS is loaded there is nothing to observe and the tests skip).
"""

import threading
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest
import scipy.sparse.linalg  # noqa: F401  (scipy's BLAS loaded before the fixture looks)
from threadpoolctl import threadpool_info, threadpool_limits

from bikemass.fe import frame_modes
from bikemass.fe import modes as fe_modes
from bikemass.study import pipeline
from bikemass.study.parallel import executor
from bikemass.sweep import evaluate as sweep_evaluate
from bikemass.sweep.table import NUMBERS
from bikemass.core.threads import one_blas_thread
from thesis_frames import jamis_structure

OUTSIDE = 2


def blas_threads():
    """Thread count of every loaded BLAS library (one entry each)."""
    return [pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas"]


@pytest.fixture(autouse=True)
def two_threads():
    if not blas_threads():
        pytest.skip("no BLAS library that threadpoolctl can resize is loaded (e.g. Apple Accelerate)")
    with threadpool_limits(OUTSIDE, user_api="blas"):
        assert set(blas_threads()) == {OUTSIDE}
        yield
        assert set(blas_threads()) == {OUTSIDE}, "the global BLAS limit was not restored"


def test_the_block_runs_on_one_thread_and_restores_the_limit():
    with one_blas_thread():
        assert set(blas_threads()) == {1}
    assert set(blas_threads()) == {OUTSIDE}


def test_nested_and_failing_blocks_restore_only_at_the_outermost_exit():
    with pytest.raises(ZeroDivisionError):
        with one_blas_thread():
            with one_blas_thread():
                pass
            assert set(blas_threads()) == {1}, "an inner block restored the limit too early"
            1 / 0
    assert set(blas_threads()) == {OUTSIDE}


@pytest.mark.parametrize("main_leaves_first", [False, True])
def test_overlapping_blocks_in_two_threads_leave_the_limit_as_it_was(main_leaves_first):
    entered, leave, left = threading.Event(), threading.Event(), threading.Event()

    def other():
        with one_blas_thread():
            entered.set()
            leave.wait(10)
        left.set()

    worker = threading.Thread(target=other)
    with one_blas_thread():
        worker.start()
        assert entered.wait(10)
        assert set(blas_threads()) == {1}
        if not main_leaves_first:
            leave.set()
            assert left.wait(10)
            assert set(blas_threads()) == {1}, "the other thread's exit undid this thread's limit"
    leave.set()
    worker.join(10)
    assert set(blas_threads()) == {OUTSIDE}


def test_frame_modes_solve_inside_the_limit(monkeypatch):
    seen = []
    solve = fe_modes._lowest

    def observed(*args, **kwargs):
        seen.append(blas_threads())
        return solve(*args, **kwargs)

    monkeypatch.setattr(fe_modes, "_lowest", observed)
    modes = frame_modes(jamis_structure(), "fix-rear", 3)
    assert len(modes.frequencies_hz) == 3 and seen and all(set(s) == {1} for s in seen)
    with pytest.raises(ValueError, match="modes asked"):      # a refused solve restores the limit too
        frame_modes(jamis_structure(), "fix-rear", 10 ** 6, element_size=None)


def _worker_blas_threads():
    return blas_threads()


def test_workers_forked_inside_the_limit_inherit_it():
    with one_blas_thread():
        with executor(2) as pool:
            observed = [pool.submit(_worker_blas_threads).result() for _ in range(2)]
    assert all(set(s) == {1} for s in observed)


class _Stop(Exception):
    pass


def test_the_study_starts_its_workers_inside_the_limit(monkeypatch):
    seen = []

    def recording_executor(workers):
        seen.append(blas_threads())
        raise _Stop

    monkeypatch.setattr(pipeline, "_INPUTS", pipeline._INPUTS)        # compute sets it: restored after
    monkeypatch.setattr(pipeline, "_preload", lambda inputs: None)
    monkeypatch.setattr(pipeline, "figure_jobs", lambda *args: [])
    monkeypatch.setattr(pipeline, "executor", recording_executor)
    with pytest.raises(_Stop):
        pipeline.compute(workers=2)
    with pytest.raises(_Stop):
        pipeline.draw(SimpleNamespace(), Path("unused"), workers=2)
    assert len(seen) == 2 and all(set(s) == {1} for s in seen)


def test_sweep_chunks_are_evaluated_inside_the_limit(monkeypatch, tmp_path):
    from bikemass.sweep.spec import read_spec
    from bikemass.sweep.table import Outcomes
    seen = []

    def outcomes(model, spec, columns, count):
        seen.append(blas_threads())
        return Outcomes({k: np.full(count, np.nan) for k in NUMBERS}, [None] * count)
    monkeypatch.setattr(sweep_evaluate, "_scenario", lambda scenario, inputs=None: None)
    monkeypatch.setattr(sweep_evaluate, "evaluate_outcomes", outcomes)
    (tmp_path / "s.yaml").write_text("bike: benchmark\nvary: {c: [0.07, 0.08]}\n")
    finished = sweep_evaluate.finish_chunk(read_spec(str(tmp_path / "s.yaml")), sweep_evaluate.Chunk(0, 2))
    assert finished.text.count("\n") == 2 and len(seen) == 1 and set(seen[0]) == {1}
