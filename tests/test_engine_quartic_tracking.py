"""The Whipple bicycle's modes (the quartic path) tracked on eigenvalues alone
(``engine.eigen.quartic_tracked_sweep``: eigenvectors only at standstill and where roots meet; the
modes' eigenvectors made when first read).

* Contract tests (the fast path against the engine's own eigenvector tracking of every step,
  ``eigen_sweep`` + ``tracking.track``, its earlier path, switched on by disabling the fast one): on
  the benchmark bicycle and on 50 seeded random variants (every parameter times 0.9-1.1), the same
  labels, the same roots in the same columns (the same arithmetic gives them: to 1e-12 (1 + |root|)
  1/s, rounding only) and eigenvectors made when first read equal to the eager ones to 1e-12 (each
  is the same null vector of ``M s^2 + C s + K`` at its root).
* Reference (independent of the tracking): each eigenvector made when read satisfies
  ``A x = lambda x`` with the model's dynamic matrix to 1e-9 of ``|A|`` (the quartic's roots are
  polished to about 1e-13 relative; an eigenvector inherits that times the conditioning of the 2 x 2
  null space, a few orders at most near the weave's split).
"""

import pickle
import warnings

import numpy as np
import pytest

import bikemass as bm
from bikemass.analysis.engine import modes as modes_module
from bikemass.analysis.engine.eigen import has_quartic_path, quartic_tracked_sweep
from bikemass.analysis.engine.modes import follow_modes
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.models.family import build
from bikemass.models.parameters import NAMES

SPEEDS = speed_grid()
TOL = 1e-12


def _variants(count=50, spread=0.1, seed=3737):
    p = bm.parameters("benchmark")
    out = [pytest.param(p, id="benchmark")]
    rng = np.random.default_rng(seed)
    for i in range(count):
        q = p.replace(**{k: getattr(p, k) * rng.uniform(1 - spread, 1 + spread) for k in NAMES
                         if k != "g" and getattr(p, k) != 0})
        out.append(pytest.param(q, id=f"random-{i}"))
    return out


VARIANTS = _variants()


def _model(p):
    with warnings.catch_warnings():          # a variant may be implausible in some respect: computed as given
        warnings.simplefilter("ignore", bm.BikemassWarning)
        return build("whipple", p)


def _followed_by_eigenvectors(model, speeds):
    """``follow_modes`` on the engine's eigenvector path at every step (the fast path switched off)."""
    fast = modes_module._follow_quartic
    modes_module._follow_quartic = lambda *args: None
    try:
        return follow_modes(model, speeds)
    finally:
        modes_module._follow_quartic = fast


@pytest.mark.parametrize("p", VARIANTS)
def test_contract_quartic_modes_tracked_on_eigenvalues_are_those_tracked_by_eigenvectors(p):
    model = _model(p)
    assert has_quartic_path(model)
    fast, slow = follow_modes(model, SPEEDS), _followed_by_eigenvectors(model, SPEEDS)
    assert "eigenvectors" not in fast.__dict__            # not made until read
    assert fast.labels == slow.labels
    E = slow.eigenvalues
    assert np.abs(fast.eigenvalues - E).max() <= TOL * (1 + np.abs(E).max())
    assert np.abs(fast.eigenvectors - slow.eigenvectors).max() <= TOL


def test_lazily_made_quartic_eigenvectors_are_eigenvectors_made_once_and_pickled():
    model = _model(bm.parameters("benchmark"))
    modes = follow_modes(model, SPEEDS)
    X, E = modes.eigenvectors, modes.eigenvalues
    assert modes.eigenvectors is X and not X.flags.writeable
    A = model.dynamic_matrix(SPEEDS)
    residual = np.abs(A @ X - X * E[:, None, :]).max(axis=(1, 2)) / np.abs(A).max(axis=(1, 2))
    assert residual.max() <= 1e-9
    np.testing.assert_allclose(np.linalg.norm(X, axis=1), 1.0, rtol=0, atol=1e-12)
    back = pickle.loads(pickle.dumps(follow_modes(model, SPEEDS)))
    np.testing.assert_array_equal(back.eigenvectors, X)


def test_contract_the_quartic_sweep_gets_eigenvectors_only_where_roots_meet_and_where_asked():
    model = _model(bm.parameters("benchmark"))
    sweep, _, _ = quartic_tracked_sweep(model, SPEEDS, need=[0, 300])
    assert 0 in sweep.rows and 300 in sweep.rows
    assert len(sweep.rows) < 20                           # the weave's split near 0.7 m/s, not 601 speeds
    for row in (0, 300):
        X = sweep.vectors_at(row)
        A = model.dynamic_matrix(SPEEDS[row])
        np.testing.assert_allclose(A @ X, X * sweep.values[row], atol=1e-9 * np.abs(A).max())


def test_contract_stability_of_random_variants_is_that_of_the_eigenvector_tracking():
    """The whole analysis (named crossings, ranges) on the fast path against the eigenvector path."""
    for param in VARIANTS[:8]:
        model = _model(param.values[0])
        fast = bm.stability(model)
        fast_path = modes_module._follow_quartic
        modes_module._follow_quartic = lambda *args: None
        try:
            slow = bm.stability(model)
        finally:
            modes_module._follow_quartic = fast_path
        assert [(c.kind, c.direction, c.mode) for c in fast.crossings] == \
            [(c.kind, c.direction, c.mode) for c in slow.crossings]
        np.testing.assert_allclose([c.speed for c in fast.crossings], [c.speed for c in slow.crossings],
                                   rtol=0, atol=1e-12)
        assert fast.ranges["strict"] == slow.ranges["strict"]
        assert dict(fast.mode_ranges) == dict(slow.mode_ranges)


@pytest.mark.parametrize("speeds", [[0.0], [5.0], [0.0, 0.05], [2.0, 2.5, 3.0], np.linspace(2.0, 10.0, 161),
                                    np.linspace(0.0, 30.0, 3001), np.linspace(0.3, 1.2, 50)],
                         ids=["standstill", "one-speed", "two-speeds", "from-2-coarse", "from-2", "fine", "the-split"])
@pytest.mark.parametrize("stiffness", [None, np.array([[3000.0, 100.0], [100.0, 2000.0]])], ids=["rigid", "flexible-static"])
def test_contract_quartic_tracking_on_other_grids_and_the_quasi_static_frame(speeds, stiffness):
    """Grids that start above standstill (extended down for the naming, the extension dropped), a
    single speed, a fine grid and one around the weave's split; the rigid and the quasi-static frame."""
    model = bm.linear_model(bm.parameters("benchmark"), stiffness=stiffness)
    assert has_quartic_path(model)
    fast, slow = follow_modes(model, speeds), _followed_by_eigenvectors(model, speeds)
    assert fast.labels == slow.labels
    E = slow.eigenvalues
    assert np.abs(fast.eigenvalues - E).max() <= TOL * (1 + np.abs(E).max())
    assert np.abs(fast.eigenvectors - slow.eigenvectors).max() <= TOL
