"""Issue 35: a resumed sweep never mixes two computations, and a sweep's folder survives what a
crash or a full disk leaves.

``sweep.json`` records every input file's SHA-256 and bikemass's version and code digest; a resume
after any of them changed is refused in one line naming what changed (exit 2), ``--restart``
starts over.  Every file a spec names is looked up next to the spec.  Zero-filled and CR LF chunk
files are computed again; an empty ``chunks/`` folder does not block a run.  One key of 10^8
values is made per chunk from its index range (its values equal ``numpy.linspace``'s).
"""

import json
import os
import subprocess
import sys
import tracemalloc
from pathlib import Path

import numpy as np
import pytest

import bikemass as bm
from bikemass.cli.main import main
from bikemass.sweep import read_spec, run_sweep
from bikemass.sweep import run as sweep_run
from bikemass.sweep.spec import Variable

ROOT = Path(__file__).parents[1]
SRC = ROOT / "src"
TYRES = "front: {cornering_coefficient: 11.46 1/rad, camber_coefficient: 0.573 1/rad, relaxation_length: 0.175 m}\n" \
        "rear:  {cornering_coefficient: 11.46 1/rad, camber_coefficient: 0.573 1/rad, relaxation_length: 0.175 m}\n"
FRAME = "S: [[20000.0, 1500.0], [1500.0, 6000.0]]\n"     # N m/rad


def one_line_error(capsys, argv):
    code = main([str(a) for a in argv])
    err = capsys.readouterr().err.strip()
    assert code == 2 and err.count("\n") == 0 and "Traceback" not in err, err
    return err


def folder(tmp_path):
    """A spec in ``tmp_path/spec/`` naming a bicycle, tyres and a stiffness file beside it."""
    here = tmp_path / "spec"
    here.mkdir()
    (here / "bike.yaml").write_text((ROOT / "frames" / "jamis.yaml").read_text())
    (here / "tyres.yaml").write_text(TYRES)
    (here / "frame.yaml").write_text(FRAME)
    (here / "body.yaml").write_text((ROOT / "bodies" / "thesis_rider.yaml").read_text())
    (here / "pose.yaml").write_text("body: body.yaml\nbike: jamis\nchain: {torso_lean: 30 deg, hands: hoods}\n")
    return here


@pytest.mark.parametrize("spec_text, changed, edit", [
    ("bike: bike.yaml\nvary:\n  c: [0.06, 0.08]\nchunk: 1\n", "bike.yaml",
     lambda t: t.replace("0.474 lb", "0.574 lb", 1)),
    ("bike: benchmark\nmodel: tyre\ntyres: tyres.yaml\nvary:\n  c: [0.06, 0.08]\nchunk: 1\n", "tyres.yaml",
     lambda t: t.replace("0.175 m}\nrear", "0.2 m}\nrear")),
    ("bike: benchmark\nstiffness: frame.yaml\nvary:\n  c: [0.06, 0.08]\nchunk: 1\n", "frame.yaml",
     lambda t: t.replace("20000.0", "10000.0")),
    ("bike: benchmark\nvary:\n  stiffness: [infinite, frame.yaml]\nchunk: 1\n", "frame.yaml",
     lambda t: t.replace("6000.0", "5000.0")),
    ("bike: jamis\nrider: pose.yaml\nvary:\n  c: [0.06, 0.08]\nchunk: 1\n", "pose.yaml",       # the rider's pose
     lambda t: t.replace("30 deg", "35 deg")),
    ("bike: jamis\nrider: pose.yaml\nvary:\n  c: [0.06, 0.08]\nchunk: 1\n", "body.yaml",       # a file the pose
     lambda t: t.replace("mass: 41.05", "mass: 45.05")),                                         # names (cached)
])
def test_a_resume_after_an_input_file_changed_is_refused_or_restarted(tmp_path, capsys, spec_text, changed, edit):
    here = folder(tmp_path)
    spec, out = here / "s.yaml", tmp_path / "out"
    spec.write_text(spec_text)
    os.chdir(tmp_path)                                  # every path of the spec is found next to the spec
    assert main(["sweep", str(spec), "--out", str(out), "--quiet", "--no-figures"]) == 0
    first = (out / "results.csv").read_text()
    record = json.loads((out / "sweep.json").read_text())
    assert str((here / changed).resolve()) in record["inputs"] and record["bikemass"]["version"] == bm.__version__
    (out / "chunks" / "000000001-000000002.csv").unlink()               # an interrupted run
    path = here / changed
    path.write_text(edit(path.read_text()))
    err = one_line_error(capsys, ["sweep", spec, "--out", out, "--quiet", "--no-figures"])
    assert f"{path.resolve()} changed since it was computed" in err and "--restart" in err
    assert main(["sweep", str(spec), "--out", str(out), "--quiet", "--no-figures", "--restart"]) == 0
    again = (out / "results.csv").read_text()
    assert again != first                               # every row from the new file, none from the old
    fresh = tmp_path / "fresh"
    assert main(["sweep", str(spec), "--out", str(fresh), "--quiet", "--no-figures"]) == 0
    assert again == (fresh / "results.csv").read_text()  # contract: a restart is a fresh run


