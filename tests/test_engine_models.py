"""The stability engine on the richer models (tyres that slip, a flexible frame and fork, a leaning
rider), against references that know nothing of the engine:

* the knife-edge limit: very stiff tyres give Meijaard et al. (2007)'s exact weave and capsize
  speeds of the benchmark bicycle, the error falling as 1 / (cornering coefficient); every crossing
  equals one of a counting reference (LAPACK eigenvalues on a grid of 30,001 speeds, bisection);
* the infinitely stiff limit: a flexible frame and fork of stiffness times f give the rigid
  bicycle's critical speeds (closed form), the error falling as 1/f;
* the weave speed is the weave's crossing: the lowest-frequency oscillation (the Whipple bicycle's
  weave, roll and steer) followed by hand (``scipy.linalg.eigvals`` on a 0.01 m/s grid, nearest
  root) and its real part's sign change refined by Brent's method; another oscillation's crossing
  (the Jamis's 6.3 Hz tyre mode) is reported under its own name, never as weave, in the stability
  analysis and in the critical speeds that sweeps, sensitivities and uncertainty use;
* a mode unstable from the lowest speed (an undamped 6 Hz oscillation on the axis at standstill
  that grows from there) is reported, at standstill and for a grid that starts above it;
* the two-coordinate Whipple bicycle's closed form, which calls every oscillatory crossing weave
  without following the modes, agrees with the followed names on every thesis set and on random
  variants of them.
"""

import numpy as np
import pytest
import scipy.linalg
from scipy.optimize import brentq

import bikemass as bm
from bikemass.analysis.engine.critical import critical_speeds
from bikemass.analysis.engine.naming import WOBBLE, family, is_weave
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.analysis.engine.stability import analyse
from bikemass.analysis.uncertainty import first_crossings
from bikemass.fe.flexible import compliances
from bikemass.models.family import build
from bikemass.models.parameters import NAMES
from bikemass.models.members.tyre.parameters import Tyre, Tyres
from bikemass.models.whipple import whipple_model
from bikemass.scenario.scenario import Scenario, parameters
from bikemass.sweep.evaluate import evaluate
from test_stability_crossings import count_crossings
from thesis_sets import RIDERS, stiffness, thesis_set

BENCHMARK = parameters("benchmark")
MEIJAARD_WEAVE, MEIJAARD_CAPSIZE = 4.2923825363411040, 6.0242620153883589
"""Meijaard et al. (2007)'s benchmark critical speeds, exact to 16 digits (docs/stability.md)."""


def roots(model, v):
    """The dynamic eigenvalues (1/s) at ``v`` by SciPy's LAPACK driver (not the engine's)."""
    return scipy.linalg.eigvals(model.dynamic_matrix(v))


def followed(model, start, speeds):
    """The root continuing ``start`` (an eigenvalue at ``speeds[0]``) at each speed: nearest root."""
    out, root = [], start
    for v in speeds:
        r = roots(model, v)
        root = r[np.argmin(np.abs(r - root))]
        out.append(root)
    return np.array(out)


def sign_changes(model, start, speeds):
    """Speeds (m/s) where the root followed from ``start`` changes the sign of its real part, each
    refined by Brent's method on the real part of the root nearest the followed one."""
    path = followed(model, start, speeds)
    out = []
    for k in np.flatnonzero(np.sign(path.real[1:]) != np.sign(path.real[:-1])):
        a, b, za, zb = speeds[k], speeds[k + 1], path[k], path[k + 1]

        def real_part(x):
            r = roots(model, x)
            return r[np.argmin(np.abs(r - (za + (zb - za) * (x - a) / (b - a))))].real
        out.append(brentq(real_part, a, b, xtol=1e-13))
    return out


def stiff_tyres(cornering):
    """Tyres of cornering coefficient ``cornering`` (1/rad), relaxation length ``1 / cornering`` (m)
    and no camber: the knife-edge wheel as the coefficient grows (1e5 /rad and 1e-5 m are
    tests/test_models_tyre.py's very stiff tyres)."""
    tyre = Tyre(cornering_coefficient=cornering, camber_coefficient=0.0, relaxation_length=1.0 / cornering)
    return build("tyre", BENCHMARK, tyres=Tyres(tyre, tyre))


