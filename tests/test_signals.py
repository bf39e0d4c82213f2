"""Stopping a running study: SIGTERM and SIGINT end it with one line and exit 143 / 130, its
worker processes go with it, and neither a partial output folder nor a temporary one is left."""

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
pytestmark = pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="needs Linux /proc")


def _children(pid):
    """Process ids of the direct children of ``pid`` (from /proc)."""
    found = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        try:
            found += [int(x) for x in (task / "children").read_text().split()]
        except OSError:
            pass
    return found


def _alive(pid):
    try:
        return Path(f"/proc/{pid}/stat").read_text().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


@pytest.mark.slow     # starts a study in a subprocess and stops it (~5 s each)
@pytest.mark.parametrize("signum, status, word", [(signal.SIGTERM, 143, "terminated"),
                                                  (signal.SIGINT, 130, "interrupted")])
def test_stopping_a_study(tmp_path, signum, status, word):
    out = tmp_path / "study"
    env = {**os.environ, "PYTHONPATH": f"{SRC}{os.pathsep}{os.environ.get('PYTHONPATH', '')}"}
    proc = subprocess.Popen([sys.executable, "-m", "bikemass.cli.main", "study", "--out", str(out), "--no-figures",
                             "--jobs", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    workers = []
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        workers = _children(proc.pid)
        if workers and any(tmp_path.glob(".study.*.tmp")):
            break
        time.sleep(0.05)
    if proc.poll() is not None:
        pytest.skip("the study finished before it could be interrupted")
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == status
    assert err.strip().splitlines()[-1] == f"bikemass: error: {word}" and "Traceback" not in err
    time.sleep(0.5)
    assert not [w for w in workers if _alive(w)], "worker processes outlived the study"
    assert sorted(p.name for p in tmp_path.iterdir()) == [], "a partial or temporary folder was left"
