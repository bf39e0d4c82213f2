"""A sweep chunk evaluated as arrays (bikemass.sweep.vectorised) against independent references.

* Numbers: the general engine (eigenvalues and the polynomial eigenvalue problems of
  bikemass.analysis.engine.crossings, the closed form switched off) on the same parameter sets:
  random sets around the benchmark (rigid and with a flexible rear frame), benchmark variants
  whose crossings lie close together (the narrow stable windows near c = 0), a speed range that
  cuts crossings off: every speed to 1e-10 m/s, the total mass to 1e-12 kg.
* Outcomes: the per-configuration path (bikemass.sweep.evaluate.evaluate) on the same rows,
  refused rows included (non-numbers, non-finite values, negative masses, a steer tilt out of
  range, a non-positive-definite inertia, a singular flexible stiffness): the same rows refused,
  with the same one-line reasons.
* The array checks against check_parameters, row by row, on values at and beside each boundary.
"""

import math
import warnings
from types import SimpleNamespace

import numpy as np
import pytest

from bikemass.analysis.engine import closed_form
from bikemass.analysis.engine.critical import critical_speeds
from bikemass.core.errors import InputError
from bikemass.models.parameters import NAMES
from bikemass.models.plausibility import check_parameters, refused_parameters
from bikemass.models.whipple import whipple_model
from bikemass.scenario.scenario import parameters
from bikemass.sweep.evaluate import evaluate
from bikemass.sweep.vectorised import NUMBERS, SPEEDS, evaluate_columns, takes

BENCHMARK = parameters("benchmark")
VARIED = ("c", "lam", "xB", "zB", "mH", "IHzz", "IBxz", "xH", "IFyy", "w")
SPEED_TOL = 1e-10
MASS_TOL = 1e-12


class Fixed:
    """The little of a sweep's Model the chunk evaluator and the reference use: one parameter
    set and one frame stiffness (any 2x2 matrix, so that a singular g K0 + S can be made)."""

    def __init__(self, base, S=None):
        self.base, self.S, self.stiffness = base, S, "fixed"

    def parameters(self):
        return self.base

    def frame_stiffness(self, choice):
        if choice != "fixed":
            raise InputError("spec", "stiffness", f"the fixed stiffness, got {choice!r}")
        return self.S

    def build(self, changes):
        stiffness = changes.get("stiffness", "fixed")
        params = {k: v for k, v in changes.items() if k in NAMES}
        p = check_parameters(self.base.replace(**params), "spec")
        S = self.frame_stiffness(stiffness)
        return SimpleNamespace(parameters=p, model=whipple_model(p, S))


LOWEST = 1e-12
"""The general engine looks on (LOWEST, vmax]: at v = 0 itself the quartic's odd terms vanish, and
a set that is stable at rest (some of the widest random spreads) has a pair on the axis there,
which the general engine reports as a crossing at 1e-29 m/s; the closed form's range (0, vmax]
leaves v = 0 out.  A stable range from 0 then starts at LOWEST, within the tolerance of 0."""


def general_outputs(p, S, vmax):
    """First weave and capsize speeds and the first stable range by the general engine."""
    saved = closed_form.applies
    closed_form.applies = lambda model: False          # the eigenvalue path of critical_speeds
    try:
        found = critical_speeds(whipple_model(p, S), vmax, lo=LOWEST)
    finally:
        closed_form.applies = saved
    return dict(zip(SPEEDS, (found.weave_speed, found.capsize_speed, found.stable_from, found.stable_to)))


def run(model, configurations, vmax=30.0):
    changes = {k: [c[k] for c in configurations] for k in configurations[0]}
    return evaluate_columns(model, changes, len(configurations), vmax, lambda c: evaluate(model, c, vmax))


