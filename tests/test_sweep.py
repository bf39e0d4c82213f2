"""Sweeps: identical tables from every engine, values equal to independent stability runs,
resuming, samples, Sobol indices, geometry-level inputs, bad specs."""

import csv
import json
from pathlib import Path

import numpy as np
import pytest
from images import is_drawn

from bikemass.scenario import catalog
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.cli.main import main
from bikemass.analysis.engine import crossings
from bikemass.models.whipple import whipple_model


def general_crossings(p, S=None):
    """``[(speed, kind, w)]`` by the engine's general path (compound matrices), not the closed form
    that sweeps use."""
    return crossings.axis_crossings(whipple_model(p, S), 0.0, 30.0)

GRID = """bike: benchmark
vary:
  c: {from: 0.04, to: 0.12, num: 4}
  lam: [0.25, 0.314159265358979, 0.4]
chunk: 5
"""


def _spec(tmp_path, text, name="spec.yaml"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def _rows(folder):
    with open(folder / "results.csv") as fh:
        return list(csv.DictReader(fh))


@pytest.mark.slow     # a sweep on a Dask cluster or many full builds (4-6 s)
def test_engines_give_identical_tables(tmp_path):
    """In-process, --workers 1, --workers 2 (worker processes) and --scheduler (the address of a
    LocalCluster started here, in-process workers for a quick start): the same bytes in results.csv."""
    from distributed import LocalCluster
    spec = _spec(tmp_path, GRID)
    assert main(["sweep", spec, "--out", str(tmp_path / "serial"), "--quiet"]) == 0
    assert main(["sweep", spec, "--out", str(tmp_path / "w1"), "--workers", "1", "--quiet"]) == 0
    assert main(["sweep", spec, "--out", str(tmp_path / "w2"), "--workers", "2", "--quiet"]) == 0
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, protocol="tcp", host="127.0.0.1",
                      dashboard_address="127.0.0.1:0", silence_logs=40) as cluster:
        assert main(["sweep", spec, "--out", str(tmp_path / "sched"), "--scheduler",
                     cluster.scheduler_address, "--quiet"]) == 0
    ref = (tmp_path / "serial" / "results.csv").read_bytes()
    for name in ("w1", "w2", "sched"):
        assert (tmp_path / name / "results.csv").read_bytes() == ref, name
    rows = _rows(tmp_path / "serial")
    assert len(rows) == 12 and list(rows[0]) == ["c", "lam", "weave_speed", "capsize_speed", "stable_from",
                                                 "stable_to", "total_mass", "error"]
    import pyarrow.parquet as pq
    table = pq.read_table(tmp_path / "serial" / "results.parquet")
    np.testing.assert_array_equal(table.column("weave_speed").to_numpy(),
                                  [float(r["weave_speed"]) for r in rows])


@pytest.mark.slow     # a sweep on a Dask cluster or many full builds (4-6 s)
def test_rows_equal_independent_stability_runs(tmp_path):
    """Every row's critical speeds equal those the engine's general path finds (polynomial eigenvalue
    problems of the compound matrices; the sweep uses the closed form) on the benchmark with that c
    and lam, to 1e-9 m/s, and its strict stable range holds the speeds where a dense eigenvalue scan
    finds every root stable."""
    spec = _spec(tmp_path, GRID)
    assert main(["sweep", spec, "--out", str(tmp_path / "o"), "--quiet"]) == 0
    p = scenario_parameters("benchmark")
    for row in _rows(tmp_path / "o"):
        q = p.replace(c=float(row["c"]), lam=float(row["lam"]))
        found = general_crossings(q)
        assert float(row["weave_speed"]) == pytest.approx(next(s for s, k, _ in found if k == "oscillatory"), abs=1e-9)
        assert float(row["capsize_speed"]) == pytest.approx(next(s for s, k, _ in found if k == "real"), abs=1e-9)
        v = np.linspace(0.0, 30.0, 30001)
        stable = np.all(np.linalg.eigvals(whipple_model(q).dynamic_matrix(v)).real < 0, axis=1)
        edges = np.flatnonzero(np.diff(np.concatenate([[0], stable.astype(int), [0]])))
        first = v[edges[0]], v[edges[1] - 1]                  # the first run of stable grid speeds
        assert [float(row["stable_from"]), float(row["stable_to"])] == pytest.approx(first, abs=1.1e-3)
        assert float(row["total_mass"]) == pytest.approx(p.mR + p.mB + p.mH + p.mF)