def test_very_stiff_tyres_give_meijaards_critical_speeds():
    """1e5 /rad: the weave speed within 2e-5 m/s of Meijaard's (measured 1.5e-5), the capsize speed
    within 1e-5 (measured 1.0e-6: the eigenvalues of a model with roots of 1e6 1/s beside roots of 1
    are resolved to about 1e-6 1/s, which is also the tolerance against the references); the weave's
    error times the coefficient is the same at 1e4 and 1e5 /rad (2 %): the limit is Meijaard's."""
    errors = []
    for cornering in (1e4, 1e5):
        model = stiff_tyres(cornering)
        result = analyse(model)
        assert [c.mode for c in result.crossings] == ["weave", "capsize"]
        (weave,), (capsize,) = result.weave_speeds, result.capsize_speeds
        errors.append((weave - MEIJAARD_WEAVE) * cornering)
        assert critical_speeds(model).weave_speed == pytest.approx(weave, abs=1e-9)
        # the reference: the root continuing the Whipple bicycle's weave, followed by hand
        whipple = roots(whipple_model(BENCHMARK), 3.0)
        start = roots(model, 3.0)
        start = start[np.argmin(np.abs(start - whipple[np.argmax(whipple.imag)]))]
        assert sign_changes(model, start, np.linspace(3.0, 5.5, 251)) == [pytest.approx(weave, abs=1e-5)]
        ref, _ = count_crossings(model, 0.0, 30.0)
        assert [k for _, k in ref] == ["oscillatory", "real"]
        assert ref[0][0] == pytest.approx(weave, abs=1e-5) and ref[1][0] == pytest.approx(capsize, abs=1e-5)
    assert abs(weave - MEIJAARD_WEAVE) <= 2e-5 and abs(capsize - MEIJAARD_CAPSIZE) <= 1e-5
    assert errors[1] == pytest.approx(errors[0], rel=2e-2)


@pytest.fixture(scope="module")
def jamis_flexible():
    bike = bm.load_bicycle("jamis")
    return bm.parameters(bike, bm.load_rider("relaxed")), compliances(bike, "steel")


def test_infinitely_stiff_frame_and_fork_give_the_rigid_critical_speeds(jamis_flexible):
    """Compliances held rigid: the closed form's weave and capsize speeds to 1e-9 m/s; stiffness
    times 1e4 and 1e6: each speed's error times f the same to 1e-3 (the limit), no other crossing."""
    params, flexible = jamis_flexible
    rigid = critical_speeds(whipple_model(params))
    held = analyse(build("flexible", params, compliances=flexible.rigid()))
    assert held.weave_speeds == (pytest.approx(rigid.weave_speed, abs=1e-9),)
    assert held.capsize_speeds == (pytest.approx(rigid.capsize_speed, abs=1e-9),)
    errors = []
    for factor in (1e4, 1e6):
        result = analyse(build("flexible", params, compliances=flexible.undamped().scaled(factor)))
        assert [(c.kind, c.mode) for c in result.crossings] == [("oscillatory", "weave"), ("real", "capsize")]
        errors.append(((result.weave_speeds[0] - rigid.weave_speed) * factor,
                       (result.capsize_speeds[0] - rigid.capsize_speed) * factor))
    np.testing.assert_allclose(errors[1], errors[0], rtol=1e-3)


@pytest.fixture(scope="module")
def jamis_lean_tyre_flexible():
    scenario = Scenario("jamis", "relaxed", "steel", model="rider-lean+tyre+flexible")
    model = scenario.build().model
    # the weave by hand: the lowest-frequency oscillation at 2 m/s, followed to 30 m/s
    start = roots(model, 2.0)
    start = min(start[start.imag > 0], key=lambda z: z.imag)
    weave = sign_changes(model, start, np.round(np.arange(2.0, 30.0 + 1e-9, 0.01), 12))
    # the 6.3 Hz oscillation whose largest share is the tyres' and the frame's: at 0.5 m/s, 35-45 rad/s
    tyre = roots(model, 0.5)
    tyre = tyre[(tyre.imag > 35) & (tyre.imag < 45)]
    assert len(tyre) == 1
    other = sign_changes(model, tyre[0], np.round(np.arange(0.5, 3.0 + 1e-9, 0.01), 12))
    return scenario, model, start, weave, other


