"""Fit checks a new user meets (issue 35): standover against the rider's inseam, a chart ridden
on another tyre than the one it was measured with, and EN 15194's front-wheel load.

References: the manufacturer's published standover (Specialized Diverge 2018 chart, checked to
35 mm, frames/specialized_diverge.yaml); ANSUR II's inseam per stature (0.48); ISO 5775's bead
seat diameter of a 650b rim (584 mm); Meijaard et al. (2007) Table 1's masses and centres of
mass, summed by hand."""

import math
import warnings

import pytest

import bikemass as bm
from bikemass.bicycle.derived_chart import derived_chart
from bikemass.cli.main import main
from bikemass.core.errors import BikemassWarning
from bikemass.models.plausibility import EN15194_FRONT_SHARE, front_load

DIVERGE_56 = """\
name: Diverge 56 on {wheel} x {tire}
chart:
  units: {{length: mm, angle: deg}}
  stack: 613
  reach: 379
  head_tube_length: 178
  head_tube_angle: 72.5
  bb_height: 265
  bb_drop: 85
  trail: 58
  fork_offset: 50
  front_center: 604
  chainstay_length: 421
  wheelbase: 1011
  top_tube_length: 561
  seat_tube_length: 500
  seat_tube_angle: 73.5
  wheel: {wheel}
  tire_width: {tire}
frame: {{tubeset: carbon}}
brakes: disc
"""


def _caught(call):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = call()
    return result, [str(w.message) for w in caught if issubclass(w.category, BikemassWarning)]


def _body_pose(tmp_path, height, mass, sex):
    path = tmp_path / f"body{height}.yaml"
    path.write_text(f"body: {{height: {height} m, mass: {mass} kg, sex: {sex}}}\nchain: {{torso_lean: 40 deg, "
                    "hands: hoods}\n")
    return path


# -- standover -----------------------------------------------------------------------------------

def test_a_small_rider_on_a_tall_frame_is_warned_about_standover(tmp_path):
    """A 1.45 m rider on the 64 cm Diverge (standover published 846 mm): the top tube is far above
    the crotch; the warning gives the standover (the published one within the chart's 35 mm) and
    an inseam that is 0.48 +- 0.02 of the stature (ANSUR II)."""
    bike = "specialized-diverge@64"
    pose = _body_pose(tmp_path, 1.45, 45, "female")
    _, lines = _caught(lambda: bm.parameters(bike, str(pose)))
    standover = [line for line in lines if "standover" in line]
    assert len(standover) == 1, lines
    height, above, inseam = (float(x) for x in __import__("re").search(
        r"top tube is (\d+) mm above the ground, (\d+) mm above the crotch .*\(inseam (\d+) mm", standover[0]).groups())
    assert abs(height - 846) <= 35                           # the published standover, the chart's tolerance
    assert abs(inseam / 1450 - 0.48) <= 0.02                  # ANSUR II inseam per stature
    assert abs(above - (height - inseam - 10)) <= 1           # 10 mm of shoe; rounding of three printed numbers
    assert "too big" in standover[0]


def test_a_rider_who_clears_the_top_tube_gets_no_standover_warning(tmp_path):
    pose = _body_pose(tmp_path, 1.85, 80, "male")
    _, lines = _caught(lambda: bm.parameters("specialized-diverge@64", str(pose)))
    assert not [line for line in lines if "standover" in line], lines


def test_standover_clearance_is_inseam_plus_sole_less_standover():
    from bikemass.rider.fit import SOLE, standover_clearance, standover_height
    bicycle = bm.load_bicycle("specialized-diverge@64")
    assert standover_clearance(bicycle, 0.70) == pytest.approx(0.70 + SOLE - standover_height(bicycle), abs=1e-15)
    assert standover_clearance(bm.load_bicycle("benchmark"), 0.8) is None      # no top tube: no check


# -- a chart on another tyre ---------------------------------------------------------------------

def test_a_650b_tyre_on_a_700c_chart_is_built_and_warned_about(tmp_path):
    """The Diverge's chart (BB height 265 mm with 85 mm drop: measured on a 350 mm wheel) with a
    real 650b x 47 tyre: radius 584/2 + 47 = 339 mm (ISO 5775).  Built, not refused: the BB sits
    11 mm lower (254 mm), the trail 11 cot(72.5 deg) = 3.47 mm shorter; the published values are
    checked on the stock wheel; one warning says so."""
    path = tmp_path / "diverge650b.yaml"
    path.write_text(DIVERGE_56.format(wheel="650b", tire=47))
    bicycle, lines = _caught(lambda: bm.load_bicycle(str(path)))
    chart = derived_chart(bicycle)
    radius = 0.584 / 2 + 0.047
    assert bicycle.geometry.rear_wheel_radius == pytest.approx(radius, abs=1e-12)
    assert chart["bb_height"] == pytest.approx(0.265 - (0.350 - radius), abs=1e-9)
    stock = derived_chart(bm.load_bicycle("specialized-diverge@56"))
    drop = stock["rear_wheel_radius"] - radius              # the shipped 700c x 38 wheel: 311 + 38 mm
    assert chart["trail"] == pytest.approx(stock["trail"] - drop / math.tan(math.radians(72.5)), abs=1e-9)
    assert chart["wheelbase"] == pytest.approx(stock["wheelbase"], abs=1e-9)    # the frame is the frame
    tyre = [line for line in lines if "chart.wheel" in line]
    assert len(tyre) == 1 and "350.0 mm" in tyre[0] and "339.0 mm" in tyre[0] and "265.0 -> 254.0 mm" in tyre[0]


