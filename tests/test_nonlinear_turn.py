"""Steady turns of the nonlinear Whipple bicycle (bm.steady_turn, bm.hands_free_turns) against the
linear model's limit and the nonlinear simulator.

- Wide circles: the nonlinear lean, steer and steer torque tend to the linear model's steady turn
  (``(g K0 + v^2 K2) [phi, delta] = [0, T]`` with the yaw rate ``v delta cos(lam) / w``) with an
  error of the order of the lean squared (the bicycle's symmetry removes the first-order one): ten
  times the radius, a hundredth of the relative difference (to 5 %).
- Hands-free circles start, at zero steer, at the speed where ``det(g K0 + v^2 K2)`` vanishes: the
  benchmark's linear capsize speed, 6.0243 m/s (Meijaard et al. 2007; here from the eigenvalues,
  bm.stability, to 1e-6 m/s), approached as the steer angle squared.
- A steady turn is a solution of the equations of motion: simulated from it (with its steer torque
  held), the lean and steer stay put for 0.5 s to 1e-7 rad.
"""

import json
import warnings
import math
from pathlib import Path

import numpy as np
import pytest

import bikemass as bm
from bikemass.core.errors import InputError


@pytest.fixture(scope="module")
def meijaard():
    return bm.parameters("benchmark")


def _relative(turn):
    return max(abs(turn.roll / turn.linear_roll - 1), abs(turn.steer / turn.linear_steer - 1),
               abs(turn.steer_torque / turn.linear_steer_torque - 1))


@pytest.mark.parametrize("speed", [3.0, 5.0, 8.0])
def test_wide_circles_tend_to_the_linear_steady_turn(meijaard, speed):
    wide, wider = bm.steady_turn(meijaard, speed, radius=300.0), bm.steady_turn(meijaard, speed, radius=3000.0)
    assert wide.radius == pytest.approx(300.0, rel=1e-9) and wider.yaw_rate == pytest.approx(speed / 3000.0, rel=1e-9)
    assert _relative(wide) < 1e-3                         # measured 1.1e-4 at 3 m/s
    assert _relative(wide) / _relative(wider) == pytest.approx(100.0, rel=0.05)


def test_a_left_turn_mirrors_a_right_turn(meijaard):
    right, left = bm.steady_turn(meijaard, 5.0, radius=20.0), bm.steady_turn(meijaard, 5.0, radius=-20.0)
    for name in ("roll", "steer", "steer_torque", "yaw_rate"):
        assert getattr(left, name) == pytest.approx(-getattr(right, name), rel=1e-9)
    assert left.pitch == pytest.approx(right.pitch, rel=1e-9)


def test_a_steer_angle_gives_the_same_turn_as_its_radius(meijaard):
    by_steer = bm.steady_turn(meijaard, 4.0, steer=0.1)
    by_radius = bm.steady_turn(meijaard, 4.0, radius=by_steer.radius)
    assert by_radius.roll == pytest.approx(by_steer.roll, abs=1e-9)
    assert by_radius.steer == pytest.approx(0.1, abs=1e-9)


def test_hands_free_circles_start_at_the_capsize_speed(meijaard):
    capsize = bm.stability(meijaard).capsize_speeds[0]
    family = bm.hands_free_turns(meijaard, [0.004, 0.002, 0.02, 0.2])
    assert family.capsize_speed == pytest.approx(capsize, abs=1e-6)
    assert family.capsize_speed == pytest.approx(6.0243, abs=5e-5)
    gaps = np.abs(family.speed[:2] - family.capsize_speed)
    assert gaps[0] / gaps[1] == pytest.approx(4.0, rel=0.05)
    assert np.all(np.isfinite(family.speed)) and np.all(np.diff(family.speed[1:]) < 0)


def test_a_steady_turn_stays_steady_when_simulated(meijaard):
    turn = bm.steady_turn(meijaard, 5.0, radius=15.0)
    r = bm.simulate(meijaard, 5.0, initial={"roll-angle": turn.roll, "steer-angle": turn.steer},
                    inputs={"steer-torque": ("step", turn.steer_torque)}, duration=0.5, nonlinear=True)
    np.testing.assert_allclose(r["roll-angle"], turn.roll, atol=1e-7)
    np.testing.assert_allclose(r["steer-angle"], turn.steer, atol=1e-7)
    np.testing.assert_allclose(r["forward-speed"], 5.0, atol=1e-7)
    assert r["heading"][-1] == pytest.approx(turn.yaw_rate * 0.5, rel=1e-6)


