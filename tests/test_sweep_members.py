"""A model with members swept as arrays (bikemass.sweep.members, bikemass.analysis.engine.batch) against the
engine, configuration by configuration.

The reference is the engine: ``bm.stability(params, model=...)`` (the modes followed and named on the
speed grid, the crossings from the compound matrices' polynomial eigenvalue problems) for the c x lam
grid through ``bm.sweep``, and ``bikemass.sweep.evaluate.evaluate`` (the scenario built, the engine's
critical speeds) for seeded random perturbations of several bicycles with the tyre and rider-lean members.
Tolerance 1e-9 m/s (issue 32's); the two paths share no numerical step (characteristic polynomial,
Routh's array and Newton's method on determinants against eigenvalues and QZ), so the agreement is
limited by the engine's own refinement (Brent's method on eigenvalues' real parts, about 1e-11 m/s).
"""

import dataclasses
import functools
import os

import numpy as np
import pytest

import bikemass as bm
from bikemass.analysis.engine.batch import (_convex_floor, _illinois, batch_critical_speeds, characteristic,
                                            routh)
from bikemass.sweep.evaluate import evaluate
from bikemass.sweep.members import evaluate_member_batch
from bikemass.sweep.table import NUMBERS

TOL = 1e-9
SPEEDS = ("weave_speed", "capsize_speed", "stable_from", "stable_to")
KEYS = ("c", "lam", "w", "xB", "zB", "mB", "IBxx", "IBzz", "xH", "zH", "mH", "IHxx", "IFyy", "IRyy")


def _same(got, want):
    """Both ``None``/``nan`` or within TOL (m/s)."""
    if want is None or (isinstance(want, float) and np.isnan(want)):
        return got is None or np.isnan(got)
    return got is not None and not np.isnan(got) and abs(got - want) <= TOL


def test_characteristic_polynomial_is_numpys_poly_of_the_eigenvalues():
    """Faddeev-LeVerrier's coefficients, at any speed, against numpy's polynomial of the eigenvalues."""
    model = bm.Scenario("benchmark", model="tyre").build().model
    P = np.asarray(model.dynamic_coefficients)
    a = characteristic(P[None])[0]
    for v in (0.5, 4.0, 17.0):
        A = sum(v ** k * P[k] for k in range(len(P)))
        want = np.poly(np.linalg.eigvals(A))[::-1]
        got = a @ v ** np.arange(a.shape[1])
        assert np.allclose(got, want, rtol=1e-9, atol=1e-9 * np.abs(want).max())


@pytest.mark.parametrize("n, degree", [(1, 1), (2, 2), (3, 1), (5, 2), (6, 3)])
def test_characteristic_polynomial_of_random_matrix_polynomials(n, degree):
    """Seeded random ``A(v) = sum_k v**k P[k]`` of n states and degree 1-3 in v (the recursion's last two
    coefficients come from traces, not products): numpy's polynomial of the eigenvalues at three speeds
    (1e-10 relative to the largest coefficient)."""
    P = np.random.default_rng(n * 10 + degree).standard_normal((4, degree + 1, n, n))
    a = characteristic(P)
    for v in (0.3, 1.0, 2.5):
        A = sum(v ** k * P[:, k] for k in range(degree + 1))
        want = np.array([np.poly(np.linalg.eigvals(x))[::-1] for x in A]).real
        got = a @ v ** np.arange(a.shape[2])
        assert np.all(np.abs(got - want) <= 1e-10 * np.abs(want).max(axis=1, keepdims=True))