def test_resume_recomputes_only_missing_chunks(tmp_path):
    from bikemass.sweep import read_spec, run_sweep
    spec = read_spec(_spec(tmp_path, GRID))
    out = tmp_path / "o"
    first = list(run_sweep(spec, out))
    assert sorted(p.name for p in (out / "chunks").iterdir()) == [
        "000000000-000000005.csv", "000000005-000000010.csv", "000000010-000000012.csv"]
    table = (out / "results.csv").read_bytes()
    (out / "chunks" / "000000005-000000010.csv").unlink()
    (out / "results.csv").unlink()
    done = []
    second = run_sweep(spec, out, progress=done.append)
    assert done == [7, 5] and second == first        # 7 configurations kept, one chunk of 5 recomputed
    assert (out / "results.csv").read_bytes() == table
    other = _spec(tmp_path, GRID.replace("num: 4", "num: 5"), "other.yaml")
    assert main(["sweep", other, "--out", str(out), "--quiet"]) == 2


def test_resume_with_another_chunk_size_and_engine(tmp_path):
    """The chunk size is not part of the sweep: chunks of 5 from this process, two of them lost,
    are completed by a run with chunks of 2 on a 2-worker Dask cluster, and the table is unchanged."""
    from distributed import LocalCluster

    from bikemass.sweep import read_spec, run_sweep
    out = tmp_path / "o"
    first = list(run_sweep(read_spec(_spec(tmp_path, GRID)), out))
    for name in ("000000000-000000005.csv", "000000010-000000012.csv"):
        (out / "chunks" / name).unlink()
    done = []
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, protocol="tcp", host="127.0.0.1",
                      dashboard_address="127.0.0.1:0", silence_logs=40) as cluster:
        second = run_sweep(read_spec(_spec(tmp_path, GRID.replace("chunk: 5", "chunk: 2"), "two.yaml")), out,
                           scheduler=cluster.scheduler_address, progress=done.append)
    assert second == first and done[0] == 5 and sum(done) == 12
    names = sorted(p.name for p in (out / "chunks").iterdir())
    assert "000000005-000000010.csv" in names and len(names) > 3


def test_a_client_is_used_and_left_open(tmp_path):
    """``scheduler=`` a distributed.Client (a notebook's cluster): the sweep runs on it, leaves it
    open for the next sweep, and writes the table this process writes."""
    from distributed import Client, LocalCluster

    from bikemass.sweep import read_spec, run_sweep
    spec = read_spec(_spec(tmp_path, GRID))
    serial = run_sweep(spec, tmp_path / "serial")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, protocol="tcp", host="127.0.0.1",
                      dashboard_address="127.0.0.1:0", silence_logs=40) as cluster, \
            Client(cluster, set_as_default=False) as client:            # not the default client either
        for name in ("a", "b"):
            assert run_sweep(spec, tmp_path / name, scheduler=client) == serial
            assert client.status == "running"
        assert client.submit(sum, [1, 2]).result() == 3
    assert (tmp_path / "b" / "results.csv").read_bytes() == (tmp_path / "serial" / "results.csv").read_bytes()


@pytest.mark.slow     # a sweep on a Dask cluster or many full builds (4-6 s)
def test_local_cluster_runs_quiet_and_leaves_the_callers_settings():
    """``--workers N``'s cluster: its worker processes run with QUIET_CLUSTER's settings (profiler
    off, chores less often); the caller's Dask settings are what they were."""
    import importlib

    import dask
    from distributed import Client
    run = importlib.import_module("bikemass.sweep.run")
    before = {key: dask.config.get(key) for key in run.QUIET_CLUSTER}
    assert before["distributed.worker.profile.enabled"] is True      # Dask's default: the test can fail
    with run.local_cluster(1) as cluster, Client(cluster) as client:
        seen = client.run(lambda: {key: dask.config.get(key) for key in run.QUIET_CLUSTER})
    assert list(seen.values()) == [run.QUIET_CLUSTER]
    assert {key: dask.config.get(key) for key in run.QUIET_CLUSTER} == before