def test_weave_speed_is_the_weaves_crossing_not_a_tyre_modes(jamis_lean_tyre_flexible):
    """The followed weave (below 1 Hz at 2 m/s) crosses once, at 5.40 m/s; the 6.3 Hz mode crosses
    at 2.40 m/s (with the steering bearing's default damping): the engine's weave speed is the former (1e-9 m/s), the latter is a crossing named
    by its own mode, not weave: ``wobble``, the steer-dominated oscillation of the wobble band at 8 m/s (labelled by
    what moves; it was named ``tyre`` by the family that holds it at standstill)."""
    scenario, model, start, weave, other = jamis_lean_tyre_flexible
    assert start.imag < 2 * np.pi and len(weave) == 1 and len(other) == 1 and other[0] < weave[0]
    result = analyse(model)
    assert result.weave_speeds == (pytest.approx(weave[0], abs=1e-9),)
    crossing, = [c for c in result.crossings if abs(c.speed - other[0]) < 1e-9]
    assert crossing.kind == "oscillatory" and not is_weave(crossing.mode)
    assert crossing in result.other_crossings and crossing.mode == "wobble" and crossing.speed in result.wobble_speeds
    at = roots(model, other[0])
    assert crossing.frequency == pytest.approx(abs(at[np.argmin(np.abs(at - 1j * crossing.frequency))].imag), rel=1e-9)
    assert 6.0 < crossing.frequency / (2 * np.pi) < 6.5


def test_sweeps_sensitivity_and_uncertainty_take_the_same_weave_speed(jamis_lean_tyre_flexible):
    """What sweeps (one configuration's row), sensitivities and uncertainty take as the weave speed
    is the followed weave's crossing, not the tyre mode's earlier one."""
    scenario, model, _, weave, _ = jamis_lean_tyre_flexible
    assert critical_speeds(model).weave_speed == pytest.approx(weave[0], abs=1e-9)
    assert critical_speeds(model).weave_crossing.mode == "weave"
    assert evaluate(scenario, {}, 30.0)["weave_speed"] == pytest.approx(weave[0], abs=1e-9)
    assert bm.sensitivity(scenario, names=("c",)).weave_speed == pytest.approx(weave[0], abs=1e-9)
    assert first_crossings(model, speed_grid())["weave_speed"].speed == pytest.approx(weave[0], abs=1e-9)


def test_cli_reports_the_tyre_crossing_under_its_name(jamis_lean_tyre_flexible, capsys):
    _, _, _, weave, other = jamis_lean_tyre_flexible
    from bikemass.cli.main import main
    assert main(["stability", "jamis", "--rider", "relaxed", "--stiffness", "steel",
                 "--model", "rider-lean+tyre+flexible"]) == 0
    lines = capsys.readouterr().out.splitlines()
    shown = {line.split(":")[0]: line.split(":", 1)[1] for line in lines[:8] if ":" in line}
    assert float(shown["weave speeds (the weave pair crosses Re = 0)"]) == pytest.approx(weave[0], abs=1e-11)
    speed, name = shown["other oscillations crossing Re = 0"].split(",")[0].split()
    assert float(speed) == pytest.approx(other[0], abs=1e-11) and name == "(wobble)"


@pytest.fixture(scope="module")
def jamis_tyre_flexible(jamis_flexible):
    """The tyre and flexible Jamis with the member undamped (no steering damper, no structural damping)."""
    params, flexible = jamis_flexible
    model = build("tyre+flexible", params, compliances=flexible.undamped())
    at_rest = roots(model, 0.0)
    six = at_rest[(at_rest.imag > 2 * np.pi * 5.5) & (at_rest.imag < 2 * np.pi * 6.5)]
    assert len(six) == 1
    return model, six[0]


