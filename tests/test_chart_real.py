"""Real bicycles that charts describe but an earlier reading of them refused or got wrong."""

import pytest
import yaml

from bikemass.bicycle import load_bicycle
from bikemass.cli import main


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
