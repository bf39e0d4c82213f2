"""The rider's arms (the ``arms`` member): a torsional spring and damper about the steer axis between the
handlebars and the upper body.

References, each independent of the member's derivation:

* the limit ``k_arms = c_arms = 0``: every combination with the arms is the combination without them
  (eigenvalues to 1e-10, relative to the largest);
* for the Whipple bicycle, Meijaard et al.'s (2007) matrices from :func:`bikemass.matrices` with the
  spring added to ``g K0[steer, steer]`` and the damper to the steer-steer damping, built here by hand
  (eigenvalues to 1e-10 relative);
* with the leaning rider and with the flexible frame, the model without the arms (itself checked against
  BicycleParameters and the stiff limits) plus ``k f f^T`` and ``c f f^T``, ``f`` the steer axis's share of
  each coordinate's rotation of the handlebars relative to the upper body written out by hand: 1 for
  the steer, ``-sin(lam)`` for the rider's lean about x, ``n . s`` for the frame's twist about the axis
  ``n`` (eigenvalues to 1e-9 relative);
* a very stiff arm spring locks the steer: the roll alone, ``M[0,0] phi'' + g K0[0,0] phi = 0`` (the
  benchmark's ``C1[0,0] = K2[0,0] = 0``), roots ``+-sqrt(-g K0[0,0] / M[0,0])`` (1e-6 relative at 1e10 N m/rad:
  the error goes as 1/k).
"""

import dataclasses
import math
import warnings

import numpy as np
import pytest
import yaml

import bikemass as bm
from bikemass.cli.main import main
from bikemass.core.errors import BikemassWarning, InputError
from bikemass.models.members.arms.parameters import Arms, as_arms
from bikemass.models.family import build, generated

SPEEDS = (0.5, 2.0, 4.0, 6.0, 9.0)
ARMS = Arms(stiffness=35.0, damping=1.7)                  # test values, not defaults


def roots(model, speed):
    return np.sort_complex(np.linalg.eigvals(model.dynamic_matrix(speed)))


def same_roots(a, b, rtol):
    """Every root of ``b`` in ``a`` (and as many) within ``rtol`` of the largest."""
    assert len(a) == len(b)
    scale = max(np.abs(b).max(), 1.0)
    for z in b:
        assert np.min(np.abs(a - z)) <= rtol * scale, (z, a)


def second_order_roots(M, C, K):
    """The roots of ``M q'' + C q' + K q = 0``."""
    n = len(M)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    return np.linalg.eigvals(A)


@pytest.fixture(scope="module")
def meijaard():
    return bm.parameters("benchmark")


@pytest.fixture(scope="module")
def jamis():
    return bm.Scenario("jamis", "relaxed")


@pytest.mark.parametrize("model", ["whipple", "tyre", "rider-lean", "rider-lean+tyre"])
def test_no_arms_give_the_model_without_them_to_1e_10(jamis, model):
    base = jamis.replace(model=model).build()
    with_arms = "+".join(m for m in (*base.choice.members, "arms")) if base.choice.members else "arms"
    arms = jamis.replace(model=with_arms, arms=Arms(0.0, 0.0)).build()
    for v in SPEEDS:
        same_roots(roots(arms.model, v), roots(base.model, v), 1e-10)


def test_whipple_with_arms_is_the_benchmark_with_a_steer_spring_and_damper(meijaard):
    """Built by hand from Meijaard et al.'s matrices: ``M q'' + (v C1 + c E) q' + (g K0 + v^2 K2 + k E) q = 0``,
    ``E`` the steer-steer unit matrix."""
    m = bm.matrices(meijaard)
    steer = np.array([[0.0, 0.0], [0.0, 1.0]])
    model = build("arms", meijaard, arms=ARMS)
    for v in SPEEDS:
        reference = second_order_roots(m.M, v * m.C1 + ARMS.damping * steer,
                                       m.g * m.K0 + v * v * m.K2 + ARMS.stiffness * steer)
        same_roots(roots(model, v), reference, 1e-10)


def _with_arms_by_hand(base, f, speed, arms=ARMS):
    """The roots of the second-order model ``base`` with ``k f f^T`` and ``c f f^T`` added."""
    mech = base.model.mechanics
    F = np.outer(f, f)
    return second_order_roots(mech.M, mech.damping(speed) + arms.damping * F, mech.stiffness(speed) + arms.stiffness * F)


