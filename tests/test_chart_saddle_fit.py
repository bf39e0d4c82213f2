"""Riders of every size seated on real chart bicycles: the saddle is fitted to each rider.

A geometry chart does not say how high its rider sits.  The BMC Roadmachine (2017) chart
(shipped as ``frames/bmc_roadmachine.yaml``; BMC's published chart as transcribed in
github.com/smopucilowski/bikegeo, bmc/roadmachine/year_2017.py) used to put every rider on
a saddle at 1.28 x stack: a 1.60 m woman could not reach the pedals of the 61 (38.8 mm
short) and a 1.95 m man sat 130 mm too low on the 47 without a word.
"""

import numpy as np
import pytest

import bikemass as bm
from bikemass.bicycle import load_bicycle
from bikemass.bicycle.contacts import SADDLE_RULES
from bikemass.core.config import Node
from bikemass.rider.body import load_body
from bikemass.rider.seating import CONTACT_TOLERANCE, seat_rider

PEOPLE = {"woman 1.60 m": {"height": "1.60 m", "mass": "55 kg", "sex": "female"},
          "man 1.95 m": {"height": "1.95 m", "mass": "95 kg", "sex": "male"}}


def _inseam(body):
    return load_body(Node(body, "<test>", "body")).chain.inseam


@pytest.mark.parametrize("size", ["47", "61"])
@pytest.mark.parametrize("person", list(PEOPLE))
def test_every_rider_sits_on_a_saddle_fitted_to_their_inseam(size, person):
    bike = load_bicycle(f"bmc-roadmachine@{size}")
    body = PEOPLE[person]
    seated = seat_rider({"body": body, "chain": {"hands": "hoods"}}, bike)
    assert max(seated.residuals().values()) <= CONTACT_TOLERANCE
    d = seated.solution.pose.points()["seat"] - bike.contacts.bottom_bracket
    assert np.linalg.norm(d) == pytest.approx(SADDLE_RULES["lemond"] * _inseam(body), abs=1e-9)
    # up the seat tube: the chart's 74.2 deg seat angle (setback 0)
    assert np.degrees(np.arctan2(-d[2], -d[0])) == pytest.approx(74.2, abs=1e-9)


def test_a_saddle_height_in_the_file_fixes_the_sit_point(tmp_path):
    text = open(load_bicycle("bmc-roadmachine@56").source).read()
    path = tmp_path / "fixed.yaml"
    path.write_text(text + "saddle: {height: 755 mm, setback: 20 mm}\n")
    bike = load_bicycle(f"{path}@56")
    assert bike.contacts.saddle_fit is None
    bb = bike.contacts.bottom_bracket
    sa = np.radians(74.2)
    expected = bb + 0.755 * np.array([-np.cos(sa), 0.0, -np.sin(sa)]) - [0.020, 0.0, 0.0]
    assert np.allclose(bike.contacts.saddle, expected, atol=1e-12)


def test_a_fitted_saddle_keeps_the_files_setback(tmp_path):
    text = open(load_bicycle("bmc-roadmachine@56").source).read()
    path = tmp_path / "setback.yaml"
    path.write_text(text + "saddle: {setback: 30 mm}\n")
    bike = load_bicycle(f"{path}@56")
    plain = load_bicycle("bmc-roadmachine@56").contacts
    for inseam in (0.75, 0.90):
        moved = bike.contacts.sit_point(inseam) - plain.sit_point(inseam)
        assert np.allclose(moved, [-0.030, 0.0, 0.0], atol=1e-12)


def test_small_and_tall_riders_get_a_weave_speed_on_the_61():
    """Whole path: the 1.60 m woman on the 61 (refused before) has a weave speed in the
    usual 4-7 m/s of an adult on a road bicycle."""
    p = bm.parameters("bmc-roadmachine@61", {"body": PEOPLE["woman 1.60 m"], "chain": {"hands": "hoods"}})
    weave = bm.stability(p).weave_speeds
    assert len(weave) == 1 and 4.0 < weave[0] < 7.0


def test_the_saddle_goes_no_lower_than_the_seat_tube():
    """A 1.25 m child on the 61 (seat tube 573 mm + 40 mm of saddle): LeMond's 0.883 x
    inseam would put the saddle inside the frame; it stops at 613 mm, out of the child's
    reach, which is one error naming the shortfall."""
    from bikemass.core.errors import InputError
    bike = load_bicycle("bmc-roadmachine@61")
    child = {"height": "1.25 m", "mass": "25 kg", "sex": "male"}
    assert SADDLE_RULES["lemond"] * _inseam(child) < 0.613
    d = bike.contacts.sit_point(_inseam(child)) - bike.contacts.bottom_bracket
    assert np.linalg.norm(d) == pytest.approx(0.573 + 0.040, abs=1e-12)
    with pytest.raises(InputError, match=r"feet out of reach by [0-9.]+ mm \(saddle too high"):
        seat_rider({"body": child, "chain": {"hands": "hoods"}}, bike)