def test_hands_free_circles_need_no_torque(meijaard):
    family = bm.hands_free_turns(meijaard, [0.15])
    turn = bm.steady_turn(meijaard, float(family.speed[0]), steer=0.15)
    assert turn.steer_torque == pytest.approx(0.0, abs=1e-8)
    assert turn.roll == pytest.approx(family.roll[0], abs=1e-9)


def test_bad_input_is_refused(meijaard):
    with pytest.raises(InputError, match="exactly one"):
        bm.steady_turn(meijaard, 5.0)
    with pytest.raises(InputError, match="exactly one"):
        bm.steady_turn(meijaard, 5.0, radius=10.0, steer=0.1)
    with pytest.raises(InputError, match="not 0"):
        bm.steady_turn(meijaard, 5.0, radius=0.0)
    with pytest.raises(InputError, match="a radius with a steady turn at 5 m/s"):    # tighter than any upright turn
        bm.steady_turn(meijaard, 5.0, radius=0.3)
    with pytest.raises(InputError):
        bm.steady_turn(meijaard, 0.0, radius=10.0)
    with pytest.raises(InputError, match="nonzero"):
        bm.hands_free_turns(meijaard, [0.0, 0.1])
    with pytest.raises(InputError):
        bm.steady_turn(meijaard, 5.0, steer=math.pi)