def test_a_mode_unstable_from_standstill_is_reported(jamis_tyre_flexible):
    """The 6 Hz oscillation sits on the axis at standstill (undamped there) and its followed root
    has Re > 0 at every speed of (0, 5] m/s: no crossing reports it, the engine's modes unstable from
    the lowest speed do (frequency to 1e-4 of the followed root's just above standstill), with as
    many roots as LAPACK counts unstable there."""
    model, six = jamis_tyre_flexible
    assert abs(six.real) <= 1e-9 * abs(six)
    speeds = np.round(np.arange(0.01, 5.0 + 1e-9, 0.01), 12)
    path = followed(model, six, np.concatenate([[1e-3], speeds]))
    assert np.all(path.real > 0)
    result = analyse(model)
    assert result.stable_speeds == ()
    assert all(abs(c.frequency - path[0].imag) > 1e-3 * path[0].imag for c in result.crossings)
    entry, = [u for u in result.unstable_at_start if u.kind == "oscillatory"
              and u.frequency == pytest.approx(path[0].imag, rel=1e-4)]
    assert entry.speed == 0.0 and not is_weave(entry.mode)
    unstable = int(np.sum(roots(model, 1e-3).real > 0))
    assert sum(2 if u.kind == "oscillatory" else 1 for u in result.unstable_at_start) == unstable
    late = analyse(model, speed_grid(2.0, 30.0, 0.05))                # a grid that starts above 0
    assert [u.mode for u in late.unstable_at_start if u.frequency == pytest.approx(path[200].imag, rel=1e-3)] \
        == [entry.mode]
    assert late.unstable_at_start[0].speed == 2.0


def test_flexible_wobble_unstable_from_standstill_is_reported_as_wobble(jamis_flexible):
    """The undamped flexible Jamis's 7 Hz wobble grows from standstill (tests/test_wobble_naming.py) and
    has no crossing: it is reported unstable from 0 m/s, named wobble, at its frequency (1e-4)."""
    params, flexible = jamis_flexible
    model = build("flexible", params, compliances=flexible.undamped())
    at_rest = roots(model, 0.0)
    seven = at_rest[(at_rest.imag > 2 * np.pi * 6.0) & (at_rest.imag < 2 * np.pi * 8.0)]
    assert len(seven) == 1
    result = analyse(model)
    entry, = [u for u in result.unstable_at_start if u.frequency == pytest.approx(seven[0].imag, rel=1e-4)]
    assert family(entry.mode) == WOBBLE and entry.kind == "oscillatory"


def _whipple_sets(count, seed):
    """Every thesis set (bicycle x rider x frame) and ``count`` random variants (every parameter times
    0.6-1.4; seeded)."""
    sets = [(thesis_set(b, r), stiffness("Cargo" if b.startswith("Cargo") else b, m))
            for b in ("Jamis", "Cargo", "Cargo load") for r in ("No Rider", *RIDERS)
            for m in ("Infinite", "Steel", "Titanium", "Aluminum")]
    sets.append((thesis_set("Benchmark", "Benchmark"), None))
    rng = np.random.default_rng(seed)
    for i in range(count):
        p, _ = sets[i % 19]
        sets.append((p.replace(**{k: getattr(p, k) * rng.uniform(0.6, 1.4) for k in NAMES
                                  if k != "g" and getattr(p, k) != 0}), None))
    return sets


def test_the_whipple_closed_form_names_its_oscillatory_crossings_as_the_modes_followed_do():
    """The closed form (no tracking) calls every oscillatory crossing of the two-coordinate bicycle
    weave; the modes followed from standstill say the same of each (``is_weave``: the weave pair or
    a weave root paired with capsize), on 73 thesis sets and 200 random variants."""
    oscillatory = 0
    for p, S in _whipple_sets(200, seed=7):
        model = whipple_model(p, S)
        result = analyse(model)
        found = critical_speeds(model)
        for c in result.crossings:
            if c.kind == "oscillatory":
                oscillatory += 1
                assert is_weave(c.mode), c
        assert [c.speed for c in found.crossings if c.kind == "oscillatory"] == pytest.approx(
            list(result.weave_speeds), abs=1e-9)
    assert oscillatory > 150