def assert_matches_general(model, configurations, vmax=30.0):
    out = run(model, configurations, vmax)
    for i, c in enumerate(configurations):
        p = model.base.replace(**c)
        expected = general_outputs(p, model.S, vmax)
        assert out.errors[i] is None, (c, out.errors[i])
        for k in SPEEDS:
            got = out.values[k][i]
            if expected[k] is None:
                assert np.isnan(got), (c, k, got)
            else:
                assert got == pytest.approx(expected[k], abs=SPEED_TOL), (c, k)
        assert out.values["total_mass"][i] == pytest.approx(p.mR + p.mB + p.mH + p.mF, abs=MASS_TOL)
    return out


def random_sets(seed, count, spread):
    rng = np.random.default_rng(seed)
    base = BENCHMARK.to_dict()
    return [{k: base[k] * (1 + spread * rng.uniform(-1, 1)) for k in VARIED} for _ in range(count)]


def test_random_sets_match_the_general_engine():
    out = assert_matches_general(Fixed(BENCHMARK), random_sets(1, 60, 0.3))
    assert np.sum(~np.isnan(out.values["stable_from"])) > 20          # most have a stable range


def test_random_sets_with_a_flexible_rear_frame_match_the_general_engine():
    S = np.array([[2.0e4, 1.5e3], [1.5e3, 6.0e3]])                    # N m/rad, positive definite
    assert_matches_general(Fixed(BENCHMARK, S), random_sets(2, 40, 0.3))


def test_close_crossings_match_the_general_engine():
    """Steer tilts across the narrow windows of a bicycle without trail (stable for a few mm/s)
    and trails around 2.5 mm: weave and capsize crossings within 1e-3 m/s of each other."""
    configurations = [{"c": 0.0, "lam": lam} for lam in np.linspace(0.205, 0.22, 16)]
    configurations += [{"c": c, "lam": 0.2} for c in np.linspace(0.001, 0.004, 16)]
    out = assert_matches_general(Fixed(BENCHMARK), configurations, vmax=10.0)
    widths = out.values["stable_to"] - out.values["stable_from"]
    assert np.nanmin(widths) < 2e-3                                   # some windows really are narrow


def test_many_crossings_and_a_short_speed_range_match_the_general_engine():
    """Wide spreads (several crossings each, some sets never stable) and a top speed that cuts
    crossings and stable ranges off."""
    configurations = random_sets(3, 40, 0.6)
    assert_matches_general(Fixed(BENCHMARK), configurations, vmax=30.0)
    assert_matches_general(Fixed(BENCHMARK), configurations, vmax=5.0)


def test_refused_rows_have_the_reference_outcome():
    """Rows the checks refuse, rows that are not numbers, a stiffness choice that fails and a
    singular g K0 + S each get exactly the per-configuration path's outcome; the good rows
    between them are unchanged."""
    good = {"c": 0.08, "lam": 0.3, "mB": 85.0, "IBxz": 2.4, "mR": 2.0, "rF": 0.35}
    bad = [{"c": math.nan}, {"c": math.inf}, {"lam": math.pi / 2}, {"lam": -math.pi / 2}, {"mB": -1.0},
           {"mB": 0.0}, {"mR": -0.5}, {"mR": 0.0}, {"rF": 0.0}, {"IBxz": 20.0},
           {"c": "0.08"}, {"lam": True}, {"mB": None}, {"c": 1 + 2j}]
    configurations = []
    for change in bad:
        configurations += [good, {**good, **change}]
    configurations.append({**good, "mB": 1e300})      # accepted, but its matrices overflow: no speeds
    model = Fixed(BENCHMARK)
    with warnings.catch_warnings():                     # numpy's overflow warnings on that row, if any
        warnings.simplefilter("ignore", RuntimeWarning)
        out = run(model, configurations)
    for i, c in enumerate(configurations):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            expected = evaluate(model, c, 30.0)
        assert out.errors[i] == expected["error"], c
        for k in NUMBERS:
            got = out.values[k][i]
            assert (np.isnan(got) if expected[k] is None else got == pytest.approx(expected[k], abs=SPEED_TOL)), (c, k)
    assert all(e is not None for e in out.errors[1:-1:2]) and all(e is None for e in out.errors[0::2])
    assert out.errors[-1] is None and np.isnan(out.values["weave_speed"][-1])