def test_a_sweep_does_not_make_its_client_the_default(tmp_path):
    """While a --workers sweep runs, dask collections elsewhere in the caller's program still use
    their own scheduler: the sweep's client is not made the default (Dask's Client would)."""
    import dask

    from bikemass.sweep import read_spec, run_sweep
    seen = []
    run_sweep(read_spec(_spec(tmp_path, GRID)), tmp_path / "o", workers=1,
              progress=lambda n: seen.append(dask.config.get("scheduler", None)))
    assert len(seen) > 1 and set(seen) == {None}


def test_an_asynchronous_client_is_refused_in_one_line(tmp_path):
    import asyncio

    from distributed import Client, LocalCluster

    from bikemass.core.errors import InputError
    from bikemass.sweep import read_spec, run_sweep
    spec = read_spec(_spec(tmp_path, GRID))

    async def attempt():
        async with LocalCluster(n_workers=1, processes=False, asynchronous=True, dashboard_address=None) as cluster, \
                Client(cluster, asynchronous=True) as client:
            with pytest.raises(InputError, match="a synchronous distributed.Client"):
                run_sweep(spec, tmp_path / "o", scheduler=client)
    asyncio.run(attempt())


def test_table_cells_read_back(tmp_path):
    """A cell with a comma, quote, newline or carriage return reads back as one cell."""
    import io

    from bikemass.sweep.table import NUMBERS, chunk_text, read_chunk
    from bikemass.sweep.table import Outcomes
    odd = ['a,b', 'say "x"', "two\nlines", "cr\rhere", "née"]
    outcomes = Outcomes({k: np.full(len(odd), np.nan) for k in NUMBERS}, odd)
    text = chunk_text(["k"], {"k": odd}, outcomes)
    assert [row[0] for row in csv.reader(io.StringIO(text, newline=""))] == odd
    back = read_chunk(text, ["k"], (), len(odd))
    assert back["k"] == odd and back["error"] == odd and back["weave_speed"] == [None] * len(odd)


