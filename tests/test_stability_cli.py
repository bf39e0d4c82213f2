"""``bikemass eig`` / ``bikemass stability`` on parameter files, stiffness files and bad input."""

import json
import re

import numpy as np

import pytest
from images import colour_mask, is_drawn, pixels, runs
from matplotlib import colormaps

from bikemass.cli.main import main
from bikemass.core.paths import frames_dir

BENCHMARK = str(frames_dir() / "benchmark.yaml")


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_stability_json_schema_and_meijaard_speeds(capsys):
    code, out, _ = run(capsys, "stability", BENCHMARK, "--format", "json")
    assert code == 0
    d = json.loads(out)
    assert d["weave_speeds"] == [pytest.approx(4.29238253634110, abs=1e-9)]
    assert d["capsize_speeds"] == [pytest.approx(6.02426201538836, abs=1e-9)]
    assert d["ranges"]["strict"]["grid"] == [[4.3, 6.0]]
    assert d["ranges"]["marginal"]["grid"] == [[4.3, 30.0]]
    assert d["modes"]["capsize"]["strict"]["grid"] == [[0.0, 6.0]]
    assert set(d["modes"]) == {"weave", "weave 1", "weave 2", "capsize", "caster"}


def test_eig_json_table_and_csv(capsys):
    code, out, _ = run(capsys, "eig", BENCHMARK, "--speeds", "0:10:1", "--format", "json")
    d = json.loads(out)
    assert code == 0 and d["speeds"] == [float(v) for v in range(11)]
    caster = next(m for m in d["modes"] if m["label"] == "caster")["eigenvalues"]
    assert caster[10] == [pytest.approx(-24.62459635017404, abs=1e-12), 0.0]   # Meijaard 2007, Table 2
    code, out, _ = run(capsys, "eig", BENCHMARK, "--speeds", "0:1:0.5", "--format", "csv")
    lines = out.splitlines()
    assert lines[0].startswith("speed,weave_1_re,weave_1_im") and len(lines) == 4
    assert float(lines[1].split(",")[1]) == pytest.approx(3.13164324790656, abs=1e-12)
    code, out, _ = run(capsys, "eig", BENCHMARK, "--speeds", "0:1:1")
    head, _, first = out.splitlines()[:3]
    row = dict(zip(re.split(r"\s{2,}", head.strip()), re.split(r"\s{2,}", first.strip())))
    assert code == 0 and float(row["capsize re"]) == pytest.approx(-3.13164324790656, abs=1e-6)


def test_stiffness_file_changes_the_result_and_plots_are_written(capsys, tmp_path):
    stiff = tmp_path / "s.yaml"
    stiff.write_text("S: [[6538.4, 1234.9], [1234.9, 3622.1]]\n")
    png = tmp_path / "eig.png"
    code, out, _ = run(capsys, "stability", BENCHMARK, "--stiffness", str(stiff), "--format", "json",
                       "--plot", str(png))
    assert code == 0 and is_drawn(png)
    flexible = json.loads(out)["weave_speeds"][0]
    assert 4.29238253634110 < flexible < 6                    # a softer frame delays weave stability
    out_file = tmp_path / "eig.json"
    assert run(capsys, "eig", BENCHMARK, "--speeds", "0:2:1", "--format", "json",
               "-o", str(out_file))[0] == 0
    assert json.loads(out_file.read_text())["speeds"] == [0.0, 1.0, 2.0]


@pytest.mark.parametrize("argv,needle", [
    (["eig", BENCHMARK, "--speeds", "0:x"], "--speeds"),
    (["eig", BENCHMARK, "--speeds", "5:1:0.1"], "START:STOP:STEP"),
    (["stability", BENCHMARK, "--marginal", "-1"], "--marginal"),
    (["eig", BENCHMARK, "--plot", "out.txt"], ".png"),
    (["stability", "no-such-bike"], "no-such-bike"),
])
def test_bad_input_is_one_line_exit_2(capsys, argv, needle):
    code, out, err = run(capsys, *argv)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and needle in err
    assert "Traceback" not in err


def test_bad_stiffness_file(capsys, tmp_path):
    bad = tmp_path / "s.yaml"
    bad.write_text("S: [[1, 2], [2, 1]]\n")      # not positive definite
    code, _, err = run(capsys, "stability", BENCHMARK, "--stiffness", str(bad))
    assert code == 2 and "S" in err and "positive definite" in err


@pytest.mark.parametrize("bike,rider,stiffness,table,material,row", [
    ("jamis-thesis", "relaxed-thesis", "steel", "T5_1", "Steel", "Relaxed"),
    ("cargo-loaded-thesis", "aero-tuck-thesis", "titanium", "T5_3", "Titanium", "Aero Tuck"),
])
def test_named_thesis_bicycles_reproduce_chapter_5_rows(capsys, bike, rider, stiffness, table,
                                                        material, row):
    from thesis_sets import TABLES
    code, out, _ = run(capsys, "stability", bike, "--rider", rider, "--combine", "thesis",
                       "--stiffness", stiffness, "--format", "json")
    assert code == 0
    d = json.loads(out)["ranges"]
    got = []
    for criterion in ("strict", "marginal"):
        grid = d[criterion]["grid"]
        got += [grid[0][0], grid[0][1], grid[0][1] - grid[0][0]] if grid else [None] * 3
    for g, printed in zip(got, TABLES[table][material][row]):
        assert (g is None and printed is None) or abs(g - printed) <= 0.05 + 1e-9


