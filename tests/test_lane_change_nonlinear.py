"""The Hess-Moore-Hubbard rider on the nonlinear Whipple bicycle through the lane change
(bikemass.analysis.handling.lane_change.follow_nonlinear; docs/nonlinear.md, "The rider in the loop")."""

import numpy as np
import pytest

import bikemass as bm
from bikemass.analysis.handling.lane_change import follow_nonlinear, front_contact
from bikemass.analysis.handling.plant import linear_model
from bikemass.analysis.handling.rider import closed_loop, rider_plant
from bikemass.analysis.handling.tuning import tune_gains
from bikemass.cli.main import main
from bikemass.core.errors import InputError
from bikemass.models.nonlinear import NonlinearWhipple

P = bm.parameters("benchmark")
SPEED = 5.0


@pytest.fixture(scope="module")
def runs():
    return bm.lane_change(P, SPEED), bm.lane_change(P, SPEED, nonlinear=True)


def test_front_contact_on_the_ground_and_its_linear_limit():
    # reference 1: the holonomic constraint (the pitch solved by the model) puts the contact at z = 0;
    # reference 2: to first order the contact's y is the linear model's front-lateral row (w psi - c cos(lam) delta + y)
    bike = NonlinearWhipple(P)
    rng = np.random.default_rng(33)
    for roll, steer in rng.uniform(-0.6, 0.6, (5, 2)):
        point = front_contact(P, 0.3, -0.2, 0.7, roll, bike.pitch(roll, steer), steer)
        assert abs(point[2]) < 1e-12
    assert np.allclose(front_contact(P, 0, 0, 0, 0, 0, 0), (P.w, 0, 0), atol=1e-15)
    row = linear_model(P, None).output_matrix(["front-lateral"])[0]
    e = 1e-6
    q = np.array((e, 2 * e, 3 * e, -e))           # roll, steer, yaw, y
    y = front_contact(P, 0.0, q[3], q[2], q[0], bike.pitch(q[0], q[1]), q[1])[1]
    linear = row[0] * q[0] + row[1] * q[1] + row[4] * q[2] + row[5] * q[3]
    assert abs(y - linear) < 1e-9 * e * 10


def test_small_lane_change_equals_the_linear_closed_loop(runs):
    # the linear limit: the road scaled by 0.01 (2 cm), the run divided by 0.01, equals the linear run
    # to 1e-3 of each signal's peak (the difference goes with the amplitude squared: ~5e-7 measured)
    linear, _ = runs
    plant = rider_plant(linear_model(P, None), SPEED)
    small = follow_nonlinear(P, closed_loop(plant, tune_gains(plant)), scale=0.01)
    assert not small.stopped and len(small.time) == len(linear.time)
    for name, values in linear.signals.items():
        error = np.abs(small.signals[name] / 0.01 - values).max() / np.abs(values).max()
        assert error < 1e-3, (name, error)


def test_energy_balance_of_the_full_lane_change(runs):
    # the bicycle's energy changes only by the rider's work: d E / dt = T_delta * steer rate
    # (the steer torque acts between the frames about the steer axis); trapezoidal rule at 0.01 s
    _, run = runs
    s = run.signals
    power = s["steer-torque"] * s["steer-rate"]
    work = np.concatenate(([0.0], np.cumsum(np.diff(run.time) * (power[1:] + power[:-1]) / 2)))
    change = s["energy"] - s["energy"][0]
    assert np.abs(work).max() > 1e-3                      # the rider does work (about 0.017 J)
    assert np.abs(change - work).max() < 1e-3 * np.abs(work).max()


def test_full_lane_change_runs_and_differs_from_linear(runs):
    # 2 m at 5 m/s: within a few percent of linear (about 0.5 % of the peak roll), but not equal
    linear, run = runs
    assert run.model == "nonlinear" and not run.stopped and len(run.time) == len(linear.time)
    assert np.abs(run.signals["front-lateral"] - run.road).max() < 1.0       # it follows the road
    for name in ("roll-angle", "steer-angle", "steer-torque"):
        a, b = linear.signals[name], run.signals[name]
        difference = np.abs(a - b).max() / np.abs(a).max()
        assert 1e-4 < difference < 0.05, (name, difference)
    speed = run.signals["forward-speed"]
    assert np.all(np.abs(speed - SPEED) < 0.05 * SPEED)


def test_nonlinear_refuses_other_systems():
    with pytest.raises(InputError):
        bm.lane_change(linear_model(P, None), SPEED, nonlinear=True)
    with pytest.raises(InputError):
        bm.lane_change(P, SPEED, nonlinear=True, stiffness=np.eye(2))
    with pytest.raises(InputError, match="stable"):          # 2 m/s: the linear closed loop diverges
        bm.lane_change(P, 2.0, nonlinear=True)


def test_cli(tmp_path, capsys):
    png = tmp_path / "lane.png"
    assert main(["handling", "benchmark", "--speeds", "5", "--lane-change", str(png), "--nonlinear"]) == 0
    # lazy: matplotlib's image reader to decode the figure
    import matplotlib.image
    image = matplotlib.image.imread(png)
    assert image.shape[0] > 300 and image.std() > 0.01            # drawn, not blank
    for extra in ((), ("--model", "rider-lean", "--lane-change", str(tmp_path / "x.png"))):
        capsys.readouterr()
        assert main(["handling", "benchmark", "--speeds", "5", "--nonlinear", *extra]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--nonlinear" in err, err
    assert not (tmp_path / "x.png").exists()