def test_a_number_among_stiffness_choices_is_refused(tmp_path, capsys):
    """A stiffness is a choice or a file, never a number: refused at once, naming the element,
    instead of an error on every row."""
    spec = _spec(tmp_path, "bike: benchmark\nvary:\n  stiffness: [infinite, 2.5]\n")
    assert main(["sweep", spec, "--out", str(tmp_path / "o"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "vary.stiffness[1]" in err and "stiffness choice" in err
    assert not (tmp_path / "o").exists()


def test_chunk_sizes():
    """Default: 20 chunks in this process; on Dask equal chunks, one per worker thread for
    parameter-only sweeps and 12 otherwise, never more than 2000 configurations; the spec's
    chunk wins; missing ranges are cut at that size."""
    from bikemass.sweep.layout import Kept, missing_ranges, split
    from bikemass.sweep.run import chunk_size
    from bikemass.sweep.spec import read_spec
    from bikemass.sweep.vectorised import takes
    assert chunk_size(2050) == 103 and chunk_size(2050, 2, fixed=50) == 50
    assert chunk_size(2000, 0, cheap=True) == 100                    # a cluster with no worker yet
    assert chunk_size(2050, 2) == 86 and chunk_size(2050, 1) == 171 and chunk_size(3, 8) == 1   # 12 rounds
    assert chunk_size(2050, 2, cheap=True) == 1025 and chunk_size(2050, 1, cheap=True) == 2050
    assert chunk_size(10 ** 6, 2, cheap=True) == 100_000 and chunk_size(10 ** 7, None, cheap=True) == 100_000
    assert chunk_size(10 ** 6, 2) == 2000 and chunk_size(10 ** 6 + 1, 2) == 1993
    examples = Path(__file__).resolve().parents[1] / "examples" / "sweeps"
    assert takes(read_spec(str(examples / "benchmark_c_lam.yaml")).keys)
    assert not takes(read_spec(str(examples / "jamis_torso_lean.yaml")).keys)
    assert not takes(read_spec(str(examples / "jamis_walls.yaml")).keys)
    kept = [Kept(3, 5, 0, None)]
    assert split(missing_ranges(kept, 11), 4) == [(0, 3), (5, 9), (9, 11)]
    assert split(missing_ranges([Kept(0, 4, 0, None)], 4), 2) == []


def test_latin_hypercube_and_sobol_indices(tmp_path, capsys):
    lhs = _spec(tmp_path, """bike: benchmark
vary: {c: {from: 0.05, to: 0.1}, mB: {from: 80, to: 90}}
sample: {method: lhs, n: 20, seed: 3}
""")
    assert main(["sweep", lhs, "--out", str(tmp_path / "lhs"), "--quiet"]) == 0
    rows = _rows(tmp_path / "lhs")
    c = sorted(float(r["c"]) for r in rows)
    assert len(rows) == 20 and 0.05 <= c[0] and c[-1] <= 0.1
    # Latin hypercube: exactly one sample in each of the 20 strata of c
    assert sorted(int((x - 0.05) / 0.05 * 20) for x in c) == list(range(20))
    gsa = _spec(tmp_path, """bike: benchmark
vary: {c: {from: 0.06, to: 0.1}, IByy: {from: 9, to: 12}}
sample: {method: sobol, n: 32, seed: 1}
global_sensitivity: true
""", "gsa.yaml")
    assert main(["sweep", gsa, "--out", str(tmp_path / "gsa"), "--quiet"]) == 0
    sobol = json.loads((tmp_path / "gsa" / "sobol.json").read_text())
    assert len(_rows(tmp_path / "gsa")) == 32 * (2 + 2)          # Saltelli, first order: N (D + 2)
    for out in ("weave_speed", "capsize_speed"):
        assert sobol[out]["IByy"]["ST"] == 0                     # IByy does not enter the model
        assert sobol[out]["c"]["ST"] > 0.9 and sobol[out]["c"]["S1"] > 0.9


@pytest.mark.slow     # a sweep on a Dask cluster or many full builds (4-6 s)
def test_geometry_level_sweep_changes_with_the_walls(tmp_path):
    """Jamis tube walls (seat stays, chain stays), steel frame (beam S), Relaxed rider."""
    spec = _spec(tmp_path, """bike: jamis
rider: relaxed
stiffness: steel
vary:
  sections.seat_stay.wall: [0.02, 0.04, 0.08]     # inches, as the file writes them
  sections.chain_stay.wall: [0.04, 0.08]
""")
    assert main(["sweep", spec, "--out", str(tmp_path / "g"), "--quiet"]) == 0
    rows = _rows(tmp_path / "g")
    assert len(rows) == 6 and not any(r["error"] for r in rows)
    for col in ("weave_speed", "capsize_speed", "total_mass"):
        values = [float(r[col]) for r in rows]
        assert len(set(values)) == 6, col
    nominal = next(r for r in rows if float(r["sections.seat_stay.wall"]) == 0.04
                   and float(r["sections.chain_stay.wall"]) == 0.04)
    p, S = scenario_parameters("jamis", "relaxed"), catalog.stiffness("jamis", "steel")
    weave = next(s for s, k, _ in general_crossings(p, S) if k == "oscillatory")
    assert float(nominal["weave_speed"]) == pytest.approx(weave, abs=1e-9)
    assert is_drawn(tmp_path / "g" / "heatmap.png")


PERSON = """name: a person on the hoods
body: {height: 1.80 m, mass: 75 kg, sex: male}
chain: {hands: hoods}
"""


def test_chart_sweep_reseats_a_person_on_every_frame(tmp_path):
    """A chart bicycle's stack and head angle with a chain pose that has no bicycle of its own:
    every row valid (the chart's published wheelbase, trail, ... no longer describe the changed
    frame and are not checked), each equal to the chart edited by hand (its redundant values
    removed) with the person solved on it, by the general engine."""
    import yaml
    from bikemass.bicycle.chart import CHECKED_KEYS
    from bikemass.core.paths import frames_dir
    (tmp_path / "person.yaml").write_text(PERSON)
    spec = _spec(tmp_path, """bike: specialized_diverge@56
rider: person.yaml
vary:
  chart.stack: [590, 613, 640]
  chart.head_tube_angle: [71.5, 72.5]
""")
    assert main(["sweep", spec, "--out", str(tmp_path / "g"), "--quiet"]) == 0
    rows = _rows(tmp_path / "g")
    assert len(rows) == 6 and not any(r["error"] for r in rows)
    assert len({r["weave_speed"] for r in rows}) == 6
    document = yaml.safe_load((frames_dir() / "specialized_diverge.yaml").read_text())
    size = document["sizes"].index(56)
    for row in (rows[0], rows[5]):
        edited = {**document, "chart": {k: v for k, v in document["chart"].items() if k not in CHECKED_KEYS}}
        for key in ("stack", "head_tube_angle"):
            values = list(edited["chart"][key])
            values[size] = float(row[f"chart.{key}"])
            edited["chart"][key] = values
        bicycle = catalog.load_bicycle(edited, size="56")
        p = scenario_parameters(bicycle, str(tmp_path / "person.yaml"))
        weave = next(s for s, k, _ in general_crossings(p) if k == "oscillatory")
        assert float(row["weave_speed"]) == pytest.approx(weave, abs=1e-9)
        assert float(row["total_mass"]) == pytest.approx(p.mR + p.mB + p.mH + p.mF, rel=1e-12)


def test_a_poses_own_bicycle_is_read_once(tmp_path, monkeypatch):
    """A chain pose naming a bicycle of its own (here a copy of the Jamis, so that its contacts
    are the scenario's): that bicycle is loaded once for a whole geometry-level sweep, not per
    configuration."""
    from bikemass.core.paths import frames_dir
    from bikemass.rider import chain_file
    from bikemass.scenario.scenario import Scenario
    (tmp_path / "twin.yaml").write_text((frames_dir() / "jamis.yaml").read_text())
    loads = []
    real = chain_file.load_bicycle
    monkeypatch.setattr(chain_file, "load_bicycle", lambda *a, **k: loads.append(a) or real(*a, **k))
    (tmp_path / "own.yaml").write_text(PERSON + "bike: twin.yaml\n")
    scenario = Scenario("jamis", str(tmp_path / "own.yaml"))
    for wall in (0.0008, 0.001, 0.0012):                     # m (SI, as the Model reads every input)
        scenario.build({"sections.seat_stay.wall": wall})
    assert len(loads) == 1


@pytest.mark.parametrize("text, key", [
    ("bike: benchmark\nvary: {}\n", "vary"),
    ("bike: benchmark\nvary: {c: {from: 1, to: 0, num: 3}}\n", "vary.c"),
    ("bike: benchmark\nvary: {c: {from: 0, to: 1}}\n", "vary.c.num"),
    ("bike: benchmark\nvary: {c: [0.1]}\nsample: {method: magic, n: 3}\n", "sample.method"),
    ("bike: benchmark\nvary: {c: {from: 0, to: 1, num: 100000}, lam: {from: 0, to: 1, num: 1001}}\n", "vary"),
    ("bike: benchmark\nvary: {c: [0.1]}\nextra: 1\n", "extra"),
    ("bike: jamis\nvary: {sections.nope.wall: [0.001]}\n", "sections.nope.wall"),
    ("bike: benchmark\nvary: {rider.chain.torso_lean: [10]}\n", "rider.chain.torso_lean"),
    # a member's file and the model's rider, named in the spec (they were blamed on vary, or named no spec)
    ("bike: benchmark\nmodel: tyre\ntyres: nosuch.yaml\nvary: {c: [0.1]}\n", "spec.yaml: tyres: the path of"),
    ("bike: benchmark\ntyres: spec.yaml\nvary: {c: [0.1]}\n", "spec.yaml: tyres: a model with the tyre member"),
    ("bike: benchmark\nmodel: rider-lean\nvary: {c: [0.1]}\n", "spec.yaml: rider: a rider for the rider-lean"),
])
def test_bad_specs_one_line(tmp_path, capsys, text, key):
    spec = _spec(tmp_path, text)
    assert main(["sweep", spec, "--out", str(tmp_path / "o"), "--quiet"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and key in err[0], err
    assert not (tmp_path / "o" / "results.csv").exists()
