"""Running the hostile corpus (cases.yaml) in-process through ``bikemass.cli.main``.

:func:`run_case` prepares a case's folder, runs the command with stdout and stderr
captured and a time limit, and returns an :class:`Outcome`; :func:`problems` lists
what is wrong with it (empty = the case keeps its promise).
"""

import contextlib
import io
import os
import signal
import time
import traceback
from dataclasses import dataclass
from pathlib import Path

import yaml

from . import generators

CASES_FILE = Path(__file__).with_name("cases.yaml")
TIME_LIMIT = 60
"""Seconds after which a case counts as hung (the slowest refusal takes well under one)."""


def load_cases():
    return yaml.safe_load(CASES_FILE.read_text())


@dataclass
class Outcome:
    status: object
    stdout: str
    stderr: str
    seconds: float
    crash: str = ""
    """The traceback of an exception that escaped ``main`` ("" if none)."""
    hung: bool = False


class _Hung(BaseException):
    pass


def _alarm(signum, frame):
    raise _Hung()


def _make(folder, spec):
    if spec is None:
        return None
    if "text" in spec:
        path = folder / "in.yaml"
        path.write_text(spec["text"])
        return path
    if "from" in spec:                     # "as": the copy's file name where its suffix matters (.txt)
        return generators.from_shipped(folder, spec, spec.get("as", "in.yaml"))
    return getattr(generators, spec["make"])(folder, spec)


def prepare(case, folder):
    """Write the case's input into ``folder``; return the substitutions for argv and message."""
    folder = Path(folder)
    path = _make(folder, case.get("input"))
    return {"{in}": str(path or folder / "in.yaml"), "{dir}": str(folder), "{base}": str(folder / "base.yaml")}


def substitute(text, values):
    for key, value in values.items():
        text = text.replace(key, value)
    return text


def run(argv, env=None):
    """``bikemass.cli.main(argv)`` with stdout and stderr captured and a time limit."""
    from bikemass.cli.main import main
    out, err = io.StringIO(), io.StringIO()
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(TIME_LIMIT)
    start = time.perf_counter()
    crash, hung, status = "", False, None
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), _env(env or {}):
            status = main(argv)
    except _Hung:
        hung = True
    except BaseException:                      # noqa: BLE001 - a crash is what we count
        crash = traceback.format_exc()
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    return Outcome(status, out.getvalue(), err.getvalue(), time.perf_counter() - start, crash, hung)


@contextlib.contextmanager
def _env(changes):
    saved = {k: os.environ.get(k) for k in changes}
    os.environ.update(changes)
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


def problems(case, outcome, values, before, after):
    """What is wrong with ``outcome`` of ``case`` (folder listings ``before``/``after`` the run)."""
    found = []
    if outcome.hung:
        return [f"hung (over {TIME_LIMIT} s)"]
    if outcome.crash:
        return ["exception escaped main: " + outcome.crash.strip().splitlines()[-1]]
    if "Traceback" in outcome.stderr or "internal error" in outcome.stderr:
        found.append("traceback or internal error on stderr")
    if outcome.status != case["exit"]:
        found.append(f"exit {outcome.status}, expected {case['exit']}")
    message = substitute(case["message"], values)
    if message not in outcome.stderr:
        found.append(f"{message!r} not in stderr")
    lines = outcome.stderr.splitlines()
    if case["exit"] == 2:
        if len(lines) != 1:
            found.append(f"{len(lines)} stderr lines, expected one")
        if after != before:
            found.append(f"files left behind: {sorted(set(after) - set(before))}")
    elif any(not line.startswith("bikemass: warning: ") for line in lines):
        found.append("a stderr line that is not a warning")
    if "stdout" in case and case["stdout"] not in outcome.stdout:
        found.append(f"{case['stdout']!r} not in stdout")
    return found


def listing(folder):
    return sorted(str(p.relative_to(folder)) for p in Path(folder).rglob("*"))


def check(case, folder):
    """Run ``case`` in the empty ``folder``; return (Outcome, list of problems)."""
    folder = Path(folder)
    values = prepare(case, folder)
    before = listing(folder)
    outcome = run([substitute(a, values) for a in case["argv"]], case.get("env"))
    return outcome, problems(case, outcome, values, before, listing(folder))
