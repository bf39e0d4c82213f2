"""The flexible member (bikemass.models.flexible): the Whipple bicycle with a twisting rear frame and a
bending fork.  Checked against

* Meijaard et al. (2007)'s published matrices (the roll-steer block, any compliance);
* an independent numerical Kane linearisation in plain numpy (tests/flexible_reference.py: exact
  rotations, numerical pitch, velocities and accelerations by finite differences), every matrix at
  speed, random axes and inertias;
* the potential energy's Hessian for the static stiffness;
* a hand derivation of the heading's kinematics (the no-slip front contact);
* the sympy derivation itself (the shipped code evaluates it);
* the limits: infinitely stiff compliances give the Whipple bicycle, a finite stiffness k differs
  from it as 1/k;
* the published wobble band for the Jamis with the Relaxed rider and a steel frame and fork.
"""

import numpy as np
import pytest
import sympy as sm

import bikemass as bm
import flexible_reference as reference
from bikemass.models.flexible import FlexibleParameters, WOBBLE, flexible_matrices, flexible_model, flexible_parameters
from bikemass.models.generated import flexible_matrices as generated
from bikemass.models.whipple import whipple_model
from bikemass.stability.matrices import canonical_matrices


def random_values(seed, rigid=None):
    """Parameter values of the generated module: a rigid set (the benchmark unless given) and random
    compliance axes, stiffnesses and modal inertias."""
    rng = np.random.default_rng(seed)
    p = (rigid or bm.load_bicycle("benchmark").published).to_dict()
    for key in "rf":
        p[f"x{key}"], p[f"z{key}"] = rng.uniform(0.3, 1.2), rng.uniform(-1.2, -0.2)
        angle = rng.uniform(0, 2 * np.pi)
        p[f"n{key}x"], p[f"n{key}z"] = np.cos(angle), np.sin(angle)
        p[f"k{key}"] = rng.uniform(1e3, 1e4)
        p[f"L{key}"], p[f"J{key}x"], p[f"J{key}z"] = rng.uniform(0.05, 0.3), rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2)
        p[f"m{key}"] = rng.uniform(0.01, 0.1)
    return p


@pytest.fixture(scope="module")
def jamis():
    bike = bm.load_bicycle("jamis")
    params = bm.parameters(bike, bm.load_rider("relaxed"))
    return params, flexible_parameters(bike, "steel", params)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_roll_steer_block_is_meijaard(seed, jamis):
    """Whatever the compliances, the equations' roll-steer block is the rigid bicycle's: Meijaard et
    al. (2007), Appendix A (bikemass.stability.matrices), for the benchmark and the Jamis."""
    for rigid in (None, jamis[0]):
        p = random_values(seed, rigid)
        M, C1, K0, K2 = generated.matrices(p)
        m = canonical_matrices(rigid or bm.load_bicycle("benchmark").published)
        for ours, theirs in ((M, m.M), (C1, m.C1), (K0, m.gK0), (K2, m.K2)):
            np.testing.assert_allclose(ours[:2, :2], theirs, rtol=1e-12, atol=1e-12 * np.abs(theirs).max())


@pytest.mark.parametrize("seed, speed", [(3, 5.0), (4, 2.0)])
def test_independent_numerical_kane(seed, speed):
    """M, C(v) and K(v) of all four coordinates equal an independent numerical linearisation of Kane's
    equations (finite differences of exact rotations; observed agreement 1e-8 .. 1e-6)."""
    p = random_values(seed)
    M, C1, K0, K2 = generated.matrices(p)
    Mn, Cn, Kn = reference.linear_matrices(p, speed)
    for ours, theirs in ((M, Mn), (speed * C1, Cn), (K0 + speed ** 2 * K2, Kn)):
        np.testing.assert_allclose(ours, theirs, atol=2e-5 * np.abs(ours).max())


def test_static_stiffness_is_the_potential_hessian():
    """K0 is the Hessian of the potential energy (gravity on every mass, the springs) with the pitch
    keeping the front wheel on the ground."""
    p = random_values(5)
    np.testing.assert_allclose(generated.matrices(p)[2], reference.static_stiffness(p), rtol=1e-6, atol=1e-6)