def test_compare_plots_several_riders_and_stiffnesses(capsys, tmp_path):
    out_png = tmp_path / "cmp.png"
    code, out, _ = run(capsys, "compare", "jamis-thesis", "--riders", "none,relaxed-thesis",
                       "--stiffnesses", "infinite,steel", "--combine", "thesis", "--plot", str(out_png),
                       "--format", "table")
    assert code == 0
    rows = [line.split() for line in out.splitlines()[2:6]]
    assert [r[:2] for r in rows] == [["none", "infinite"], ["none", "steel"],
                                     ["relaxed-thesis", "infinite"], ["relaxed-thesis", "steel"]]
    # Table 5-1, Jamis + Relaxed: strict stable 5.70..10.35 (rigid) and 5.85..8.30 (steel) on the
    # 0.05 grid; the exact ends, moved onto the grid, agree to one grid step as in every table test
    ranges = []
    for row, (start, stop) in zip(rows[2:], [(5.70, 10.35), (5.85, 8.30)]):
        a, b = map(float, row[4].split(".."))
        ranges.append((a, b))
        assert abs(np.ceil(a / 0.05) * 0.05 - start) <= 0.05 + 1e-9
        assert abs(np.floor(b / 0.05) * 0.05 - stop) <= 0.05 + 1e-9
    # The figure, decoded: one colour per stiffness (viridis 0 and 0.8), each on two rows (the bare
    # frame's capsize mark alone, the rider's weave and capsize marks); the marks of the rider's rows
    # lie as far apart as the stable ranges are long (the pixels per m/s taken from the rigid row,
    # the mark's own width from the bare frame's row): the steel range to 0.1 m/s (~6 px)
    rgb = pixels(out_png)
    marks = [colour_mask(rgb, colormaps["viridis"](x)[:3], 0.05) for x in (0.0, 0.8)]
    spans = []
    for mask in marks:
        bands = runs(mask.any(axis=1))
        assert len(bands) == 2, bands                                # two rows of each series
        spans.append([np.ptp(np.flatnonzero(mask[a:b + 1].any(axis=0))) for a, b in bands])
    (bare_rigid, rider_rigid), (bare_steel, rider_steel) = spans
    per_speed = (rider_rigid - bare_rigid) / (ranges[0][1] - ranges[0][0])         # pixels per m/s
    assert (rider_steel - bare_steel) / per_speed == pytest.approx(ranges[1][1] - ranges[1][0], abs=0.1)


def test_compare_refuses_a_non_image_plot_and_an_image_as_data(capsys, tmp_path):
    code, _, err = run(capsys, "compare", BENCHMARK, "--plot", str(tmp_path / "x.txt"))
    assert code == 2 and err.count("\n") == 1 and not (tmp_path / "x.txt").exists()
    code, _, err = run(capsys, "compare", BENCHMARK, "-o", str(tmp_path / "x.png"))
    assert code == 2 and "a figure goes to --plot FILE" in err and not (tmp_path / "x.png").exists()


def test_compare_data_in_every_format(capsys, tmp_path):
    code, out, _ = run(capsys, "compare", "jamis", "--stiffnesses", "infinite,steel", "--format", "json")
    data = json.loads(out)
    assert code == 0 and [r["stiffness"] for r in data["runs"]] == ["infinite", "steel"]
    assert data["units"] == {"weave_speeds": "m/s", "capsize_speeds": "m/s", "stable_speeds": "m/s"}
    target = tmp_path / "speeds.csv"                      # the format follows the suffix
    assert run(capsys, "compare", BENCHMARK, "-o", str(target))[:2] == (0, "")
    assert target.read_text().splitlines()[0].startswith("rider,stiffness,weave speeds (m/s)")


def test_contract_compare_applies_a_members_file_to_the_models_that_have_the_member(capsys, tmp_path):
    """Contract test of ``compare`` against ``stability`` (both the library's): ``compare --models whipple,tyre
    --tyres FILE`` was refused (the Whipple model has no tyre member); the file applies to the tyre model, whose row equals ``stability --model tyre --tyres FILE`` (1e-9 m/s), and
    the Whipple row equals ``stability`` without it. A file no model of the list takes is one line."""
    tyres = tmp_path / "tyres.yaml"
    tyres.write_text("front: {cornering_coefficient: 11.46 1/rad, camber_coefficient: 0.573 1/rad, "
                     "relaxation_length: 0.1 m}\nrear: {cornering_coefficient: 0.2 1/deg, camber_coefficient: "
                     "0.01 1/deg, relaxation_length: 100 mm}\n")
    args = ["jamis", "--rider", "relaxed", "--speeds", "0:10:0.1", "--format", "json"]
    assert main(["compare", "jamis", "--riders", "relaxed", "--models", "whipple,tyre", "--tyres", str(tyres),
                 *args[3:]]) == 0
    runs = {run["model"]: run for run in json.loads(capsys.readouterr().out)["runs"]}
    for model, extra in (("whipple", []), ("tyre", ["--model", "tyre", "--tyres", str(tyres)])):
        assert main(["stability", *args, *extra]) == 0
        alone = json.loads(capsys.readouterr().out)
        assert runs[model]["weave_speeds"] == pytest.approx(alone["weave_speeds"], abs=1e-9)
    assert main(["compare", "jamis", "--riders", "relaxed", "--models", "whipple,rider-lean", "--tyres",
                 str(tyres)]) == 2
    assert "none of whipple, rider-lean has one" in capsys.readouterr().err