def test_the_leaning_upper_body_holds_the_arms(jamis):
    """The handlebars turn relative to the upper body by ``steer - sin(lam) lean`` about the steer axis."""
    base = jamis.replace(model="rider-lean").build()
    arms = jamis.replace(model="rider-lean+arms", arms=ARMS).build()
    names = [s.name for s in base.model.mechanics.coordinates]
    assert names == ["roll-angle", "steer-angle", "lean-angle"]
    f = np.array([0.0, 1.0, -math.sin(base.parameters.lam)])
    for v in SPEEDS:
        same_roots(roots(arms.model, v), _with_arms_by_hand(base, f, v), 1e-9)


def test_the_arms_bridge_the_frames_twist(jamis):
    """With the flexible frame the upper body sits on the rear frame, the bars on the twisted head tube:
    the handlebars turn by ``steer + (n . s) twist`` about the steer axis, ``n`` the twist axis.  The
    Jamis's twist axis is nearly normal to the steer axis (``n . s = -8e-5``), so the check turns it to
    ``(0.6, 0.8)`` (``n . s = 0.95``) to see the coupling."""
    built = jamis.replace(model="flexible", stiffness="steel").build()
    frame = dataclasses.replace(built.compliances.frame, direction=(0.6, 0.8))
    compliances = dataclasses.replace(built.compliances, frame=frame)
    base = dataclasses.replace(built, model=build("flexible", built.parameters, compliances=compliances))
    arms = build("flexible+arms", built.parameters, compliances=compliances, arms=ARMS)
    names = [s.name for s in base.model.mechanics.coordinates]
    lam = built.parameters.lam
    f = np.zeros(len(names))
    f[names.index("steer-angle")] = 1.0
    f[names.index("frame-twist")] = 0.6 * math.sin(lam) + 0.8 * math.cos(lam)
    for v in SPEEDS:
        same_roots(roots(arms, v), _with_arms_by_hand(base, f, v), 1e-9)


def test_very_stiff_arms_lock_the_steer(meijaard):
    m = bm.matrices(meijaard)
    locked = math.sqrt(-m.g * m.K0[0, 0] / m.M[0, 0])
    model = build("arms", meijaard, arms=Arms(stiffness=1e10, damping=0.0))
    for v in (1.0, 5.0):
        r = roots(model, v)
        slow = r[np.argsort(np.abs(r))][:2]
        assert np.sort(slow.real) == pytest.approx([-locked, locked], rel=1e-6)
        assert np.abs(slow.imag).max() <= 1e-6 * locked


def test_every_combination_with_arms_is_shipped():
    from bikemass.models.registry import MEMBERS
    from itertools import combinations
    for n in range(len(MEMBERS)):
        for others in combinations([m for m in MEMBERS if m != "arms"], n):
            code = generated("+".join((*others, "arms")))
            assert {"k_arms", "c_arms"} <= {p for p, _, _ in code.PARAMETERS} and code.MEMBERS == (*others, "arms")


def test_arms_are_refused_without_the_member_and_checked():
    with pytest.raises(InputError, match="arms member"):
        bm.Scenario("benchmark", arms=ARMS)
    with pytest.raises(InputError, match="stiffness"):
        Arms(stiffness=-1.0)
    with pytest.raises(InputError, match="damping"):
        as_arms({"damping": "-2 N m s/rad"})
    with pytest.raises(InputError, match="no arms parameters for the model tyre"):
        build("tyre", bm.parameters("benchmark"), arms=ARMS)
    with pytest.warns(BikemassWarning, match="no published default"):    # the family's builder: the same default
        assert build("arms", bm.parameters("benchmark")).name == "arms"
    assert as_arms({"stiffness": "1 N m/deg", "damping": 2}).stiffness == pytest.approx(180 / math.pi, rel=1e-15)


def test_the_default_is_zero_and_says_so():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        built = bm.Scenario("benchmark", model="arms").build()
    assert built.arms == Arms(0.0, 0.0)
    assert any(issubclass(w.category, BikemassWarning) and "no published default" in str(w.message) for w in caught)


