"""The scalar fast path of one Whipple configuration (:mod:`bikemass.analysis.engine.scalar`) and the
scipy-free speed polynomials of a two-coordinate model, against independent references.

* The critical speeds of the scalar path against the engine's general algorithm, which knows nothing
  of the closed form (the polynomial eigenvalue problems of the state matrix by scipy's QZ, each
  candidate refined by Brent's method on LAPACK's eigenvalues: ``crossings.axis_crossings``), on
  every thesis set and 60 random variants (seeded); the stable ranges against LAPACK's eigenvalues
  of the state matrix inside each interval; the benchmark's speeds against the 50-digit values.
* The Moebius-shifted companion matrix (numpy) against scipy's QZ on the same matrix polynomials.
"""

import numpy as np
import pytest

from bikemass.analysis.engine import crossings, polynomial, scalar
from bikemass.analysis.engine.compound import additive_coefficients, multiplicative_coefficients
from bikemass.analysis.engine.critical import critical_speeds, whipple_critical_speeds
from bikemass.analysis.engine.tracking import assignments
from bikemass.models.whipple import whipple_model
from test_engine import EXACT
from test_engine_models import _whipple_sets

SETS = _whipple_sets(60, seed=11)


def test_the_scalar_path_gives_the_benchmarks_exact_speeds():
    found = whipple_critical_speeds(SETS[-61][0])      # the benchmark set (thesis_set "Benchmark")
    assert found.weave_speed == pytest.approx(EXACT["weave"], abs=1e-12)
    assert found.capsize_speed == pytest.approx(EXACT["capsize"], abs=1e-12)
    assert len(found.stable) == 1
    assert found.stable[0] == pytest.approx((EXACT["weave"], EXACT["capsize"]), abs=1e-12)


@pytest.mark.parametrize("index", range(len(SETS)))
def test_the_scalar_path_agrees_with_the_general_engine(index):
    """Every crossing speed to 1e-9 m/s (the general path's Brent tolerance is 1e-13 m/s; the QZ
    candidates it refines are 1e-12 relative); the unstable count in each interval by LAPACK."""
    p, S = SETS[index]
    model = whipple_model(p, S)
    fast = whipple_critical_speeds(p, S)
    general = crossings.axis_crossings(model, 0.0, 30.0)
    assert [c.kind for c in fast.crossings] == [k for _, k, _ in general]
    assert [c.speed for c in fast.crossings] == pytest.approx([s for s, _, _ in general], abs=1e-9)
    assert [c.frequency for c in fast.crossings] == pytest.approx([w for _, _, w in general], abs=1e-7)
    ends = [0.0, *[s for s, _, _ in general], 30.0]
    at = crossings.Eigenvalues(model)
    stable = [(a, b) for a, b in zip(ends, ends[1:]) if b > a and np.all(at(0.5 * (a + b)).real < 0)]
    merged = []
    for a, b in stable:
        if merged and merged[-1][1] == a:
            merged[-1] = (merged[-1][0], b)
        else:
            merged.append((a, b))
    assert len(fast.stable) == len(merged)
    for got, want in zip(fast.stable, merged):
        assert got == pytest.approx(want, abs=1e-9)
    # the model's own path (its pieces from the built matrices) is the same computation
    built = critical_speeds(model)
    assert [c.speed for c in built.crossings] == pytest.approx([c.speed for c in fast.crossings], abs=1e-9)
    assert [(c.kind, c.direction, c.mode) for c in built.crossings] == \
        [(c.kind, c.direction, c.mode) for c in fast.crossings]


def test_the_scalar_pieces_are_the_closed_forms_of_the_built_model():
    """Contract test: the pieces from the parameters (no model) and from the model's matrices."""
    for p, S in SETS[:20]:
        a = scalar.whipple_pieces(p, S)
        b = scalar.model_pieces(whipple_model(p, S))
        for key in a:
            assert a[key] == pytest.approx(b[key], rel=1e-12, abs=1e-12 * max(map(abs, b.values())))


def test_moebius_shifted_speed_polynomials_match_qz():
    """The real roots of every speed polynomial of a Whipple model (det A, the additive compound, the
    circle conditions) by the shifted companion matrix and by scipy's QZ, to 1e-10 relative; the double
    root of the additive compound at standstill (two pairs on the axis at v = 0) lands within 1e-13 of
    0 either way, where the engine takes no crossing (``crossings.MERGE_TOL``)."""
    for p, S in SETS[::7]:
        P = crossings.balanced(crossings.Eigenvalues(whipple_model(p, S)).coefficients)
        shifted = P.copy()
        shifted[0] = shifted[0] - 2.0 * np.eye(4)
        C2 = multiplicative_coefficients(P)
        C2[0] = C2[0] - 4.0 * np.eye(6)
        for Q in (P, additive_coefficients(P), shifted, C2):
            fast = polynomial.real_roots(Q, 1e-9, 30.0, shifted=True)
            qz = polynomial.real_roots(Q, 1e-9, 30.0)
            assert fast == pytest.approx(qz, rel=1e-10, abs=1e-10)


def test_brute_force_assignment_is_optimal():
    """The permutations tried at once give scipy's optimal cost on random 4 x 4 and 3 x 3 costs."""
    from scipy.optimize import linear_sum_assignment
    rng = np.random.default_rng(3)
    for m in (3, 4):
        costs = rng.uniform(size=(200, m, m))
        got = assignments(costs)
        for c, g in zip(costs, got):
            assert c[np.arange(m), g].sum() == pytest.approx(c[np.arange(m), linear_sum_assignment(c)[1]].sum(),
                                                             abs=1e-14)


@pytest.mark.parametrize("argv", [["stability", "benchmark", "--format", "json"], ["params", "benchmark"],
                                  ["simulate", "benchmark", "--speed", "5", "--duration", "1"]])
def test_the_whipple_commands_load_no_scipy(argv):
    """The Whipple bicycle's stability, parameters and time response need no scipy module (its import
    alone is about twice numpy's): issue 37's start-up."""
    import subprocess
    import sys
    code = ("import sys; from bikemass.cli.main import main; sys.argv[0] = 'bikemass'; code = main(sys.argv[1:]); "
            "sys.stderr.write('SCIPY ' + str(sorted(m for m in sys.modules if m.split('.')[0] == 'scipy')[:3]) + '\\n'); "
            "sys.exit(code)")
    done = subprocess.run([sys.executable, "-c", code, *argv], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "SCIPY []" in done.stderr


def test_contract_following_many_models_at_once_is_following_each():
    """Contract test: the modes of 40 random Whipple variants followed as one sequence (the Monte
    Carlo's path) are exactly those each gives alone; a richer member is left to the caller."""
    import bikemass as bm
    from bikemass.analysis.engine.modes import follow_many, follow_modes
    models = [whipple_model(p, S) for p, S in SETS[::2][:40]]
    speeds = np.linspace(0.0, 10.0, 101)
    many, labels = follow_many(models, speeds)
    for model, values, names in zip(models, many, labels):
        alone = follow_modes(model, speeds)
        assert names == alone.labels
        assert np.array_equal(values, alone.eigenvalues)
    tyre = bm.linear_model(bm.parameters("benchmark"), model="tyre")
    assert follow_many([tyre, tyre], speeds) is None