def test_a_resume_by_another_bikemass_is_refused(tmp_path, capsys, monkeypatch):
    spec, out = tmp_path / "s.yaml", tmp_path / "out"
    spec.write_text("bike: benchmark\nvary:\n  c: [0.06, 0.08]\n")
    assert main(["sweep", str(spec), "--out", str(out), "--quiet", "--no-figures"]) == 0
    monkeypatch.setattr(sweep_run, "__version__", "99.0")
    err = one_line_error(capsys, ["sweep", spec, "--out", out, "--quiet", "--no-figures"])
    assert f"computed by bikemass {bm.__version__}, this is 99.0" in err
    monkeypatch.undo()
    monkeypatch.setattr(sweep_run, "code_digest", lambda: "0" * 16)
    err = one_line_error(capsys, ["sweep", spec, "--out", out, "--quiet", "--no-figures"])
    assert "bikemass's code changed" in err
    monkeypatch.undo()
    record = json.loads((out / "sweep.json").read_text())             # a record of an earlier bikemass
    del record["inputs"], record["bikemass"]
    (out / "sweep.json").write_text(json.dumps(record))
    err = one_line_error(capsys, ["sweep", spec, "--out", out, "--quiet", "--no-figures"])
    assert "did not record its input files' content" in err
    with pytest.raises(bm.InputError, match="did not record"):
        run_sweep(str(spec), out)
    assert len(run_sweep(str(spec), out, restart=True)) == 2


def test_a_stiffness_file_is_found_next_to_the_spec(tmp_path, monkeypatch):
    here = folder(tmp_path)
    (here / "s.yaml").write_text("bike: benchmark\nstiffness: frame.yaml\nvary:\n  c: [0.08]\n")
    monkeypatch.chdir(tmp_path)
    spec = read_spec(here / "s.yaml")
    assert spec.stiffness == str((here / "frame.yaml").resolve())
    assert read_spec(here / "s.yaml").bike == "benchmark"                # a shipped name stays a name


def test_zero_filled_and_crlf_chunks_are_computed_again(tmp_path):
    spec, out = tmp_path / "s.yaml", tmp_path / "out"
    spec.write_text("bike: benchmark\nvary:\n  c: [0.04, 0.06, 0.08, 0.1]\nchunk: 1\n")
    run_sweep(str(spec), out)
    clean = (out / "results.csv").read_bytes()
    chunks = sorted((out / "chunks").iterdir())
    chunks[1].write_bytes(b"\0" * 5_000_000)                            # what a crash or a full disk leaves
    chunks[2].write_bytes(chunks[2].read_bytes().replace(b"\n", b"\r\n"))
    rows = run_sweep(str(spec), out)
    assert len(rows) == 4 and (out / "results.csv").read_bytes() == clean and b"\r" not in clean
    assert rows[1]["c"] == 0.06 and rows[2]["weave_speed"] == pytest.approx(4.292, abs=5e-4)   # Meijaard 2007: 4.292 m/s


def test_an_empty_chunks_folder_does_not_block_a_run(tmp_path, capsys):
    spec, out = tmp_path / "s.yaml", tmp_path / "out"
    spec.write_text("bike: benchmark\nvary:\n  c: [0.08]\n")
    (out / "chunks").mkdir(parents=True)                                 # what a full disk left
    assert main(["sweep", str(spec), "--out", str(out), "--quiet", "--no-figures"]) == 0
    other = tmp_path / "other"
    (other / "chunks").mkdir(parents=True)
    (other / "notes.txt").write_text("mine")                             # real content is still protected
    one_line_error(capsys, ["sweep", spec, "--out", other, "--quiet", "--no-figures"])
    assert (other / "notes.txt").read_text() == "mine"


@pytest.mark.parametrize("address", ["inproc://nothing", "tls://127.0.0.1:1", "ucx://127.0.0.1:1"])
def test_a_scheduler_address_beyond_reach_is_one_line_and_nothing_after(tmp_path, address):
    """inproc:// used to print the line, then a Client's traceback 20 s later; tls:// an internal error."""
    pytest.importorskip("distributed")
    spec = tmp_path / "s.yaml"
    spec.write_text("bike: benchmark\nvary:\n  c: [0.08]\n")
    argv = ["sweep", str(spec), "--out", str(tmp_path / "o"), "--scheduler", address, "--no-figures"]
    code = f"import sys; from bikemass.cli.main import main; sys.exit(main({argv!r}))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          env={**os.environ, "PYTHONPATH": str(SRC)}, timeout=120)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and address in done.stderr, done.stderr
    assert not (tmp_path / "o").exists()


def test_a_range_key_is_made_per_chunk_as_numpy_linspace_makes_it():
    rng = np.random.default_rng(35)
    for _ in range(300):
        low, high = np.sort(rng.normal(size=2) * 10.0 ** rng.integers(-4, 4, size=2))
        num = int(rng.integers(2, 3000))
        assert Variable("c", low=low, high=high, num=num).at(np.arange(num)) == np.linspace(low, high, num).tolist()


def test_one_key_of_1e8_values_costs_a_chunk_its_own_rows(tmp_path):
    spec_path = tmp_path / "s.yaml"
    spec_path.write_text("bike: benchmark\nvary:\n  c: {from: 0.0, to: 0.2, num: 100000000}\n")
    spec = read_spec(spec_path)
    tracemalloc.start()
    columns = spec.columns(10 ** 8 - 1000, 10 ** 8)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    assert peak < 5_000_000                                             # the whole key would be 800 MB and more
    step = 0.2 / (10 ** 8 - 1)
    assert columns["c"][-1] == 0.2 and columns["c"][0] == pytest.approx((10 ** 8 - 1000) * step, rel=1e-15)
