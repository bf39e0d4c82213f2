"""A sweep streamed to disk: configurations made from index ranges, chunk files as the state,
rows read back on demand, the in-process rule for small sweeps offered workers."""

import csv
import itertools

import numpy as np
import pytest

from bikemass.sweep import read_spec, run_sweep
from bikemass.sweep.layout import chunk_path

GRID = """bike: benchmark
vary:
  c: {from: 0.04, to: 0.12, num: 4}
  lam: [0.25, 0.314159265358979, 0.4]
  stiffness: [infinite, "FRAME"]
chunk: 5
"""
FRAME = "S: [[20000.0, 1500.0], [1500.0, 6000.0]]\n"     # N m/rad


def _spec(tmp_path, text, name="spec.yaml"):
    (tmp_path / "frame.yaml").write_text(FRAME)
    path = tmp_path / name
    path.write_text(text.replace("FRAME", str(tmp_path / "frame.yaml")))
    return str(path)


def test_index_ranges_give_the_grid_in_its_order(tmp_path):
    """Any range of a grid's configurations equals that slice of the product of its values (the
    last key fastest), and a sample's ranges the slices of its drawn points."""
    spec = read_spec(_spec(tmp_path, GRID))
    product = [dict(zip(spec.keys, combo)) for combo in itertools.product(*(v.grid() for v in spec.variables))]
    assert spec.count == len(product) == 24
    for start, stop in ((0, 24), (3, 17), (23, 24), (5, 5)):
        columns = spec.columns(start, stop)
        assert [dict(zip(spec.keys, row)) for row in zip(*(columns[k] for k in spec.keys))] == product[start:stop]
    sample = read_spec(_spec(tmp_path, "bike: benchmark\nvary:\n  c: {from: 0.0, to: 0.2}\n  lam: {from: 0.2, to: 0.4}\n"
                                       "sample: {method: lhs, n: 9, seed: 3}\n", "s.yaml"))
    rows = sample.configurations()
    assert sample.columns(2, 7) == {k: [r[k] for r in rows[2:7]] for k in sample.keys}


def test_rows_read_back_from_disk_equal_the_table(tmp_path):
    """The returned rows (read from the chunk files) equal results.csv read independently by the
    csv module, by index, negative index, slice, iteration and column."""
    out = tmp_path / "o"
    rows = run_sweep(_spec(tmp_path, GRID), out)
    with open(out / "results.csv", newline="") as fh:
        table = list(csv.DictReader(fh))
    assert len(rows) == len(table) == 24
    for got, line in zip(rows, table):
        for key, cell in line.items():
            expected = (None if cell == "" else cell) if key in ("stiffness", "error") else \
                (None if cell == "" else float(cell))
            assert got[key] == expected, key
    assert rows[-1] == rows[23] and rows[3:6] == [rows[3], rows[4], rows[5]]
    with pytest.raises(IndexError):
        rows[24]
    weave = rows.column("weave_speed")
    assert isinstance(weave, np.ndarray) and weave[7] == rows[7]["weave_speed"]
    assert rows.column("stiffness")[:2] == ["infinite", str(tmp_path / "frame.yaml")]
    assert rows == list(rows) and rows.refused == 0 and rows.notes == ()


def test_an_overlapping_chunk_of_another_size_is_not_counted_twice(tmp_path):
    """Chunk files of two chunk sizes over the same rows (an interrupted run resumed with another
    size): each configuration is in the table once."""
    out = tmp_path / "o"
    run_sweep(_spec(tmp_path, GRID), out)
    chunk_path(out, 0, 5).rename(chunk_path(out, 0, 5).with_name("keep"))
    run_sweep(read_spec(_spec(tmp_path, GRID.replace("chunk: 5", "chunk: 3"), "three.yaml")), out)
    chunk_path(out, 0, 5).with_name("keep").rename(chunk_path(out, 0, 5))   # now 0-5 and 0-3, 3-6 overlap
    (out / "results.csv").unlink()
    again = run_sweep(_spec(tmp_path, GRID), out)
    assert len(again) == 24 and (out / "results.csv").read_text().count("\n") == 25


def test_a_small_sweep_offered_workers_runs_here_and_says_why(tmp_path, monkeypatch):
    """Workers offered for a sweep of a fraction of a second: no cluster is started (starting one
    is refused here, so a start would fail the test), the rows are those of a run in this
    process, and a note says why."""
    from bikemass.sweep import run as sweep_run
    monkeypatch.setattr(sweep_run, "_client", lambda *a: pytest.fail("a cluster was started"))
    here = list(run_sweep(_spec(tmp_path, GRID), tmp_path / "here"))
    offered = run_sweep(_spec(tmp_path, GRID), tmp_path / "offered", workers=2)
    assert list(offered) == here
    assert len(offered.notes) == 1 and "ran in this process, not on 2 workers" in offered.notes[0]
    assert (tmp_path / "offered" / "results.csv").read_bytes() == (tmp_path / "here" / "results.csv").read_bytes()


def test_a_sweep_that_would_take_long_here_goes_to_the_workers(tmp_path, monkeypatch):
    """The same sweep judged too long for this process (its start-up cost set to 0 s) is handed
    to the workers after its first chunk."""
    from bikemass.sweep import run as sweep_run
    monkeypatch.setattr(sweep_run, "WORKER_START", 0.0)
    started = []
    monkeypatch.setattr(sweep_run, "_engine", _recording_engine(started))
    rows = run_sweep(_spec(tmp_path, GRID), tmp_path / "o", workers=2)
    assert started == [2] and rows.notes == () and len(rows) == 24


def _recording_engine(started):
    from contextlib import contextmanager

    from bikemass.sweep.run import _in_process

    @contextmanager
    def engine(workers, scheduler):
        started.append(workers)
        yield _in_process, None
    return engine


def test_a_sweep_without_figures_never_loads_matplotlib(tmp_path):
    """Issue 26: matplotlib only when asked (its import is about a second of a small sweep)."""
    import subprocess
    import sys
    spec = tmp_path / "c.yaml"
    spec.write_text("{bike: benchmark, vary: {c: [0.04, 0.08]}}")
    code = ("import sys; from bikemass.cli.main import main; "
            f"status = main(['sweep', {str(spec)!r}, '--out', {str(tmp_path / 'out')!r}, '--quiet', '--no-figures']); "
            "print(status, 'matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split()[-2:] == ["0", "False"]


def test_a_figure_format_given_is_checked_even_without_figures(tmp_path, capsys):
    """--no-figures skips the default format's check (and matplotlib), never a format the user gave."""
    from bikemass.cli.main import main
    spec = tmp_path / "c.yaml"
    spec.write_text("{bike: benchmark, vary: {c: [0.04, 0.08]}}")
    assert main(["sweep", str(spec), "--out", str(tmp_path / "out"), "--plot-format", "xyz", "--no-figures"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and ".png" in err and not (tmp_path / "out").exists()     # one line naming the formats
