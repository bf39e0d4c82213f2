"""``bikemass params / draw / export``: output forms, and bad bicycle files (exit 2, one line
naming the file and the key)."""

import json
from pathlib import Path

import numpy as np
import pytest
import trimesh
import yaml

from bikemass.bicycle import load_bicycle
from bikemass.bicycle.scene import equivalent_ellipsoid
from bikemass.cli.main import main
from bikemass.mass.inertia import MassProperties

from test_bicycle import MEIJAARD_2007

FRAMES = Path(__file__).parents[1] / "frames"
JAMIS = yaml.safe_load((FRAMES / "jamis.yaml").read_text())


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_params_benchmark_json_is_meijaard_2007(capsys):
    code, out, err = run(capsys, "params", "benchmark", "--format", "json")
    assert code == 0 and err == ""
    data = json.loads(out)
    assert data.pop("units") == {k: "m" for k in ("w", "c", "rR", "xB", "zB", "xH", "zH", "rF")} | \
        {"lam": "rad", "g": "m/s^2"} | {k: "kg" for k in ("mR", "mB", "mH", "mF")} | \
        {k: "kg m^2" for k in MEIJAARD_2007 if k.startswith("I")}
    assert data == {**MEIJAARD_2007, "rider_included": True}     # B holds the rider


def test_params_yaml_to_file(capsys, tmp_path):
    target = tmp_path / "out" / "jamis.yaml"
    code, out, _ = run(capsys, "params", "jamis-thesis", "--rider", "relaxed-thesis", "--combine", "thesis",
                       "-o", target)
    assert code == 0 and out == ""
    data = yaml.safe_load(target.read_text())
    assert data["mB"] == pytest.approx(4.615 + 82.150, abs=1e-12)
    assert data["IBxx"] == pytest.approx(12.790, abs=1e-12)


def test_draw_writes_a_png(capsys, tmp_path):
    target = tmp_path / "side.png"
    code, _, err = run(capsys, "draw", "cargo-loaded", "--rider", "relaxed", "--plot", target)
    assert code == 0 and err == ""
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("suffix", ["glb", "stl", "obj"])
def test_export_writes_the_assembled_model(capsys, tmp_path, suffix):
    target = tmp_path / f"model.{suffix}"
    code, _, err = run(capsys, "export", "jamis", "--rider", "relaxed", "-o", target)
    assert code == 0 and err == ""
    loaded = trimesh.load(target, force="mesh")
    bike = load_bicycle("jamis")
    # the model spans the wheels: from behind the rear tire to ahead of the front tire
    lo, hi = loaded.bounds
    assert lo[0] == pytest.approx(-bike.geometry.rear_wheel_radius, abs=0.005)
    assert hi[0] == pytest.approx(bike.geometry.wheelbase + bike.geometry.front_wheel_radius, abs=0.005)


def test_lumped_bodies_export_as_their_equivalent_ellipsoid():
    props = MassProperties(4.615, [0.33, 0.0, -0.493], [[0.288, 0, 0.023], [0, 0.493, 0], [0.023, 0, 0.209]])
    mesh = equivalent_ellipsoid(props)
    got = MassProperties.from_trimesh(mesh, props.mass / mesh.volume)
    np.testing.assert_allclose(got.com, props.com, atol=1e-9)
    # icosphere (subdivision 3) ellipsoid: inertia within 1 % of the lumped body's
    np.testing.assert_allclose(got.inertia, props.inertia, atol=0.01 * props.inertia.max())


def test_bad_output_suffix(capsys, tmp_path):
    code, _, err = run(capsys, "export", "jamis", "-o", tmp_path / "model.dwg")
    assert code == 2 and "model.dwg" in err and len(err.strip().splitlines()) == 1


def _variant(tmp_path, change):
    data = yaml.safe_load(yaml.safe_dump(JAMIS))
    change(data)
    path = tmp_path / "bad_bike.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    return path


def _tube(data, name):
    return next(t for t in data["tubes"] if t["name"] == name)


