"""Every code block of README.md and docs/*.md runs, and what it prints is what the page shows.

The rule (docs/api.md, "How the pages are tested") by the block's info string:

* ``python``: executed in page order in one namespace per page, in a scratch folder; what
  it prints must match the ``output`` block that follows it (a block that prints needs one);
* ``console``: each ``$ bikemass ...`` line runs the command line in that folder; the lines
  up to the next ``$`` are its stdout and stderr; a line ``...`` stands for any lines;
  exit status 0 unless the expected output holds ``bikemass: error:``;
* ``shell``: each line is a ``bikemass`` command (``#`` comments allowed) that must exit with
  status 0; its output is not shown, so not compared;
* ``yaml``, ``json``: must parse; after ``<!-- file: NAME -->`` the block is saved as NAME
  in the scratch folder for later blocks;
* ``text``: not code (synopses, layouts, tables shown for reading) and not run;
* any block after ``<!-- no-run: REASON -->`` is skipped (the reason is required), e.g. the
  install lines or a run that takes minutes;
* a block without an info string fails the test.

Numbers are compared numerically: each printed number must equal the shown one to one unit
in its last shown digit or to :data:`RELATIVE` of its value, whichever is larger (data
written in full, 17 significant digits, differs in its last digits between CPUs, BLAS
kernels and thread counts: up to 5e-13 relative measured, docs/cli.md "Numbers"), and two
numbers below :data:`bikemass.core.output.ZERO` are equal (both zero in exact arithmetic); the
text around numbers must match word for word.
"""

import contextlib
import io
import json
import re
import shlex
from pathlib import Path

import pytest
import yaml

from bikemass.cli.main import main
from bikemass.core.output import ZERO
from printed import NUMBER

ROOT = Path(__file__).parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"^```(.*)$")
MARKER = re.compile(r"^<!--\s*(file|no-run):\s*(.*?)\s*-->$")


def blocks(text):
    """``[(line number, info, code, marker)]``: every fenced block and the marker line before it."""
    out, lines, i = [], text.splitlines(), 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        start, info = i, m.group(1).strip()
        j = i + 1
        while j < len(lines) and lines[j].rstrip() != "```":
            j += 1
        before = next((lines[k].strip() for k in range(start - 1, -1, -1) if lines[k].strip()), "")
        marker = MARKER.match(before)
        out.append((start + 1, info, "\n".join(lines[i + 1:j]) + "\n", marker.groups() if marker else None))
        i = j + 1
    return out


RELATIVE = 1e-9
"""Relative tolerance of a number shown with more digits than are machine-independent."""


def _tolerance(token):
    """One unit in the last shown digit of a printed number, at least RELATIVE of its value."""
    mantissa, _, exponent = token.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return max(10.0 ** (-decimals + (int(exponent) if exponent else 0)), RELATIVE * abs(float(token)))


def same_number(shown, got):
    """The printed token ``got`` equals the shown token ``shown`` (see the module docstring)."""
    x, y = float(shown), float(got)
    if abs(x) < ZERO and abs(y) < ZERO:
        return True
    return abs(x - y) <= _tolerance(shown) * (1 + 1e-9)


def same_line(shown, got):
    """Text equal word for word (whitespace runs collapsed), numbers equal to the shown digits."""
    a, b = NUMBER.split(shown), NUMBER.split(got)
    if [" ".join(t.split()) for t in a] != [" ".join(t.split()) for t in b]:
        return False
    return all(same_number(x, y) for x, y in zip(NUMBER.findall(shown), NUMBER.findall(got)))


def matches(shown, got):
    """``got`` lines against ``shown`` lines, where a ``...`` line stands for any lines."""
    shown = [l for l in shown if l.strip()]
    got = [l for l in got if l.strip()]
    if not shown:
        return not got
    if shown[0].strip() == "...":
        return any(matches(shown[1:], got[k:]) for k in range(len(got) + 1))
    return bool(got) and same_line(shown[0], got[0]) and matches(shown[1:], got[1:])


