"""Bicycles from geometry charts: construction, checks, defaults, sizes, the geometry command."""

import json
from pathlib import Path

import numpy as np
import pytest
import yaml

from bikemass.bicycle import bicycle_parameters, load_bicycle
from bikemass.bicycle.derived_chart import derived_chart
from bikemass.cli.main import main
from bikemass.core.errors import InputError
from bikemass.core.plain import file_form
from printed import number_after

ROOT = Path(__file__).resolve().parents[1]
SHIPPED_CHARTS = ("bmc_roadmachine", "specialized_diverge", "salsa_fargo")

ROAD = {  # a 56 cm road chart (mm, deg)
    "stack": 590, "reach": 388, "head_tube_angle": 72, "seat_tube_angle": 74.2, "head_tube_length": 154,
    "seat_tube_length": 522, "chainstay_length": 410, "bb_drop": 71, "fork_offset": 45,
}


def chart_file(tmp_path, chart=None, **top):
    """A chart bicycle file with ``chart`` values (mm, deg) and extra top-level keys."""
    values = {**ROAD, **(chart or {})}
    doc = {"name": "test road", "chart": {"units": {"length": "mm", "angle": "deg"}, "wheel": "700c",
                                          "tire_width": 28, **values}, **top}
    path = tmp_path / "road.yaml"
    path.write_text(yaml.safe_dump(doc))
    return str(path)


def closed_form_wheelbase(c, r):
    """Wheelbase (m) from a chart (SI, rad): rear axle -> BB -> head-tube top -> steer axis -> axle."""
    ha = c["head_tube_angle"]
    return (np.sqrt(c["chainstay_length"] ** 2 - c["bb_drop"] ** 2) + c["reach"]
            + (c["stack"] - c["bb_drop"]) / np.tan(ha) + c["fork_offset"] / np.sin(ha))


def si(chart):
    return {k: np.radians(v) if k.endswith("_angle") else v / 1000 for k, v in chart.items()}


def test_construction_equals_the_closed_form(tmp_path):
    bike = load_bicycle(chart_file(tmp_path))
    r = 0.311 + 0.028                                     # 700c: BSD 622 mm, radius = BSD/2 + tire width
    c = si(ROAD)
    assert bike.geometry.rear_wheel_radius == pytest.approx(r, abs=1e-12)
    assert bike.geometry.wheelbase == pytest.approx(closed_form_wheelbase(c, r), abs=1e-12)
    ha = c["head_tube_angle"]
    assert bike.geometry.trail == pytest.approx((r * np.cos(ha) - c["fork_offset"]) / np.sin(ha), abs=1e-12)
    d = derived_chart(bike)
    for key, value in c.items():
        expected = np.degrees(value) if key.endswith("_angle") else value
        assert d[key] == pytest.approx(expected, abs=1e-9), key
    assert d["top_tube_length"] == pytest.approx(c["reach"] + c["stack"] / np.tan(c["seat_tube_angle"]), abs=1e-12)
    assert d["mechanical_trail"] == pytest.approx(d["trail"] * np.sin(ha), abs=1e-12)


def test_jamis_geometry_is_table_3_9(capsys):
    assert main(["geometry", "jamis", "--format", "json"]) == 0
    chart = json.loads(capsys.readouterr().out)["jamis"]
    assert chart["wheelbase"] == pytest.approx(0.988, abs=5e-4)      # Table 3-9, printed to 1 mm
    assert chart["trail"] == pytest.approx(0.060, abs=5e-4)
    assert chart["head_tube_angle"] == pytest.approx(np.degrees(1.274), abs=1e-9)
    for key in ("front_center", "stack", "reach"):
        assert chart[key] > 0


@pytest.mark.parametrize("name", SHIPPED_CHARTS)
def test_shipped_charts_match_their_published_redundant_values(name):
    doc = yaml.safe_load((ROOT / "frames" / f"{name}.yaml").read_text())
    sizes = [str(s) for s in doc["sizes"]]
    for i, size in enumerate(sizes):
        d = derived_chart(load_bicycle(name, size))
        for key, tolerance in (("wheelbase", 5), ("trail", 3), ("front_center", 5), ("top_tube_length", 5),
                               ("bb_height", 3)):
            published = doc["chart"].get(key)
            value = published[i] if isinstance(published, list) else published
            if value is None:
                continue
            assert abs(d[key] * 1000 - value) <= tolerance, (size, key, d[key], value)


def test_chart_road_bicycle_mass_and_parameters():
    bike = load_bicycle("bmc-roadmachine", "56")
    mass = sum(p.mass for p in bike.parts)
    assert 6 < mass < 14
    params = bicycle_parameters(bike)
    assert params.w == pytest.approx(1.008, abs=0.005)
    assert params.rR == params.rF == pytest.approx(0.339)
    assert 0 < params.xB < params.w and params.zB < 0
    assert bike.contacts is not None and set(bike.contacts.grips) >= {"tops", "hoods", "drops"}
    assert bike.contacts.crank_length == pytest.approx(0.1725)