BAD = {
    "missing keypoint": (lambda d: _tube(d, "down_tube").update({"to": "nowhere"}), "tubes[1].to"),
    "unknown material": (lambda d: d.update({"material": "unobtainium"}), "material"),
    "unknown tube material": (lambda d: _tube(d, "top_tube").update({"material": "balsa"}), "tubes[4].material"),
    "zero-length tube": (lambda d: _tube(d, "head_tube").update({"to": "head_top"}), "tubes[0].to"),
    "wall thicker than radius": (lambda d: d["sections"]["seat_tube"].update({"wall": "0.6 in"}),
                                 "sections.seat_tube.wall"),
    "front wheel radius vs keypoints": (lambda d: d["geometry"].update({"front_wheel_radius": 0.36}),
                                        "geometry.front_wheel_radius"),
    "rear wheel radius vs dropouts": (lambda d: (d["geometry"].update({"rear_wheel_radius": 0.37}),
                                                 d["keypoints"].pop("rear_axle")),
                                      "geometry.rear_wheel_radius"),
    "tire vs wheel radius": (lambda d: d["wheels"]["rear"]["hoops"]["tire"].update({"outer_diameter": "28 in"}),
                             "wheels.rear.hoops"),
    "trail vs head-tube keypoints": (lambda d: d["geometry"].update({"trail": 0.075}), "geometry.trail"),
    "head angle vs head-tube keypoints": (lambda d: d["geometry"].update({"head_angle": "72 deg"}),
                                          "geometry.head_angle"),
    "trail vs fork offset": (lambda d: d["geometry"].update({"fork_offset": 0.050}), "geometry.trail"),
    "unknown body": (lambda d: d["components"][0].update({"body": "saddle_bag"}), "components[0].body"),
    "unknown structure tube": (lambda d: d["structure"].update({"tubes": ["head_tube", "steerer"]}),
                               "structure.tubes[1]"),
    "asymmetric stiffness": (lambda d: d.update({"stiffness": {"steel": [[1.0, 0.2], [0.1, 1.0]]}}),
                             "stiffness.steel"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_bicycle_file_is_one_line_naming_file_and_key(capsys, tmp_path, case):
    change, key = BAD[case]
    path = _variant(tmp_path, change)
    code, out, err = run(capsys, "params", path)
    lines = err.strip().splitlines()
    assert code == 2 and out == "" and len(lines) == 1, err
    assert str(path) in lines[0] and f": {key}: " in lines[0], lines[0]


def test_the_unchanged_variant_is_good(capsys, tmp_path):
    """The bad-input cases above differ from a file that loads (guards against vacuous passes)."""
    code, _, err = run(capsys, "params", _variant(tmp_path, lambda d: None))
    assert code == 0 and err == ""


def test_unknown_bicycle_name(capsys):
    code, _, err = run(capsys, "params", "penny-farthing")
    assert code == 2 and "penny-farthing" in err and "jamis" in err


def test_base_file_errors_name_the_base(capsys, tmp_path):
    base = _variant(tmp_path, lambda d: d["sections"]["seat_tube"].update({"wall": "0.6 in"}))
    child = tmp_path / "child.yaml"
    child.write_text(f"base: {base}\nname: child\n")
    code, _, err = run(capsys, "params", child)
    assert code == 2 and str(base) in err and "sections.seat_tube.wall" in err


def test_compare_table_lists_every_parameter_with_its_difference(capsys):
    code, out, _ = run(capsys, "params", "jamis", "--compare", "jamis-thesis", "--method", "exact")
    assert code == 0
    rows = {line.split()[0]: line.split() for line in out.splitlines()[2:]}
    assert len(rows) == 26
    mB = load_bicycle("jamis").bodies("exact")["rear_frame"].mass
    assert rows["mB"][-5:] == [f"{mB:.4f}", "4.6150", f"{mB - 4.615:.4f}", f"{100 * (mB / 4.615 - 1):+.1f}", "%"]


def test_parameter_files_in_json_work_and_incomplete_ones_name_the_missing_key(capsys, tmp_path):
    good = tmp_path / "measured.json"
    good.write_text(json.dumps(MEIJAARD_2007))
    code, out, _ = run(capsys, "params", good, "--format", "json")
    assert code == 0 and {k: v for k, v in json.loads(out).items() if k != "units"} == MEIJAARD_2007
    written = tmp_path / "written.json"                     # the output is itself a parameter file
    assert run(capsys, "params", good, "-o", written)[0] == 0 and "units" in json.loads(written.read_text())
    assert run(capsys, "params", written, "--format", "json")[1] == out
    partial = dict(MEIJAARD_2007)
    del partial["IBxz"]
    bad = tmp_path / "partial.json"
    bad.write_text(json.dumps(partial))
    code, out, err = run(capsys, "params", bad)
    assert code == 2 and out == "" and err.count("\n") == 1
    assert "partial.json: IBxz: a required key that is missing" in err