def test_contract_params_with_arms_read_back(capsys, tmp_path):
    """Contract test (the code against itself): ``params --model tyre+flexible+arms --arms FILE`` writes an
    ``arms:`` block; ``eig FILE --model tyre+flexible+arms`` gives the eigenvalues of the scenario built
    directly (1e-9 relative, as tests/test_member_export.py)."""
    arms_file = tmp_path / "arms.yaml"
    arms_file.write_text("stiffness: 12 N m/rad\ndamping: 0.9 N m s/rad\n")
    out = tmp_path / "model.yaml"
    scenario = ["jamis", "--rider", "relaxed", "--model", "tyre+flexible+arms", "--stiffness", "steel",
                "--arms", str(arms_file)]
    assert main(["params", *scenario, "--format", "yaml", "-o", str(out)]) == 0, capsys.readouterr().err
    doc = yaml.safe_load(out.read_text())
    assert doc["arms"] == {"stiffness": 12.0, "damping": 0.9, "forearms": "pose"} and doc["units"]["damping"] == "N m s/rad"

    def eigenvalues(*argv):
        capsys.readouterr()
        assert main(["eig", *argv, "--speeds", "1:9:4", "--format", "json"]) == 0, capsys.readouterr().err
        import json
        d = json.loads(capsys.readouterr().out)
        return np.array([m["eigenvalues"] for m in d["modes"]])

    direct, back = eigenvalues(*scenario), eigenvalues(str(out), "--model", "tyre+flexible+arms")
    assert back == pytest.approx(direct, rel=1e-9, abs=1e-9 * np.abs(direct).max())


def test_a_sweep_takes_the_arms_file(tmp_path):
    """A sweep spec's ``arms:`` (beside it) reaches every configuration: each row's weave speed equals
    ``bm.stability`` of the benchmark with that trail and the arms (1e-9 m/s: the same engine, so this
    checks the plumbing, not the numbers), and differs from the rows without arms (the damping moves it)."""
    import csv
    (tmp_path / "arms.yaml").write_text("damping: 0.8 N m s/rad\n")
    spec = tmp_path / "spec.yaml"
    spec.write_text("bike: benchmark\nmodel: arms\narms: arms.yaml\nvary:\n  c: [0.07, 0.09]\n")
    assert main(["sweep", str(spec), "--out", str(tmp_path / "o"), "--quiet"]) == 0
    with open(tmp_path / "o" / "results.csv") as fh:
        rows = list(csv.DictReader(fh))
    assert len(rows) == 2
    for row in rows:
        c = float(row["c"])
        arms = bm.stability(bm.Scenario("benchmark", model="arms", arms=Arms(damping=0.8)).build({"c": c}).model)
        plain = bm.stability(bm.Scenario("benchmark").build({"c": c}).model)
        assert float(row["weave_speed"]) == pytest.approx(arms.weave_speeds[0], abs=1e-9)
        assert abs(arms.weave_speeds[0] - plain.weave_speeds[0]) > 0.02


# ---------------------------------------------------------------- the forearms' mass on the handlebars
def test_forearms_on_the_handlebars_move_their_mass_to_the_front_frame(jamis):
    """``forearms: handlebars``: the front frame gains exactly the forearms' mass and first moment, the
    rear frame loses them (1e-12 relative: the parts' own mass properties, summed by hand); the leaning
    upper body loses them too; the system's total mass and mass centre do not change."""
    pose = jamis.replace(model="rider-lean+arms", arms=Arms(forearms="pose")).build()
    held = jamis.replace(model="rider-lean+arms", arms=Arms(forearms="handlebars")).build()
    rider = jamis.inputs.seated()
    forearms = [props for name, _, props in rider.breakdown() if name.startswith("lower_arm")]
    m = sum(f.mass for f in forearms)
    mx = sum(f.mass * f.com[0] for f in forearms)
    mz = sum(f.mass * f.com[2] for f in forearms)
    a, b = pose.parameters, held.parameters
    assert b.mH == pytest.approx(a.mH + m, rel=1e-12) and b.mB == pytest.approx(a.mB - m, rel=1e-12)
    assert b.mH * b.xH == pytest.approx(a.mH * a.xH + mx, rel=1e-12)
    assert b.mH * b.zH == pytest.approx(a.mH * a.zH + mz, rel=1e-12)
    assert b.mB * b.xB + b.mH * b.xH == pytest.approx(a.mB * a.xB + a.mH * a.xH, rel=1e-12)
    assert held.lean.upper.mass == pytest.approx(pose.lean.upper.mass - m, rel=1e-12)
    assert 3.0 < m < 5.0                                              # two forearms with hands, kg