def test_a_singular_flexible_stiffness_and_a_failing_choice_have_the_reference_outcome():
    p = BENCHMARK.replace(c=0.05)
    S = -np.asarray(whipple_model(p).mechanics.K[0])                 # g K0 + S = 0 for c = 0.05
    model = Fixed(BENCHMARK, S)
    configurations = [{"c": 0.05, "stiffness": "fixed"}, {"c": 0.08, "stiffness": "fixed"},
                      {"c": 0.08, "stiffness": "steel"}]
    out = run(model, configurations)
    for i, c in enumerate(configurations):
        expected = evaluate(model, c, 30.0)
        assert out.errors[i] == expected["error"]
        assert (out.errors[i] is None) == (i == 1)
    expected = general_outputs(BENCHMARK.replace(c=0.08), S, 30.0)
    for k in SPEEDS:
        got = out.values[k][1]
        assert np.isnan(got) if expected[k] is None else got == pytest.approx(expected[k], abs=SPEED_TOL)


def test_rows_convert_to_the_reference_row_form():
    model = Fixed(BENCHMARK)
    configurations = [{"c": 0.08, "lam": 0.3}, {"c": 0.08, "lam": 2.0}, {"c": 0.2, "lam": 0.1}]
    for got, c in zip(run(model, configurations).rows(), configurations):
        expected = evaluate(model, c, 30.0)
        assert list(got) == list(expected)
        for k, v in expected.items():
            assert (got[k] is None) == (v is None) and (v is None or got[k] == pytest.approx(v, abs=SPEED_TOL))


def boundary_values(key, value):
    """Values of ``key`` at and beside the boundaries check_parameters draws."""
    tiny = np.nextafter(0.0, 1.0)
    values = [value, 0.0, -0.0, tiny, -tiny, -1.0, 1e300, math.nan, math.inf, -math.inf]
    if key == "lam":
        for end in (math.pi / 2, -math.pi / 2):
            values += [end, np.nextafter(end, 0.0), np.nextafter(end, 4 * end)]
    return values


def test_the_array_checks_refuse_exactly_what_check_parameters_refuses():
    base = BENCHMARK.to_dict()
    rows = [dict(base)]
    for key in NAMES:
        rows += [{**base, key: v} for v in boundary_values(key, base[key])]
    for body in "BH":                                      # Ixz around the positive semi-definite limit
        xx, zz = base[f"I{body}xx"], base[f"I{body}zz"]
        limit = math.sqrt(xx * zz)
        for xz in (limit, limit * (1 + 1e-10), limit * (1 + 1e-8), -limit * (1 + 1e-8), 0.0):
            rows.append({**base, f"I{body}xz": xz})
    for wheel in "RF":                                     # point wheels and massless wheels
        rows += [{**base, f"r{wheel}": 0.0, f"I{wheel}yy": 0.0}, {**base, f"m{wheel}": 0.0},
                 {**base, f"m{wheel}": 0.0, f"I{wheel}xx": 0.0, f"I{wheel}yy": 0.0}]
    columns = {k: np.array([r[k] for r in rows]) for k in NAMES}
    refused = refused_parameters(columns, len(rows))
    for row, flag in zip(rows, refused):
        try:
            check_parameters(BENCHMARK.replace(**row), "spec")
            expected = False
        except InputError:
            expected = True
        assert flag == expected, row
    assert 0 < refused.sum() < len(rows)


def test_which_keys_are_taken():
    assert takes(("c", "lam")) and takes(("c", "stiffness")) and takes(("stiffness",))
    assert not takes(("c", "geometry.trail")) and not takes(("rider.chain.torso_lean",))
