"""The fit check (bikemass.rider.fit): seat post showing, a saddle that cannot go low enough,
locked elbows and toe overlap, each against the closed form of the bicycle's and rider's numbers."""

import warnings

import numpy as np
import pytest
import yaml

import bikemass as bm
from bikemass.bicycle.contacts import SADDLE_RULES
from bikemass.core.errors import BikemassWarning
from bikemass.rider.fit import (FOOT_PER_INSEAM, MAX_EXPOSED_POST, SHOE, TOE_AHEAD_OF_BALL, fit_warnings,
                                toe_overlap)
from hostile.generators import KIDS_CHART


def _seated(bike, rider):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        seated = bm.seated_rider(bike, rider)
    return seated, [str(w.message) for w in caught if issubclass(w.category, BikemassWarning)]


def _body(height):
    return {"body": {"height": f"{height} m", "mass": "70 kg", "sex": "male"}, "chain": {"hands": "tops"}}


def _inseam(rider, bike):
    from bikemass.core.config import Node
    from bikemass.rider.body import load_body
    return load_body(Node(rider["body"], "<mapping>", "body")).chain.inseam


def test_a_tall_rider_on_a_kids_bicycle_shows_the_seat_post_a_fitter_would_see():
    """The post showing is LeMond's saddle height (0.883 x inseam) less the seat tube and the saddle's
    stack (40 mm, frames/chart_defaults.yaml): the 1.78 m rider's, to 0.5 mm."""
    bike = bm.load_bicycle(KIDS_CHART)
    rider = _body(1.78)
    _, lines = _seated(bike, rider)
    expected = SADDLE_RULES["lemond"] * _inseam(rider, bike) - 0.280 - 0.040
    assert expected > MAX_EXPOSED_POST
    (line,) = [line for line in lines if "seat post showing" in line]
    assert f"{expected * 1000:.0f} mm of seat post showing" in line and "the frame is too small" in line


def test_a_rider_the_kids_bicycle_fits_gets_no_fit_warning():
    _, lines = _seated(bm.load_bicycle(KIDS_CHART), _body(1.30))
    assert not [line for line in lines if "for rider" in line]


def test_a_frame_too_big_is_warned_about_when_the_legs_still_reach():
    """BMC Roadmachine 61: the lowest saddle is the 573 mm seat tube plus 40 mm of saddle; a rider
    whose LeMond height is below that but who still reaches the pedals is told the frame is too big."""
    bike = bm.load_bicycle("bmc-roadmachine@61")
    lowest = bike.contacts.saddle_fit[3]
    for height in np.arange(1.20, 1.80, 0.02):
        rider = _body(round(float(height), 2))
        wanted = SADDLE_RULES["lemond"] * _inseam(rider, bike)
        try:
            _, lines = _seated(bike, rider)
        except bm.InputError:
            continue                                   # out of reach: the seating's error
        if lowest - wanted > 0.02:
            assert any(f"{(lowest - wanted) * 1000:.0f} mm above the rider's saddle height" in line
                       for line in lines)
            return
    pytest.fail("no rider between 1.20 and 1.80 m both reaches the pedals and is too short for the frame")


def test_toe_overlap_is_the_closed_form():
    """Toe = pedal spindle of the forward crank + 0.27 foot + shoe; overlap = front wheel radius less
    its distance to the front axle (side view)."""
    bike = bm.load_bicycle(KIDS_CHART)
    inseam = 0.70
    c, g = bike.contacts, bike.geometry
    toe_x = c.bottom_bracket[0] + c.crank_length + TOE_AHEAD_OF_BALL * FOOT_PER_INSEAM * inseam + SHOE
    gap = np.hypot(g.front_axle[0] - toe_x, g.front_axle[2] - c.bottom_bracket[2])
    assert toe_overlap(bike, c, inseam) == pytest.approx(max(0.0, g.front_wheel_radius - gap), abs=1e-12)
    short = bm.load_bicycle({**KIDS_CHART, "chart": {**KIDS_CHART["chart"], "reach": 200, "head_tube_angle": 75}})
    assert toe_overlap(short, short.contacts, inseam) > toe_overlap(bike, c, inseam)


def test_a_toe_overlap_beyond_the_shoes_give_is_warned_about():
    short = bm.load_bicycle({**KIDS_CHART, "chart": {**KIDS_CHART["chart"], "reach": 200, "head_tube_angle": 75}})
    rider = _body(1.35)
    overlap = toe_overlap(short, short.contacts, _inseam(rider, short))
    _, lines = _seated(short, rider)
    if overlap > 0.02:
        assert any(f"toe overlap: the toe reaches {overlap * 1000:.0f} mm" in line for line in lines)
    else:
        pytest.skip(f"this frame overlaps {overlap * 1000:.0f} mm only")


def test_no_contacts_no_fit_check():
    assert fit_warnings(bm.load_bicycle("benchmark"), None, None, "nobody") == []


def test_the_fit_warnings_reach_the_command_line_and_the_web(tmp_path, capsys):
    from bikemass.cli.main import main
    bike, rider = tmp_path / "kids.yaml", tmp_path / "tall.yaml"
    bike.write_text(yaml.safe_dump(KIDS_CHART))
    rider.write_text(yaml.safe_dump(_body(1.78)))
    assert main(["params", str(bike), "--rider", str(rider), "--format", "json"]) == 0
    out, err = capsys.readouterr()
    import json
    assert any("seat post showing" in w for w in json.loads(out)["warnings"]) and "seat post showing" in err