def test_the_hands_free_family_ends_at_a_static_equilibrium_and_says_so(meijaard, capsys):
    """Basu-Mandal et al. (2007): the handlebar-forward family ends in a static equilibrium (speed 0,
    frame upright) with the front wheel steered far round. Followed up to it, the speed falls towards 0
    and the lean with it; beyond it there is no circle: NaN rows, one warning, and null (strict JSON) on
    the command line."""
    from bikemass.cli.main import main
    from bikemass.core.errors import BikemassWarning
    steers = np.linspace(0.9, 1.5, 7)
    with pytest.warns(BikemassWarning, match="none found at"):
        family = bm.hands_free_turns(meijaard, steers)
    found = ~np.isnan(family.speed)
    assert found[:4].all() and not found[-1]
    assert np.all(np.diff(family.speed[found]) < 0) and np.all(np.diff(family.roll[found]) < 0)
    assert family.speed[found][-1] < 0.3 and abs(family.roll[found][-1]) < 0.02
    assert main(["turn", "benchmark", "--hands-free", "--steers", "1.3:1.5:3", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["speed"][0] > 0 and doc["speed"][-1] is None


@pytest.mark.parametrize("system", [
    pytest.param(lambda: bm.Scenario("jamis", "relaxed", model="rider-lean"), id="rider-lean scenario"),
    pytest.param(lambda: bm.Scenario("benchmark", model="tyre").build(), id="tyre built"),
    pytest.param(lambda: bm.Scenario("jamis", "relaxed", "steel"), id="flexible rear frame"),
    pytest.param(lambda: bm.Scenario("jamis", "relaxed", "steel").build(), id="flexible rear frame built"),
])
def test_a_turn_of_another_model_or_a_flexible_frame_is_refused_not_made_rigid(system):
    """The steady turns are the nonlinear Whipple bicycle's: a scenario of a member or of a flexible frame is
    refused in one line (before, its benchmark parameters were turned as the rigid Whipple bicycle)."""
    with pytest.raises(InputError):
        bm.steady_turn(system(), 5.0, radius=10.0)
    with pytest.raises(InputError):
        bm.hands_free_turns(system(), [0.1])


def test_the_command_line_refuses_a_turn_of_a_rider_lean_parameter_file(capsys):
    from bikemass.cli.main import main
    lean = Path(__file__).parent / "data" / "bicycleparameters" / "to_yaml-MooreRiderLean2012-browserjason.yml"
    assert main(["turn", str(lean), "--speed", "5", "--radius", "10"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "to_yaml-MooreRiderLean2012-browserjason.yml" in err[0] and "Whipple" in err[0]


def test_a_parameter_file_with_a_frame_stiffness_block_is_refused_too(tmp_path, capsys):
    """A file written by ``params --stiffness steel`` carries its frame_stiffness: its scenario builds a
    flexible frame, so the steady turns refuse it as they refuse --stiffness steel."""
    from bikemass.cli.main import main
    written = tmp_path / "steel.yaml"
    assert main(["params", "jamis", "--rider", "relaxed", "--stiffness", "steel", "--format", "yaml",
                 "-o", str(written)]) == 0
    assert bm.Scenario(str(written)).build().stiffness is not None
    with pytest.raises(InputError, match="rigid"):
        bm.steady_turn(bm.Scenario(str(written)), 5.0, radius=20.0)
    capsys.readouterr()
    assert main(["turn", str(written), "--speed", "5", "--radius", "20"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "steel.yaml" in err[0]


def test_a_sharp_steer_finds_the_upright_turn_or_is_refused(meijaard):
    """At 5 m/s and 0.8 rad of steer the lean that balances the turn is the upright one (0.72 rad, a right
    turn for a right steer; the point mass on the kinematic circle leans atan(v^2 tan(d) cos(lam) / (g w))
    = 1.16 rad, the same side): the linear model's lean as a start had found 1.88 rad, past lying flat, on
    a circle turning left, and said nothing.  The radius of that turn gives the steer back (the same
    equations from the other end); a steer with no upright turn (1.5 rad) is refused; the linear columns,
    outside any angle the linear model describes on so tight a circle, are warned about."""
    with pytest.warns(bm.BikemassWarning, match="linear model's lean and steer for this circle"):
        sharp = bm.steady_turn(meijaard, 5.0, steer=0.8)
    assert 0 < sharp.roll < math.pi / 2 and sharp.radius > 0 and sharp.yaw_rate > 0
    point_mass = math.atan(25.0 * math.tan(0.8) * math.cos(meijaard.lam) / (meijaard.g * meijaard.w))
    assert abs(sharp.roll - point_mass) < 0.5
    with pytest.warns(bm.BikemassWarning):                  # a circle tighter than the wheelbase, as a real one can be
        back = bm.steady_turn(meijaard, 5.0, radius=sharp.radius)
    assert sharp.radius < meijaard.w
    assert back.steer == pytest.approx(0.8, abs=1e-8) and back.roll == pytest.approx(sharp.roll, abs=1e-8)
    with pytest.raises(InputError, match="steer: 1.5: a steer angle with a steady turn at 5 m/s"):
        bm.steady_turn(meijaard, 5.0, steer=1.5)


def test_the_radius_of_every_upright_turn_gives_its_steer_back(meijaard):
    """Every upright turn the steer finds (speeds 3, 4 and 8 m/s, steers to 1.5 rad) is found again from its
    radius, the same lean and steer to 1e-7: the radius's Newton start failed on 57 of 199 such circles, some at
    a moderate lean (3 m/s, 1.23 rad of steer on a 0.38 m circle), and some turns lie next to the steers that
    have none (4 m/s, 1.123 rad); the steers are then bracketed, the edge of those with a turn included."""
    found = 0
    for speed in (3.0, 4.0, 8.0):
        for steer in np.linspace(0.1, 1.5, 12).tolist() + [1.123 if speed == 4.0 else 0.708]:
            try:
                turn = bm.steady_turn(meijaard, speed, steer=steer)
            except InputError:
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", bm.BikemassWarning)
                back = bm.steady_turn(meijaard, speed, radius=turn.radius)
            assert back.steer == pytest.approx(steer, abs=1e-7) and back.roll == pytest.approx(turn.roll, abs=1e-7)
            found += 1
    assert found >= 25


def test_a_fast_sharp_turn_is_found_from_its_radius_too(meijaard):
    """At 20 m/s, 0.0336 rad of steer leans the benchmark 1.44 rad on a 4.1 m circle: the radius route's bracket
    held steers where no lean balances and the search stopped there ("no lean balances it", a word about a lean
    for a radius given); such points inside a bracket are stepped round now, and the turn comes back."""
    turn = bm.steady_turn(meijaard, 20.0, steer=0.03363)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", bm.BikemassWarning)
        back = bm.steady_turn(meijaard, 20.0, radius=turn.radius)
    assert back.steer == pytest.approx(0.03363, abs=1e-8) and back.roll == pytest.approx(turn.roll, abs=1e-8)
