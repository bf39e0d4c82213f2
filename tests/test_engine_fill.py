"""The richer members' grid without LAPACK at every speed (``engine.eigen.filled_values``: Newton's
method on the characteristic polynomial between LAPACK speeds) and their modes tracked on eigenvalues
alone (``engine.eigen.tracked_sweep``: eigenvectors only where roots meet).

* Reference: LAPACK's own eigenvalues (``scipy.linalg.eigvals``, a peer of the numpy call the fill
  replaces) at every one of the 601 speeds, on the Jamis's rider-lean, tyre, flexible (steel frame)
  and rider-lean + tyre members and on 12 seeded random variants of the benchmark bicycle (every
  parameter times 0.7-1.3) as tyre models: every root within 1e-10 (1 + |root|) 1/s of one of LAPACK's, one to
  one.  The Newton steps stop at 1e-12 relative; LAPACK's own error on these 6 x 6 and 8 x 8
  matrices is about 1e-15 of their norm (up to 1e4 for the tyres), so 1e-10 leaves room for both.
* Contract tests (the fast path against the engine's eigenvector tracking of every step,
  ``eigen_sweep`` + ``tracking.track``, its own earlier path): the same labels, the same roots in
  the same columns (to the 1e-10 above) and the same eigenvectors up to phase (1e-9).
"""

import pickle
import warnings

import numpy as np
import pytest
import scipy.linalg
from scipy.optimize import linear_sum_assignment

import bikemass as bm
from bikemass.analysis.engine import modes as modes_module
from bikemass.analysis.engine.eigen import filled_values, tracked_sweep
from bikemass.analysis.engine.modes import follow_modes
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.models.family import build
from bikemass.models.parameters import NAMES
from bikemass.scenario.scenario import parameters

SPEEDS = speed_grid()
TOL = 1e-10


def _members():
    out = []
    for member in ("rider-lean", "tyre", "flexible", "rider-lean+tyre"):
        built = bm.Scenario("jamis", "relaxed", "steel" if member == "flexible" else None, model=member).build()
        out.append(pytest.param(built.model, id=f"jamis-{member}"))
    rng = np.random.default_rng(37)
    p = parameters("benchmark")
    with warnings.catch_warnings():          # a variant may break a wheel's triangle inequality: computed as given
        warnings.simplefilter("ignore", bm.BikemassWarning)
        for i in range(12):
            q = p.replace(**{k: getattr(p, k) * rng.uniform(0.7, 1.3) for k in NAMES
                             if k != "g" and getattr(p, k) != 0})
            out.append(pytest.param(build("tyre", q), id=f"random-{i}-tyre"))
    return out


MODELS = _members()


def _same_roots(mine, lapack):
    """Largest distance (relative to 1 + |root|) of a one-to-one matching of two root sets."""
    cost = np.abs(mine[:, None] - lapack[None, :]) / (1 + np.abs(lapack[None, :]))
    r, c = linear_sum_assignment(cost)
    return cost[r, c].max()


@pytest.mark.parametrize("model", MODELS)
def test_the_filled_grid_holds_lapacks_roots_at_every_speed(model):
    A = model.dynamic_matrix(SPEEDS)
    values, candidates, _ = filled_values(model, SPEEDS, A)
    assert np.sum(candidates[:, 0] >= 0) > 0.9 * len(SPEEDS)      # continued, not LAPACK's, nearly everywhere
    worst = max(_same_roots(values[k], scipy.linalg.eigvals(A[k])) for k in range(len(SPEEDS)))
    assert worst <= TOL
    # a real root is exactly real, a complex one comes with its exact conjugate (what naming relies on)
    for row in values:
        complex_ = row[row.imag != 0]
        if len(complex_):
            assert np.all(np.min(np.abs(complex_[:, None] - complex_.conj()[None, :]), axis=1) == 0)


def _followed_by_eigenvectors(model, speeds):
    """``follow_modes`` on the engine's eigenvector path at every step (the fast path switched off)."""
    fast = modes_module._follow_fast
    modes_module._follow_fast = lambda *args: None
    try:
        return follow_modes(model, speeds)
    finally:
        modes_module._follow_fast = fast


@pytest.mark.parametrize("model", MODELS[:4])
def test_contract_modes_tracked_on_eigenvalues_are_those_tracked_by_eigenvectors(model):
    fast, slow = follow_modes(model, SPEEDS), _followed_by_eigenvectors(model, SPEEDS)
    assert fast.labels == slow.labels
    np.testing.assert_allclose(fast.eigenvalues, slow.eigenvalues, rtol=0,
                               atol=TOL * (1 + np.abs(slow.eigenvalues).max()))
    overlap = np.abs(np.einsum("kim,kim->km", fast.eigenvectors.conj(), slow.eigenvectors))
    assert np.abs(overlap - 1).max() <= 1e-9


def test_contract_the_sweep_gets_eigenvectors_only_where_roots_meet_and_where_asked():
    model = MODELS[1].values[0]
    sweep = tracked_sweep(model, SPEEDS, need=[0, 300])
    assert 0 in sweep.rows and 300 in sweep.rows
    assert len(sweep.rows) < len(SPEEDS) // 10
    for row in (0, 300):
        X = sweep.vectors_at(row)
        A = model.dynamic_matrix(SPEEDS[row])
        np.testing.assert_allclose(A @ X, X * sweep.values[row], atol=1e-9 * np.abs(A).max())


def test_lazy_eigenvectors_are_made_once_and_pickle_as_an_array():
    modes = follow_modes(MODELS[0].values[0], SPEEDS)
    assert "eigenvectors" not in modes.__dict__
    first = modes.eigenvectors
    assert modes.eigenvectors is first and not first.flags.writeable
    back = pickle.loads(pickle.dumps(follow_modes(MODELS[0].values[0], SPEEDS)))
    np.testing.assert_array_equal(back.eigenvectors, first)


def test_a_schedule_in_speed_takes_lapacks_roots_at_every_speed():
    """A closed loop with gains scheduled in speed is a polynomial piecewise (its coefficients are not
    one polynomial in v to interpolate): LAPACK's roots at every speed, exactly numpy's."""
    model = bm.linear_model(bm.parameters("benchmark"), model="tyre",
                            control={"steer-torque": {"roll-rate": {"speeds": [0, 1.5, 4.7], "gains": [0, 12.48, 0]}}})
    A = model.dynamic_matrix(SPEEDS)
    values, candidates, _ = filled_values(model, SPEEDS, A)
    assert np.all(candidates == -1)
    for k in range(0, len(SPEEDS), 25):
        assert _same_roots(values[k], np.linalg.eigvals(A[k])) == 0.0
