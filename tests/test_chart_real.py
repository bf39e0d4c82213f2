"""Real bicycles that charts describe but an earlier reading of them refused or got wrong."""

import pytest
import yaml

from bikemass.bicycle import load_bicycle
from bikemass.cli.main import main


def _folding(tmp_path, stem_length):
    """A 16 in folding bicycle (ISO 349 wheels) whose bars sit on a tall stem post, the
    layout of the Brompton: no forward stem at all (stem_length 0)."""
    doc = {"name": "folding 349", "chart": {
        "units": {"length": "mm", "angle": "deg"}, "stack": 330, "reach": 380, "head_tube_angle": 72,
        "seat_tube_angle": 71, "head_tube_length": 120, "seat_tube_length": 330, "chainstay_length": 420,
        "bb_drop": -55, "fork_offset": 30, "wheel": "349 mm", "tire_width": 35},
        "cockpit": {"bar": "flat", "spacers": "400 mm", "stem_length": stem_length, "stem_angle": "0 deg",
                    "bar_width": "560 mm", "bar_sweep": "60 mm"}}
    path = tmp_path / "folding.yaml"
    path.write_text(yaml.safe_dump(doc))
    return str(path)


def test_bars_on_the_steerer_without_a_stem(tmp_path):
    bike = load_bicycle(_folding(tmp_path, "0 mm"))
    tubes = {t.name for t in bike.tubes}
    assert "stem" not in tubes and {"handlebar_left", "handlebar_right", "steerer"} <= tubes
    assert bike.geometry.rear_wheel_radius == pytest.approx(0.1745 + 0.035, abs=1e-12)


def test_a_negative_stem_is_one_line_naming_the_cockpit_key(tmp_path, capsys):
    code = main(["params", _folding(tmp_path, "-10 mm")])
    err = capsys.readouterr().err.strip()
    assert code == 2 and len(err.splitlines()) == 1 and "cockpit.stem_length" in err, err


ALLEZ_SPRINT_56 = {  # mm, deg: Specialized's published chart, as in github.com/geometrygeeks/visual-comparison
    "stack": 554, "reach": 395, "top_tube_length": 554, "seat_tube_length": 520, "head_tube_angle": 73.5,
    "seat_tube_angle": 74, "head_tube_length": 150, "chainstay_length": 405, "wheelbase": 984,
    "bb_drop": 69, "bb_height": 272, "fork_offset": 44, "trail": 55}
LENGTHS = [k for k in ALLEZ_SPRINT_56 if not k.endswith("_angle")]


def _allez(tmp_path, name, unit, wheel, tire_width):
    """The Specialized Allez Sprint 56 chart (src/default-input-bikes.js of
    github.com/geometrygeeks/visual-comparison), lengths in ``unit`` (mm or in)."""
    per_mm = {"mm": 1.0, "in": 1 / 25.4}[unit]
    chart = {k: v * per_mm if k in LENGTHS else v for k, v in ALLEZ_SPRINT_56.items()}
    doc = {"name": "Allez Sprint 56", "chart": {"units": {"length": unit, "angle": "deg"}, **chart,
                                                "wheel": wheel, "tire_width": tire_width}}
    path = tmp_path / f"{name}.yaml"
    path.write_text(yaml.safe_dump(doc))
    return str(path)


def test_the_same_chart_in_inches_or_millimetres_gives_the_same_bicycle(tmp_path):
    from bikemass.scenario.scenario import parameters
    mm = parameters(_allez(tmp_path, "mm", "mm", "700c", 28)).to_dict()
    inch = parameters(_allez(tmp_path, "in", "in", "622 mm", 28 / 25.4)).to_dict()
    for key, value in mm.items():     # 1e-9: floating-point rounding of mm -> in -> m (and the meshes built on it)
        assert inch[key] == pytest.approx(value, rel=1e-9, abs=1e-12), key


@pytest.mark.parametrize("wheel", ["700c", "700 C", "29er", "29 inch", '29"', 622, "622mm", "62.2 cm", "0.622 m"])
def test_every_way_of_writing_the_622_wheel_is_the_same_wheel(tmp_path, wheel):
    """A bare 622 is in the chart's ``units: {length: mm}``, like every other bare length."""
    bike = load_bicycle(_allez(tmp_path, "w", "mm", wheel, 28))
    assert bike.geometry.rear_wheel_radius == pytest.approx(0.311 + 0.028, abs=1e-12)


@pytest.mark.parametrize("wheel,bsd", [(12, 203), (14, 254), (18, 355), (27, 630), ("349 mm", 349)])
def test_childrens_folding_and_old_road_wheels(tmp_path, wheel, bsd):
    doc = {"name": "small", "chart": {
        "units": {"length": "mm", "angle": "deg"}, "stack": 400, "reach": 300, "head_tube_angle": 70,
        "seat_tube_angle": 72, "head_tube_length": 90, "seat_tube_length": 250, "chainstay_length": 330,
        "bb_drop": -20, "fork_offset": 35, "wheel": wheel, "tire_width": 40}}
    path = tmp_path / "small.yaml"
    path.write_text(yaml.safe_dump(doc))
    assert load_bicycle(str(path)).geometry.rear_wheel_radius == pytest.approx(bsd / 2000 + 0.040, abs=1e-12)


def test_bb_height_and_trail_stand_in_for_bb_drop_and_fork_offset(tmp_path):
    """Charts that print BB height and trail (children's, city and mountain bicycles often do)
    but not BB drop or fork offset.  The Allez Sprint 56 so written: its own published
    wheelbase (984 mm) is still met, and the BB drop and offset come back within what the
    printed trail's rounding allows."""
    path = _allez(tmp_path, "heights", "mm", "700c", 28)
    doc = yaml.safe_load(open(path))
    del doc["chart"]["bb_drop"], doc["chart"]["fork_offset"]
    open(path, "w").write(yaml.safe_dump(doc))
    from bikemass.bicycle.derived_chart import derived_chart
    d = derived_chart(load_bicycle(path))
    assert d["bb_drop"] == pytest.approx(0.339 - 0.272, abs=1e-12)
    assert d["trail"] == pytest.approx(0.055, abs=1e-12)
    assert d["fork_offset"] == pytest.approx(0.044, abs=0.001)
    assert d["wheelbase"] == pytest.approx(0.984, abs=0.005)


def test_neither_bb_drop_nor_bb_height_names_both(tmp_path, capsys):
    path = _allez(tmp_path, "none", "mm", "700c", 28)
    doc = yaml.safe_load(open(path))
    del doc["chart"]["bb_drop"], doc["chart"]["bb_height"]
    open(path, "w").write(yaml.safe_dump(doc))
    assert main(["geometry", path]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "chart.bb_drop: a required key that is missing (or bb_height instead)" in err


def test_a_rider_asking_for_the_hoods_holds_a_flat_bar(tmp_path):
    """A flat-bar chart bicycle (the folding 349 above) seats ``chain: {hands: hoods}``, the
    form of the rider issue's examples, on its one grip, as the Cargo's flat bar does."""
    from bikemass.rider.seating import CONTACT_TOLERANCE, seat_rider
    bike = load_bicycle(_folding(tmp_path, "0 mm"))
    assert set(bike.contacts.grips) == {"tops", "hoods"}
    assert (bike.contacts.grips["tops"] == bike.contacts.grips["hoods"]).all()
    seated = seat_rider({"body": {"height": "1.70 m", "mass": "65 kg", "sex": "female"},
                         "chain": {"hands": "hoods"}}, bike)
    assert max(seated.residuals().values()) <= CONTACT_TOLERANCE
