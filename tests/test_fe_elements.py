"""Beam element checks against closed-form beam theory (no reference tables)."""

import numpy as np
import pytest

from bikemass.fe.elements import direction_cosines, local_matrices, to_global
from bikemass.fe.properties import shear_coefficient, torsion_constant
from bikemass.mass.sections import RoundSection, SquareSection

L, E, G, RHO, A, I, J, KAPPA = 0.4, 205e9, 80e9, 7850.0, 1.5e-4, 2.0e-8, 4.0e-8, 0.53


def cantilever(timoshenko=True):
    """Flexibility (6x6) of the free end of a one-element cantilever (node 1 clamped)."""
    K, _ = local_matrices([L], E, G, RHO, A, I, J, 2 * I, KAPPA, timoshenko=timoshenko)
    return np.linalg.inv(K[0][6:, 6:])


def test_cantilever_tip_matches_timoshenko_closed_form():
    F = cantilever()
    bend = L**3 / (3 * E * I) + L / (KAPPA * G * A)  # PL^3/3EI + PL/(kappa G A), exact for any L
    np.testing.assert_allclose([F[1, 1], F[2, 2]], bend, rtol=1e-12)
    np.testing.assert_allclose([F[5, 1], -F[4, 2]], L**2 / (2 * E * I), rtol=1e-12)
    np.testing.assert_allclose([F[5, 5], F[4, 4]], L / (E * I), rtol=1e-12)
    np.testing.assert_allclose(F[0, 0], L / (E * A), rtol=1e-12)
    np.testing.assert_allclose(F[3, 3], L / (G * J), rtol=1e-12)


def test_euler_bernoulli_option_drops_shear_only():
    F = cantilever(timoshenko=False)
    np.testing.assert_allclose(F[1, 1], L**3 / (3 * E * I), rtol=1e-12)
    np.testing.assert_allclose(F[5, 5], L / (E * I), rtol=1e-12)


def test_euler_bernoulli_mass_is_the_hermite_consistent_mass_plus_rotary_inertia():
    _, M = local_matrices([L], E, G, RHO, A, I, J, 2 * I, KAPPA, timoshenko=False)
    hermite = RHO * A * L / 420 * np.array([[156, 22 * L, 54, -13 * L], [22 * L, 4 * L**2, 13 * L, -3 * L**2],
                                            [54, 13 * L, 156, -22 * L], [-13 * L, -3 * L**2, -22 * L, 4 * L**2]])
    rotary = RHO * I / (30 * L) * np.array([[36, 3 * L, -36, 3 * L], [3 * L, 4 * L**2, -3 * L, -L**2],
                                            [-36, -3 * L, 36, -3 * L], [3 * L, -L**2, -3 * L, 4 * L**2]])
    idx = np.ix_([1, 5, 7, 11], [1, 5, 7, 11])
    np.testing.assert_allclose(M[0][idx], hermite + rotary, rtol=1e-12, atol=1e-16)


@pytest.mark.parametrize("timoshenko", [True, False])
def test_global_matrices_are_symmetric_and_rigid_motions_cost_nothing(timoshenko):
    rng = np.random.default_rng(1)
    start, end = rng.normal(size=(5, 3)), rng.normal(size=(5, 3))
    R = direction_cosines(start, end)
    np.testing.assert_allclose(R @ R.transpose(0, 2, 1), np.broadcast_to(np.eye(3), (5, 3, 3)), atol=1e-14)
    length = np.linalg.norm(end - start, axis=1)
    k, m = local_matrices(length, E, G, RHO, A, I, J, 2 * I, KAPPA, timoshenko=timoshenko)
    K, M = to_global(k, R), to_global(m, R)
    np.testing.assert_allclose(K, K.transpose(0, 2, 1), rtol=0, atol=1e-9 * np.abs(K).max())
    for e in range(5):
        for t in np.eye(3):  # translation and rotation about node 1: u = t, u = t x (x - x1)
            rigid_t = np.r_[t, 0, 0, 0, t, 0, 0, 0]
            arm = end[e] - start[e]
            rigid_r = np.r_[0, 0, 0, t, np.cross(t, arm), t]
            for u in (rigid_t, rigid_r):
                assert np.abs(K[e] @ u).max() < 1e-9 * np.abs(K[e]).max()
        # Total translational mass: u^T M u = rho A L for a unit rigid translation.
        np.testing.assert_allclose(rigid_t @ M[e] @ rigid_t, RHO * A * length[e], rtol=1e-12)


def test_cowper_shear_coefficients():
    nu = 0.3
    solid = RoundSection(0.02, 0.01)
    assert shear_coefficient(solid, nu) == pytest.approx(6 * (1 + nu) / (7 + 6 * nu))
    thin = RoundSection(0.02, 1e-7)
    assert shear_coefficient(thin, nu) == pytest.approx(2 * (1 + nu) / (4 + 3 * nu), rel=1e-5)
    assert shear_coefficient(SquareSection(0.0254, 0.00165), nu) == pytest.approx(20 * 1.3 / (48 + 39 * 0.3))


def test_torsion_constants():
    tube = RoundSection(0.03, 0.001)
    assert torsion_constant(tube) == pytest.approx(np.pi / 32 * (0.03**4 - 0.028**4))
    # Bredt, thin wall: 4 A_m^2 t / perimeter with mid-line side b - t.
    b, t = 0.0254, 0.00165
    assert torsion_constant(SquareSection(b, t)) == pytest.approx(4 * (b - t) ** 4 * t / (4 * (b - t)))