def test_routh_against_the_roots():
    """Routh's array of seeded random real polynomials of degree 4-8: the count of roots with ``Re > 0``
    against numpy's roots, and ``H_(n-1)`` against Orlando's formula ``(-1)**(n (n-1) / 2) prod_(i<j)
    (l_i + l_j)`` of the roots (1e-8 relative); a polynomial with a pair ``+-i w`` on the axis: ``H_(n-1)``
    zero to rounding and the auxiliary polynomial's ``w**2`` equal to ``w**2`` (1e-9 relative)."""
    rng = np.random.default_rng(11)
    for n in range(4, 9):
        for _ in range(20):
            pairs = n // 2
            re = rng.uniform(-2, 1, pairs) * rng.choice([1, 0.01], pairs)
            z = re + 1j * rng.uniform(0.1, 5, pairs)
            roots = np.concatenate([z, z.conj()] + ([rng.uniform(-2, 1, 1)] if n % 2 else []))
            c = np.real(np.poly(roots))[::-1]                     # ascending, monic
            count, hurwitz, _ = routh(c)
            assert count == int(np.sum(roots.real > 0))
            want = (-1) ** (n * (n - 1) // 2) * np.prod([roots[i] + roots[j] for i in range(n) for j in range(i + 1, n)])
            assert abs(hurwitz - want.real) <= 1e-8 * abs(want)
        w = 1.7
        others = np.concatenate([[-0.5 + 2j, -0.5 - 2j, -1.0, -3.0][:n - 2]])
        c = np.real(np.poly(np.concatenate([[1j * w, -1j * w], others])))[::-1]
        count, hurwitz, w2 = routh(c)
        scale = np.prod([abs(x) + abs(y) for x in others for y in others]) * (1 + w) ** (2 * n)
        assert abs(hurwitz) <= 1e-12 * scale
        assert w2 == pytest.approx(w * w, rel=1e-9)


def _convex(kind, centre, k, low, x):
    y = x - centre
    return [k * y ** 2 + low, np.exp(k * y) - k * y + low - 1, k * np.abs(y) ** 1.5 + low][kind]


def test_convex_floor_is_below_the_least_value_and_near_it():
    """The bound a dip's search stops on: for seeded convex functions (parabolas, exponentials, |x|**1.5)
    sampled at a golden-section bracket's four points, the bound is at most the least value on the
    bracket (the least of 20,001 samples, itself at least the true one), and it nears that value as the bracket narrows; four points that are not
    convex give no bound."""
    rng = np.random.default_rng(5)
    golden = 0.5 * (3 - np.sqrt(5))
    for _ in range(200):
        centre, k, low = rng.uniform(-0.5, 1.5), rng.uniform(0.1, 10), rng.uniform(-1, 1)
        f = functools.partial(_convex, int(rng.integers(3)), centre, k, low)
        for width in (1.0, 1e-3):
            a = np.clip(centre, 0, 1) - width * rng.uniform(0, 1)
            b = a + width
            x1, x2 = a + golden * (b - a), b - golden * (b - a)
            least = min(f(x) for x in np.linspace(a, b, 20001))
            bound = _convex_floor(*(np.array([x]) for x in (a, x1, x2, b, f(a), f(x1), f(x2), f(b))))[0]
            assert bound <= least + 1e-12
            if width < 1e-2:
                assert least - bound <= 10 * k * width ** 1.5
    x = np.array([0.0, 0.4, 0.6, 1.0])
    assert _convex_floor(*(np.array([v]) for v in (*x, 0.0, 1.0, 0.0, 1.0)))[0] == -np.inf


def test_illinois_across_values_of_very_different_sizes():
    """A bracket whose ends' values are 1e17 apart (``H_(n-1)`` from standstill to 0.5 m/s is such): the
    root of ``(x - r) 10**(40 x)`` found to 1e-7 within the iterations allowed (the plain Illinois method
    halves one end's value 57 times)."""
    r = np.array([0.259, 0.01, 0.45])
    def f(rows, x):
        return (x - r[rows]) * 10.0 ** (40 * x)
    lo, hi = np.full(3, 3.1e-5), np.full(3, 0.5)
    x = _illinois(f, lo, hi, f(np.arange(3), lo), f(np.arange(3), hi), tol=1e-7)
    assert np.all(np.abs(x - r) <= 2e-7)


def test_the_benchmark_tyre_model_as_the_engine_names_it():
    """One row: Meijaard's benchmark with the default tyres, against ``bm.stability`` (modes followed and named)."""
    params = bm.parameters("benchmark")
    result = bm.stability(params, model="tyre")
    model = bm.Scenario("benchmark", model="tyre").build().model
    out = batch_critical_speeds(np.asarray(model.dynamic_coefficients)[None], model.families, 30.0)
    assert out["decided"][0]
    assert abs(out["weave_speed"][0] - result.weave_speeds[0]) <= TOL
    assert abs(out["capsize_speed"][0] - result.capsize_speeds[0]) <= TOL
    assert abs(out["stable_from"][0] - result.stable_speeds[0][0]) <= TOL
    assert abs(out["stable_to"][0] - result.stable_speeds[0][1]) <= TOL


def test_c_lam_tyre_sweep_rows_equal_bm_stability(tmp_path):
    """Issue 32: a ``model: tyre`` sweep of the benchmark's trail x steer tilt through ``bm.sweep``;
    every row equals ``bm.stability(params, model="tyre")`` of its parameters (the first weave and
    capsize crossings and the first stable range) to 1e-9 m/s, rows without a weave crossing or
    without a stable range included."""
    spec = tmp_path / "tyre.yaml"
    spec.write_text("bike: benchmark\nmodel: tyre\nvary:\n  c: {from: 0.0, to: 0.2, num: 21}\n"
                    "  lam: {from: 0.1, to: 0.5, num: 13}\n")
    result = bm.sweep(spec, tmp_path / "out")
    base = bm.parameters("benchmark")
    empty = {"weave_speed": 0, "stable_from": 0}
    for row in result:
        r = bm.stability(dataclasses.replace(base, c=row["c"], lam=row["lam"]), model="tyre")
        want = {"weave_speed": r.weave_speeds[0] if r.weave_speeds else None,
                "capsize_speed": r.capsize_speeds[0] if r.capsize_speeds else None,
                "stable_from": r.stable_speeds[0][0] if r.stable_speeds else None,
                "stable_to": r.stable_speeds[0][1] if r.stable_speeds else None}
        for k in SPEEDS:
            assert _same(row[k], want[k]), (row, k, want[k])
        for k in empty:
            empty[k] += want[k] is None
        assert row["error"] is None
    assert empty["weave_speed"] > 0 and empty["stable_from"] > 0       # rows with no crossing were compared


CASES = [("benchmark", None, "tyre", 0), ("jamis", "relaxed", "rider-lean", 1),
         ("jamis", "relaxed", "rider-lean+tyre", 2), ("browser_measured", None, "tyre", 3)]


@pytest.mark.parametrize("bike, rider, model, seed", CASES)
def test_random_perturbations_equal_the_engine(bike, rider, model, seed):
    """Seeded random perturbations (+-30 % of four parameters at a time) of several bicycles with the
    tyre and rider-lean members: the batch path's rows equal the engine's
    (:func:`~bikemass.sweep.evaluate.evaluate`) to 1e-9 m/s, and its total mass to 1e-12 relative."""
    path = os.path.join(os.path.dirname(bm.__file__), "..", "..", "frames", f"{bike}.yaml")
    scenario = bm.Scenario(path if bike == "browser_measured" else bike, rider, model=model)
    rng = np.random.default_rng(seed)
    engine_rows = _batch_against_engine(scenario, list(rng.choice(KEYS, 4, replace=False)), rng, 120)
    assert engine_rows <= 120 // 4              # the batch decides most rows


def _batch_against_engine(scenario, keys, rng, count):
    """The batch's rows of ``count`` seeded +-30 % perturbations of ``keys`` checked against the engine's
    (:func:`~bikemass.sweep.evaluate.evaluate`): the speeds to 1e-9 m/s, the total mass to 1e-12 relative, the
    errors equal; returns how many rows the batch sent to the engine."""
    base = scenario.build().values()
    changes = {k: base[k] * (1 + 0.3 * rng.uniform(-1, 1, count)) for k in keys}
    engine_rows = []

    def reference(config):
        engine_rows.append(config)
        return evaluate(scenario, config, 30.0)
    out = evaluate_member_batch(scenario, changes, count, 30.0, reference)
    for i in range(count):
        want = evaluate(scenario, {k: float(v[i]) for k, v in changes.items()}, 30.0)
        for k in SPEEDS:
            assert _same(out.values[k][i], want[k]), (i, k, out.values[k][i], want[k])
        if want["total_mass"] is not None:
            assert abs(out.values["total_mass"][i] - want["total_mass"]) <= 1e-12 * want["total_mass"]
        assert out.errors[i] == want["error"]
    return len(engine_rows)


def test_refused_and_non_numeric_rows_get_the_references_outcome():
    """Contract test of the routing: a value that is not a number and a parameter set the checks refuse go
    to the reference, which gives them its one-line reason; the others are decided by the batch."""
    scenario = bm.Scenario("benchmark", model="tyre")
    changes = {"c": [0.08, "x", 0.08], "w": [1.02, 1.02, -1.0]}
    out = evaluate_member_batch(scenario, changes, 3, 30.0, lambda c: evaluate(scenario, c, 30.0))
    assert out.errors[0] is None and out.errors[1] and out.errors[2]
    assert np.isnan(out.values["weave_speed"][1]) and np.isnan(out.values["weave_speed"][2])
    assert set(out.values) == set(NUMBERS)


@pytest.mark.parametrize("bike, rider, model, keys, seed", [
    ("benchmark", None, "tyre", ("CaF", "CaR", "c"), 4),
    ("jamis", "relaxed", "rider-lean", ("klean", "clean", "zU", "mB"), 5),
    ("jamis", "relaxed", "rider-lean", ("mU", "klean"), 6),
])
def test_a_members_inputs_in_the_batch_equal_the_engine(bike, rider, model, keys, seed):
    """A member's own inputs (the tyres' cornering coefficients, the lean joint's stiffness and damping, the upper
    body's height) varied by +-30 % (seeded) with or without benchmark names: the batch's rows equal the
    engine's to 1e-9 m/s and its total mass to 1e-12 relative, and the batch decides most rows. Varying the
    upper body's mass changes the total mass, which the batch does not make from the 26 names: its probe
    sends every row to the engine (then the rows are the engine's own)."""
    engine_rows = _batch_against_engine(bm.Scenario(bike, rider, model=model), keys, np.random.default_rng(seed), 60)
    assert engine_rows == 60 if "mU" in keys else engine_rows <= 60 // 4