def test_chain_pose_sits_on_a_chart_bicycle():
    from bikemass.rider.anthropometry import find_anthropometry
    from bikemass.rider.chain import load_chain_body
    from bikemass.rider.solve import solve_on_bicycle
    from bikemass.core.config import Node

    bike = load_bicycle("bmc-roadmachine@54")
    body = load_chain_body(find_anthropometry(Node("thesis_rider", "test", "body")), "thesis_rider")
    solution = solve_on_bicycle(body, bike.contacts, "hoods", None, {})
    assert max(solution.residuals.values()) < 1e-3


def test_overrides_tubeset_components_grips_and_materials(tmp_path):
    base = load_bicycle(chart_file(tmp_path))
    steel = sum(p.mass for p in base.parts)
    carbon = load_bicycle(chart_file(tmp_path, frame={"tubeset": "carbon"}))
    assert sum(p.mass for p in carbon.parts) < steel - 0.5
    lighter = load_bicycle(chart_file(tmp_path, components={"pedals": None, "crankset": {"mass": "0.5 kg"}}))
    assert sum(p.mass for p in lighter.parts) == pytest.approx(steel - 0.3 - 0.2, abs=1e-9)
    gripped = load_bicycle(chart_file(tmp_path, cockpit={"grips": {"bullhorn": ["60 mm", "10 mm"]}}))
    clamp = gripped.keypoints["bar_clamp"]
    np.testing.assert_allclose(gripped.contacts.grips["bullhorn"][[0, 2]], clamp[[0, 2]] + [0.06, -0.01], atol=1e-12)
    own = load_bicycle(chart_file(tmp_path, frame={"material": "unobtainium"},
                                  materials={"unobtainium": {"E": "100 GPa", "nu": 0.3, "density": "1 g/cm^3"}}))
    assert sum(p.mass for p in own.parts) < sum(p.mass for p in carbon.parts)
    saddle = load_bicycle(chart_file(tmp_path, saddle={"height": "720 mm"})).contacts.saddle
    bb = base.keypoints["bottom_bracket"]
    assert np.hypot(*(saddle - bb)[[0, 2]]) == pytest.approx(0.720, abs=1e-12)


def test_size_run_every_size_or_one(tmp_path, capsys):
    assert main(["geometry", "bmc-roadmachine", "--format", "json"]) == 0
    every = json.loads(capsys.readouterr().out)["bmc-roadmachine"]
    assert list(every) == ["47", "51", "54", "56", "58", "61"]
    assert main(["geometry", "bmc-roadmachine", "--size", "56", "--format", "json"]) == 0
    one = json.loads(capsys.readouterr().out)["bmc-roadmachine"]
    assert one == every["56"]
    assert one["stack"] == pytest.approx(0.590)
    assert main(["geometry", "jamis", "bmc-roadmachine@47"]) == 0
    table = capsys.readouterr().out
    assert "bmc-roadmachine@47" in table and "988.0" in table


BAD_CHARTS = [
    ({"reach": -20}, "chart.reach"),
    ({"head_tube_angle": 120}, "chart.head_tube_angle"),
    ({"chainstay_length": 60}, "chart.chainstay_length"),
    ({"wheelbase": 1030}, "chart.wheelbase"),
    ({"trail": 40}, "chart.trail"),
    ({"stack": 90000}, "chart.stack"),
]


