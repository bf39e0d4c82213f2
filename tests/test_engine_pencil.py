"""The trimmed linearisation of a quadratic matrix polynomial whose leading coefficient has low rank
(``engine.polynomial._pencil``): its finite eigenvalues are the polynomial's.

* Reference: the companion pencil of the same polynomial (the textbook linearisation, size ``2 m``),
  solved by ``scipy.linalg.eig`` on its own (every root of modulus below 1e4 to 1e-8 relative); and, independently of either pencil, each root ``t`` makes
  ``sum_k t**k Q[k]`` singular (its least singular value below 1e-10 of its largest).
* Cases: seeded random quadratics of sizes 20-40 with leading coefficients of rank 1-6, and the
  compound matrices of the flexible Jamis (28 x 28) that the crossings solve.
"""

import numpy as np
import pytest
import scipy.linalg

import bikemass as bm
from bikemass.analysis.engine import polynomial
from bikemass.analysis.engine.compound import additive_coefficients
from bikemass.analysis.engine.crossings import Eigenvalues


def companion_roots(Q):
    d, m = len(Q) - 1, Q.shape[-1]
    L0, L1 = np.zeros((d * m, d * m)), np.eye(d * m)
    L0[:-m, m:] = np.eye((d - 1) * m)
    L0[-m:] = -np.concatenate(list(Q[:-1]), axis=1)
    L1[-m:, -m:] = Q[-1]
    alpha, beta = scipy.linalg.eig(L0, L1, right=False, homogeneous_eigvals=True)
    finite = np.abs(beta) > 1e-13 * np.abs(alpha)
    return alpha[finite] / beta[finite]


def cases():
    rng = np.random.default_rng(32)
    out = []
    for k, (m, r) in enumerate([(20, 1), (24, 3), (28, 6), (40, 2)]):
        Q = rng.normal(size=(3, m, m))
        Q[2] = rng.normal(size=(m, r)) @ rng.normal(size=(r, m))
        out.append(pytest.param(Q, id=f"random-{m}-rank-{r}"))
    model = bm.Scenario("jamis", "relaxed", "steel", model="flexible").build().model
    out.append(pytest.param(additive_coefficients(Eigenvalues(model).balanced), id="jamis-flexible-compound"))
    return out


@pytest.mark.parametrize("Q", cases())
def test_the_trimmed_pencil_has_the_polynomials_finite_roots(Q):
    L0, L1 = polynomial._pencil(Q)
    m = Q.shape[-1]
    assert len(L0) < 2 * m                                   # trimmed, not the companion
    alpha, beta = scipy.linalg.eig(L0, L1, right=False, homogeneous_eigvals=True)
    mine = alpha[np.abs(beta) > 1e-13 * np.abs(alpha)] / beta[np.abs(beta) > 1e-13 * np.abs(alpha)]
    theirs = companion_roots(Q)
    # the roots of a size that means something (speeds, scaled: a polynomial whose leading coefficient
    # is singular has infinite roots, which rounding leaves at 1e9 and beyond in either pencil)
    mine, theirs = mine[np.abs(mine) < 1e4], theirs[np.abs(theirs) < 1e4]
    assert len(mine) == len(theirs)
    for t in theirs:
        assert np.min(np.abs(mine - t)) <= 1e-8 * (1 + abs(t))
    for t in mine:
        sigma = np.linalg.svd(Q[0] + t * Q[1] + t * t * Q[2], compute_uv=False)
        assert sigma[-1] <= 1e-10 * sigma[0]


def test_a_full_rank_or_small_quadratic_keeps_the_companion_pencil():
    rng = np.random.default_rng(5)
    full = rng.normal(size=(3, 24, 24))
    small = rng.normal(size=(3, 10, 10))
    small[2] = np.outer(small[2][0], small[2][1])
    assert len(polynomial._pencil(full)[0]) == 48
    assert len(polynomial._pencil(small)[0]) == 20
