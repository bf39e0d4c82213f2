"""The command line runs BLAS on one thread unless the environment sizes it (bikemass's linear algebra is
small; a second thread only spins): checked in fresh processes through threadpoolctl's own report."""

import json
import os
import subprocess
import sys

import pytest

PROBE = ("import json, sys; from bikemass.cli.main import main; main(['params', 'benchmark', '--format', 'json']); "
         "from threadpoolctl import threadpool_info; "
         "print(json.dumps([p['num_threads'] for p in threadpool_info() if p['user_api'] == 'blas']), file=sys.stderr)")


def _blas_threads(env):
    done = subprocess.run([sys.executable, "-c", PROBE], capture_output=True, text=True, timeout=120,
                          env={k: v for k, v in {**os.environ, **env}.items() if v is not None})
    assert done.returncode == 0, done.stderr
    return json.loads(done.stderr.strip().splitlines()[-1])


@pytest.mark.parametrize("given, expected", [(None, 1), ("2", 2)])
def test_a_command_sizes_blas_to_one_thread_unless_told(given, expected):
    env = {name: None for name in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")}
    if given is not None:
        env["OPENBLAS_NUM_THREADS"] = env["OMP_NUM_THREADS"] = env["MKL_NUM_THREADS"] = given
    threads = _blas_threads(env)
    assert threads and all(n == expected for n in threads)