@pytest.mark.parametrize("chart,key", BAD_CHARTS)
def test_bad_charts_one_line_exit_2(tmp_path, capsys, chart, key):
    path = chart_file(tmp_path, chart)
    assert main(["geometry", path]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"road.yaml: {key}: " in err


def test_inconsistent_wheelbase_names_both_values(tmp_path):
    with pytest.raises(InputError) as info:
        load_bicycle(chart_file(tmp_path, {"wheelbase": 1030}))
    built = closed_form_wheelbase(si(ROAD), 0.339) * 1000
    assert number_after(info.value.expected, "within 5 mm of") == pytest.approx(built, abs=0.051)   # to 0.1 mm
    assert "got 1030.0 mm" in info.value.expected


@pytest.mark.parametrize("doc,key", [
    ({"chart": {**ROAD, "head_tube_angle": 72, "wheel": "700c", "tire_width": "28 mm"}}, "chart.head_tube_angle"),
    ({"chart": {**{k: f"{v} mm" for k, v in ROAD.items()}, "wheel": "700c", "tire_width": "28 mm"}},
     "chart.head_tube_angle"),
    ({"chart": {"units": {"length": "mm", "angle": "deg"}, **ROAD, "wheel": "31c", "tire_width": 28}}, "chart.wheel"),
    ({"chart": {"units": {"length": "mm", "angle": "deg"}, **ROAD, "wheel": "700c", "tire_width": 28},
      "geometry": {}}, "geometry"),
    ({"sizes": ["S", "M"], "chart": {"units": {"length": "mm", "angle": "deg"}, **ROAD, "stack": [500, 520, 540],
                                     "wheel": "700c", "tire_width": 28}}, "chart.stack"),
])
def test_bad_chart_files_name_the_key(tmp_path, doc, key):
    path = tmp_path / "bike.yaml"
    path.write_text(yaml.safe_dump({"name": "bad", **doc}))
    size = "S" if "sizes" in doc else None
    with pytest.raises(InputError) as info:
        load_bicycle(str(path), size)
    assert info.value.key == key


def test_size_must_exist(tmp_path, capsys):
    assert main(["geometry", "bmc-roadmachine", "--size", "XXL"]) == 2
    assert "sizes: one of 47, 51, 54, 56, 58, 61" in capsys.readouterr().err
    assert main(["draw", "bmc-roadmachine", "--plot", str(tmp_path / "x.png")]) == 2      # one size to draw
    assert "sizes: a size (BIKE@SIZE" in capsys.readouterr().err
    assert not (tmp_path / "x.png").exists()


def test_params_every_size_or_one(capsys):
    assert main(["params", "bmc-roadmachine", "--format", "json"]) == 0
    every = json.loads(capsys.readouterr().out)
    assert list(every) == ["47", "51", "54", "56", "58", "61", "units"]
    one = {**every["54"], "units": every["units"]}
    assert main(["params", "bmc-roadmachine", "--size", "54", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out) == one
    assert main(["params", "bmc-roadmachine@54", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out) == one
    assert [round(every[s]["w"], 3) for s in every if s != "units"] == [0.982, 0.993, 0.997, 1.008, 1.021, 1.036]


def test_draw_shows_the_chart_dimensions(tmp_path):
    from bikemass.plots.chart import plot_chart
    fig = plot_chart(load_bicycle("bmc-roadmachine@56"))
    texts = {t.get_text() for t in fig.axes[0].texts}
    assert {"stack 590", "reach 388", "wheelbase 1008", "trail 63", "72.0°", "74.2°"} <= texts
    assert main(["draw", "bmc-roadmachine@56", "--plot", str(tmp_path / "side.png")]) == 0


def _chart_bicycle(tmp_path, chart, name="bike.yaml"):
    path = tmp_path / name
    path.write_text(yaml.safe_dump(file_form({"name": "round trip", "chart": chart})))
    return load_bicycle(str(path))


def test_jamis_round_trip_keypoints(tmp_path):
    """Keypoints bicycle -> derived chart -> chart bicycle: the frame points come back (0.5 mm:
    the Jamis's head-tube keypoints sit up to 0.09 mm off its steer axis and 0.002 rad off its
    head angle, which a chart cannot hold)."""
    from bikemass.bicycle.derived_chart import chart_mapping
    jamis = load_bicycle("jamis")
    again = _chart_bicycle(tmp_path, chart_mapping(derived_chart(jamis)))
    pairs = {"bottom_bracket": "bottom_bracket", "head_top": "head_top", "head_bottom": "head_bottom",
             "seat_top": "seat_top", "rear_axle": "rear_axle", "front_axle": "front_axle"}
    for ours, theirs in pairs.items():
        np.testing.assert_allclose(again.keypoints[ours], jamis.keypoints[theirs], atol=5e-4, err_msg=ours)
    assert again.geometry.wheelbase == pytest.approx(0.988, abs=2e-4)
    assert again.geometry.trail == pytest.approx(0.060, abs=2e-4)


chart_values = {
    "stack": (0.45, 0.75), "reach": (0.33, 0.46), "head_tube_angle": (67.0, 75.0),
    "seat_tube_angle": (71.0, 76.0), "head_tube_length": (0.09, 0.25), "seat_tube_length": (0.42, 0.62),
    "chainstay_length": (0.40, 0.48), "bb_drop": (0.03, 0.085), "fork_offset": (0.035, 0.06),
    "wheel_radius": (0.30, 0.37),
}


def test_round_trip_on_generated_charts(tmp_path):
    """Property: chart -> keypoints bicycle -> derived chart -> chart bicycle gives the same
    keypoints (1e-9 m) and the same chart (1e-9 m, 1e-9 deg), on seeded generated charts."""
    from hypothesis import given, settings
    from hypothesis import strategies as st

    from bikemass.bicycle.derived_chart import chart_mapping

    @settings(max_examples=8, derandomize=True, deadline=None, database=None)
    @given(st.fixed_dictionaries({k: st.floats(*r) for k, r in chart_values.items()}))
    def check(values):
        chart = {k: f"{v!r} {'deg' if k.endswith('_angle') else 'm'}" for k, v in values.items()}
        first = _chart_bicycle(tmp_path, chart, "first.yaml")
        derived = derived_chart(first)
        second = _chart_bicycle(tmp_path, chart_mapping(derived), "second.yaml")
        assert first.keypoints.keys() == second.keypoints.keys()
        for key, point in first.keypoints.items():
            np.testing.assert_allclose(second.keypoints[key], point, atol=1e-9, err_msg=key)
        again = derived_chart(second)
        for key, value in values.items():
            if key != "wheel_radius":
                assert derived[key] == pytest.approx(value if "angle" not in key else value, abs=1e-9)
            assert again.get(key, again["rear_wheel_radius"]) == pytest.approx(
                derived.get(key, derived["rear_wheel_radius"]), abs=1e-9)

    check()


def _docs_yaml_after(heading):
    text = (ROOT / "docs" / "bicycles.md").read_text()
    block = text.split(heading, 1)[1].split("```yaml\n", 1)[1].split("```", 1)[0]
    return yaml.safe_load(block)


def test_docs_examples_load(tmp_path):
    """The chart example and the overrides example of docs/bicycles.md build bicycles."""
    example = _docs_yaml_after("## Geometry charts")
    path = tmp_path / "example.yaml"
    path.write_text(yaml.safe_dump(example))
    bike = load_bicycle(str(path))
    assert bike.geometry.wheelbase == pytest.approx(1.0078, abs=1e-4)
    overrides = _docs_yaml_after("### Defaults and how to override them")
    overrides["materials"] = {"my_alloy": {"E": "72 GPa", "nu": 0.33, "density": "2.8 g/cm^3"}}
    path.write_text(yaml.safe_dump({**example, **overrides}))
    custom = load_bicycle(str(path))
    assert "bar_ends" in custom.contacts.grips and "pedals" not in {p.name for p in custom.parts}
    assert {t.material.key for t in custom.tubes if t.name == "down_tube"} == {"my_alloy"}


def test_docs_tables_hold_the_defaults():
    """The tubeset, wheel and component tables of docs/bicycles.md list chart_defaults.yaml."""
    text = (ROOT / "docs" / "bicycles.md").read_text()
    d = yaml.safe_load((ROOT / "frames" / "chart_defaults.yaml").read_text())
    for name, tubeset in d["tubesets"].items():
        row = next(line for line in text.splitlines() if line.startswith(f"| `{name}` |"))
        for spec in tubeset["sections"].values():
            assert f"{spec['outer_diameter'].split()[0]} x {spec['wall'].split()[0]}" in row
    for bsd, wheel in d["wheels"]["sizes"].items():
        row = next(line for line in text.splitlines() if line.startswith(f"| {bsd} |"))
        assert all(wheel[k].split()[0] in row for k in ("rim", "spokes", "tire", "reference_width"))
    for name, component in d["components"].items():
        row = next(line for line in text.splitlines() if line.startswith(f"| `{name}` |"))
        assert component["mass"].split()[0] in row


def test_geometry_plot_and_quiet(tmp_path, capsys):
    path = tmp_path / "chart.svg"
    assert main(["geometry", "bmc-roadmachine", "--size", "56", "--plot", str(path), "--quiet"]) == 0
    assert capsys.readouterr().out == "" and "stack 590" in path.read_text()
    assert main(["geometry", "jamis", "--format", "csv"]) == 0
    rows = {r.split(",")[0]: r.split(",") for r in capsys.readouterr().out.splitlines()}
    assert rows["wheelbase"][1:] == ["mm", "988.000"]


def test_frame_commands_take_a_size(capsys):
    assert main(["stiffness", "specialized-diverge", "--material", "carbon", "--format", "json"]) == 0
    every = json.loads(capsys.readouterr().out)
    assert list(every) == ["48", "52", "54", "56", "58", "61", "64", "units"]
    S = np.array(every["56"]["S"])
    assert np.all(np.linalg.eigvalsh(S) > 0)                 # the chart bicycle's beam model is sound
    assert main(["stiffness", "specialized-diverge", "--bike-size", "56", "--material", "carbon",
                 "--format", "json"]) == 0
    np.testing.assert_array_equal(json.loads(capsys.readouterr().out)["S"], S)


def test_stability_of_a_chart_file_with_a_seated_rider(capsys):
    """A shipped posture seated on a chart bicycle (contacts within 1 mm) and its weave speed."""
    path = str(ROOT / "frames" / "bmc_roadmachine.yaml")
    assert main(["stability", path, "--bike-size", "56", "--rider", "relaxed", "--speeds", "0:15:0.25",
                 "--format", "json"]) == 0
    result = json.loads(capsys.readouterr().out)
    assert len(result["weave_speeds"]) == 1 and 4 < result["weave_speeds"][0] < 7