def test_heading_by_hand():
    """The rear frame's heading rate by hand: the front contact's lateral velocity ``v psi + w psi' +
    d_i q_i'`` (``d_i`` the contact's sideways displacement per unit coordinate, the steer's
    ``c cos(lam)``) equals ``v`` times the front wheel's heading ``psi + e_i q_i`` (``e_i`` the
    coordinate's yaw component: ``cos(lam)`` for the steer, ``n_z`` for a compliance), so
    ``psi' = (v e . q - d . q') / w``."""
    p = random_values(6)
    H0, H1 = generated.heading(p)
    w, c, lam = p["w"], p["c"], p["lam"]
    d = [0.0, -c * np.cos(lam)]
    e = [0.0, np.cos(lam)]
    for key in "rf":
        d.append(p[f"n{key}z"] * (w - p[f"x{key}"]) + p[f"n{key}x"] * p[f"z{key}"])
        e.append(p[f"n{key}z"])
    np.testing.assert_allclose(H0, -np.array(d) / w, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(H1, np.array(e) / w, rtol=1e-12, atol=1e-15)


def test_shipped_code_is_the_derivation():
    """The generated module evaluates the sympy derivation's matrices (derived here again, about a
    minute): three random parameter points, 1e-12."""
    from bikemass.models.derive import flexible as derive
    symbols = derive._symbols()
    mats = derive.coefficients(symbols)
    for seed in (7, 8, 9):
        p = random_values(seed)
        values = {symbols[k]: v for k, v in p.items()}
        shipped = dict(zip(derive.OUTPUTS, generated.matrices(p))) | dict(zip(derive.HEADING, generated.heading(p)))
        for name, expr in mats.items():
            expected = np.array(expr.xreplace(values).evalf(), dtype=float).reshape(np.shape(shipped[name]))
            np.testing.assert_allclose(shipped[name], expected, rtol=1e-12, atol=1e-12 * np.abs(expected).max())


def test_elementwise_over_parameter_arrays():
    """The generated code broadcasts: parameters as arrays give the matrices of each point."""
    points = [random_values(s) for s in (10, 11, 12)]
    stacked = {k: np.array([p[k] for p in points]) for k in generated.PARAMETERS}
    batch = generated.matrices(stacked)
    for i, p in enumerate(points):
        for a, b in zip(batch, generated.matrices(p)):
            np.testing.assert_array_equal(a[i], b)


def test_infinite_stiffness_is_the_rigid_bicycle(jamis):
    """Both compliances infinitely stiff (their coordinates dropped): the Whipple bicycle's eigenvalues
    (Meijaard's matrices) to 1e-12; a finite stiffness k times a factor f: the four bicycle roots
    differ from those by a constant over f (1/k), so the limit is the rigid bicycle."""
    params, flexible = jamis
    rigid = whipple_model(params)
    for v in (1.0, 5.0, 8.0):
        expected = np.sort_complex(np.linalg.eigvals(rigid.dynamic_matrix(v)))
        limit = np.sort_complex(np.linalg.eigvals(flexible_model(flexible.rigid_limit()).dynamic_matrix(v)))
        np.testing.assert_allclose(limit, expected, atol=1e-12 * np.abs(expected).max())
        errors = []
        for factor in (1e4, 1e6, 1e8):
            roots = np.linalg.eigvals(flexible_model(flexible.scaled(stiffness=factor)).dynamic_matrix(v))
            slow = roots[np.argsort(np.abs(roots))[:4]]
            errors.append(max(np.min(np.abs(slow - x)) for x in expected) * factor)
        np.testing.assert_allclose(errors, errors[0], rtol=2e-2)
        assert errors[0] / 1e10 < 1e-9


def modes_at(model, speed):
    """Eigenvalues and coordinate-part eigenvectors of the dynamic block at ``speed``."""
    values, vectors = np.linalg.eig(model.dynamic_matrix(speed))
    n = model.n_dynamic // 2
    return values, vectors[:n]


def test_jamis_wobble_in_the_published_band(jamis):
    """The Jamis with the Relaxed rider, steel frame and fork: at 8 m/s the slower oscillation of the
    compliances' family (wobble) is steer-dominated (steer the largest coordinate of its shape) at
    7.35 Hz, inside the 6-9 Hz of Ploechl et al. (2012); the faster one is the fork's own bending
    vibration (64 Hz).  The family is named by the model (the engine's naming reads it)."""
    params, flexible = jamis
    model = flexible_model(flexible)
    assert dict(model.families)[WOBBLE] == (2, 3, 6, 7)
    values, _ = modes_at(model, 8.0)
    # the family's roots at standstill: the compliance states hold most of them (participation)
    standstill, X = np.linalg.eig(model.dynamic_matrix(0.0))
    share = np.abs(X * np.linalg.inv(X).T)
    wobble_roots = standstill[share[[2, 3, 6, 7]].sum(axis=0) > 0.5]
    frequencies = np.sort(np.abs(wobble_roots.imag)) / (2 * np.pi)
    assert len(wobble_roots) == 4 and frequencies[0] > 3.0
    # follow the slower pair from standstill to 8 m/s in small steps
    root = wobble_roots[np.argmin(np.abs(wobble_roots - 1j * 2 * np.pi * frequencies[0]))]
    for v in np.linspace(0, 8, 161)[1:]:
        roots, vectors = modes_at(model, v)
        k = np.argmin(np.abs(roots - root))
        root = roots[k]
    frequency = abs(root.imag) / (2 * np.pi)
    assert 6.0 <= frequency <= 9.0
    assert frequency == pytest.approx(7.35, abs=0.01)
    shape = np.abs(vectors[:, k])
    assert np.argmax(shape) == 1                          # steer-dominated
    other = values[np.argmax(np.abs(values.imag))]
    assert abs(other.imag) / (2 * np.pi) > 30


def test_rigid_compliances_drop_their_coordinates(jamis):
    params, flexible = jamis
    frame_only = FlexibleParameters(params, flexible.frame, None)
    assert frame_only.coordinates == (0, 1, 2)
    M, C1, K0, K2 = flexible_matrices(frame_only)
    assert M.shape == (3, 3)
    model = flexible_model(frame_only)
    assert model.state_names[:3] == ("roll-angle", "steer-angle", "frame-twist")
    assert flexible_model(flexible.rigid_limit()).name == "whipple"