def test_forearms_stay_with_a_rider_whose_hands_are_off_the_bars():
    with pytest.raises(InputError, match="hands on the grips"):
        bm.Scenario("jamis", "no-hands", model="arms", arms=Arms(forearms="handlebars")).build()
    with pytest.raises(InputError, match="forearms"):
        Arms(forearms="elbows")


def test_contract_held_forearms_read_back(capsys, tmp_path):
    """Contract test: a parameter file written with ``forearms: handlebars`` holds the moved mass in its
    26 parameters and reads back as the same model (1e-9 relative)."""
    arms_file = tmp_path / "arms.yaml"
    arms_file.write_text("damping: 0.5 N m s/rad\nforearms: handlebars\n")
    out = tmp_path / "model.yaml"
    scenario = ["jamis", "--rider", "relaxed", "--model", "arms", "--arms", str(arms_file)]
    assert main(["params", *scenario, "--format", "yaml", "-o", str(out)]) == 0, capsys.readouterr().err
    doc = yaml.safe_load(out.read_text())
    assert doc["arms"]["forearms"] == "handlebars" and doc["mH"] > 5.0

    def eigenvalues(*argv):
        capsys.readouterr()
        assert main(["eig", *argv, "--speeds", "1:9:4", "--format", "json"]) == 0, capsys.readouterr().err
        import json
        return np.array([m["eigenvalues"] for m in json.loads(capsys.readouterr().out)["modes"]])

    direct, back = eigenvalues(*scenario), eigenvalues(str(out), "--model", "arms")
    assert back == pytest.approx(direct, rel=1e-9, abs=1e-9 * np.abs(direct).max())


def _arms_warnings(scenario):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        scenario.build()
    return [str(w.message) for w in caught if issubclass(w.category, BikemassWarning) and "hand" in str(w.message)
            or "forearms: handlebars with no rider" in str(w.message) or "no rider rides" in str(w.message)]


def test_arms_through_no_hands_on_the_bars_are_warned_not_silent():
    """The arms act through the hands: a stiffness or damping with a no-hands rider (hands 663 mm from the
    Jamis's grips), and forearms: handlebars with no rider seated (nothing moves), each say so in one
    warning; a rider holding the bars says nothing."""
    stiff = Arms(stiffness=50.0, damping=1.0)
    held = Arms(stiffness=0.0, damping=0.0, forearms="handlebars")
    no_hands = _arms_warnings(bm.Scenario("jamis", "no-hands", model="arms", arms=stiff))
    assert len(no_hands) == 1 and "663 mm" in no_hands[0]
    assert _arms_warnings(bm.Scenario("jamis", "relaxed", model="arms", arms=stiff)) == []
    nobody = _arms_warnings(bm.Scenario("benchmark", model="arms", arms=held))
    assert len(nobody) == 1 and "no rider seated" in nobody[0]
    assert _arms_warnings(bm.Scenario("jamis", "relaxed", model="arms", arms=held)) == []


def test_arms_with_no_rider_at_all_and_arms_past_a_riders_strength_are_warned():
    """A stiffness or damping with no rider at all (the Jamis alone: the weave speed moved from 9.82 m/s to none
    without a word) acts between the bars and the rear frame: one warning. The benchmark's set holds its rider:
    nothing to say. Arms stiffer than 1e4 N m/rad (175 N m for a degree of steer) or damped above 1e3 N m s/rad
    are warned about as no rider's (1e12 gave numbers the analysis could not resolve)."""
    stiff = Arms(stiffness=10.0, damping=0.5)
    nobody = _arms_warnings(bm.Scenario("jamis", model="arms", arms=stiff))
    assert len(nobody) == 1 and "no rider rides" in nobody[0]
    assert _arms_warnings(bm.Scenario("benchmark", model="arms", arms=stiff)) == []
    with pytest.warns(BikemassWarning, match="stiffness = 1e\\+12 N m/rad is above 10000"):
        Arms(stiffness=1e12)
    with pytest.warns(BikemassWarning, match="damping = 2000 N m s/rad is above 1000"):
        Arms(damping=2000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        Arms(stiffness=1e4, damping=1e3)                       # at the limits: a rider's strong grip