@pytest.mark.parametrize("wheel, tire", [("700c", 25), ("29", 60), ("650b", 38)])
def test_other_real_tyres_on_the_chart_are_accepted(tmp_path, wheel, tire):
    path = tmp_path / "d.yaml"
    path.write_text(DIVERGE_56.format(wheel=wheel, tire=tire))
    assert main(["geometry", str(path), "--format", "json", "--quiet"]) == 0


def test_the_stock_tyre_gives_no_warning_and_a_wheel_far_off_is_still_refused(tmp_path, capsys):
    path = tmp_path / "d.yaml"
    path.write_text(DIVERGE_56.format(wheel="700c", tire=38))
    _, lines = _caught(lambda: bm.load_bicycle(str(path)))
    assert lines == []
    path.write_text(DIVERGE_56.format(wheel="20", tire=50))       # a 20-inch wheel: not the same frame's tyre
    assert main(["geometry", str(path)]) == 2
    err = capsys.readouterr().err
    assert "chart.trail: a trail within 3 mm" in err and err.count("\n") == 1      # refused, in one line


# -- EN 15194: the front wheel's share of the weight ---------------------------------------------

def test_front_load_of_the_benchmark_by_hand():
    """Meijaard et al. 2007 Table 1: masses 2, 85, 4, 3 kg; xB 0.3, xH 0.9, front wheel at w = 1.02 m.
    Moments about the rear contact: (85 x 0.3 + 4 x 0.9 + 3 x 1.02) / (94 x 1.02)."""
    share, kg = front_load(bm.parameters("benchmark"))
    assert share == pytest.approx((85 * 0.3 + 4 * 0.9 + 3 * 1.02) / (94 * 1.02), abs=1e-12)
    assert kg == pytest.approx(94 * share, abs=1e-12)


def test_front_load_matches_the_static_contact_forces():
    """An independent reference: the vertical contact forces of the rigid bicycle standing on
    level ground, each body's weight shared between the contacts by its lever (statics, per body)."""
    p = bm.parameters("jamis", "relaxed")
    front = p.mF + p.mH * p.xH / p.w + p.mB * p.xB / p.w
    total = p.mR + p.mB + p.mH + p.mF
    share, kg = front_load(p)
    assert kg == pytest.approx(front, rel=1e-12) and share == pytest.approx(front / total, rel=1e-12)


def test_a_rear_heavy_rider_position_is_warned_about(capsys):
    """The Cargo bike with the no-hands rider puts 20.5 % on the front wheel: warned; the Jamis with
    the relaxed rider 37 %: not."""
    _, lines = _caught(lambda: bm.parameters("cargo", "no-hands"))
    share, _ = front_load(bm.parameters("cargo", "no-hands"))
    assert share < EN15194_FRONT_SHARE
    assert [line for line in lines if "EN 15194" in line] and f"{share * 100:.1f} %" in lines[-1]
    _, lines = _caught(lambda: bm.parameters("jamis", "relaxed"))
    assert not [line for line in lines if "EN 15194" in line]


def test_params_table_shows_the_front_load(capsys):
    assert main(["params", "jamis", "--rider", "relaxed", "--format", "table"]) == 0
    out = capsys.readouterr().out
    share, kg = front_load(bm.parameters("jamis", "relaxed"))
    assert f"front wheel load: {share * 100:.1f} % of the weight ({kg:.2f} kg) (meets EN 15194" in out
    assert main(["params", "cargo", "--rider", "no-hands", "--format", "table"]) == 0
    captured = capsys.readouterr()
    assert "(BELOW EN 15194" in captured.out and "EN 15194" in captured.err


def test_a_rider_too_small_to_reach_the_pedals_hears_about_standover_too(tmp_path, capsys):
    """The Jamis's fixed saddle is out of a 1.45 m rider's reach: refused in one line, which also
    says the top tube stands above the rider's crotch."""
    pose = _body_pose(tmp_path, 1.45, 45, "female")
    pose.write_text(pose.read_text().replace("torso_lean: 40 deg, ", ""))
    assert main(["stability", "jamis", "--rider", str(pose), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "feet out of reach" in err and "(standover)" in err