def run_console(code, where):
    """Run each ``$ bikemass`` line of a console block and compare its output."""
    commands = re.split(r"^\$ ", code, flags=re.M)[1:]
    assert commands, f"{where}: a console block holds '$ bikemass ...' lines"
    for chunk in commands:
        command, _, shown = chunk.partition("\n")
        argv = shlex.split(command, comments=True)
        assert argv[0] == "bikemass", f"{where}: only bikemass commands run here; mark it no-run: {command}"
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer), contextlib.redirect_stderr(buffer):
            try:
                status = main(argv[1:])
            except SystemExit as exc:                    # --help
                status = exc.code
        error = "bikemass: error:" in shown
        assert (status != 0) == error, f"{where}: `{command}` exited {status}:\n{buffer.getvalue()}"
        got = buffer.getvalue().splitlines()
        assert matches(shown.splitlines(), got), f"{where}: `{command}` printed\n{buffer.getvalue()}"


def run_shell(code, where):
    """Run each ``bikemass`` line of a shell block; each must succeed."""
    for command in code.splitlines():
        argv = shlex.split(command, comments=True)
        if not argv:
            continue
        assert argv[0] == "bikemass", f"{where}: only bikemass commands run here; mark it no-run: {command}"
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer), contextlib.redirect_stderr(buffer):
            status = main(argv[1:])
        assert status == 0, f"{where}: `{command}` exited {status}:\n{buffer.getvalue()}"


def run_page(page, folder):
    namespace = {"__name__": "__docs__"}
    found = blocks(page.read_text())
    for k, (line, info, code, marker) in enumerate(found):
        where = f"{page.relative_to(ROOT)}:{line}"
        if marker and marker[0] == "no-run":
            assert marker[1], f"{where}: no-run needs a reason"
            continue
        if info == "python":
            buffer = io.StringIO()
            with contextlib.redirect_stdout(buffer):
                exec(compile(code, where, "exec"), namespace)
            following = found[k + 1] if k + 1 < len(found) else None
            if following and following[1] == "output":
                assert matches(following[2].splitlines(), buffer.getvalue().splitlines()), \
                    f"{where} printed\n{buffer.getvalue()}"
            else:
                assert not buffer.getvalue(), f"{where} prints, so an output block follows it:\n{buffer.getvalue()}"
        elif info == "console":
            run_console(code, where)
        elif info == "shell":
            run_shell(code, where)
        elif info in ("yaml", "json"):
            (yaml.safe_load if info == "yaml" else json.loads)(code)
            if marker and marker[0] == "file":
                (folder / marker[1]).write_text(code)
        elif info in ("text", "output"):
            continue
        else:
            pytest.fail(f"{where}: a code block needs an info string: python, console, shell, yaml, json, "
                        f"text or output (got {info!r}); see tests/test_docs.py")


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_page(page, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    run_page(page, tmp_path)


def test_the_comparison_is_numeric_and_strict():
    assert same_line("weave 5.7146 m/s", "weave  5.71462884 m/s")
    assert not same_line("weave 5.7146 m/s", "weave 5.7148 m/s")
    assert not same_line("weave 5.7146 m/s", "capsize 5.7146 m/s")
    assert same_line("1.2e-05", "1.24e-05") and not same_line("1.2e-05", "1.4e-05")
    assert same_line("-1.2362 m", "-1.2363 m")                   # a rounding tie, either way
    assert same_line("1237.0287956450948", "1237.028795644554")  # full digits: 1e-9 relative
    assert not same_line("1237.0287956450948", "1237.028805")
    assert same_line("gap 2.2e-16 m", "gap 0.0e+00 m")           # both zero in exact arithmetic
    assert not same_line("gap 2.2e-12 m", "gap 0.0e+00 m")
    assert matches(["a 1", "...", "c 3"], ["a 1", "b", "b", "c 3.0"])
    assert not matches(["a 1", "c 3"], ["a 1", "b", "c 3"])
