"""The flexible member: the Whipple bicycle with a twisting rear frame and a bending fork
(bikemass.models.derive.flexible, bikemass.models.flexible).  Checked against

* Meijaard et al. (2007)'s published matrices (the roll-steer block, any compliance);
* an independent numerical Kane linearisation in plain numpy (tests/flexible_reference.py: exact
  rotations, a numerical pitch, velocities and accelerations by finite differences), every matrix at
  speed, random axes and inertias;
* the potential energy's Hessian for the static stiffness;
* a hand derivation of the heading's kinematics (the no-slip front contact);
* the limits: infinitely stiff compliances give the Whipple bicycle (and the tyre or leaning-rider
  model without the member), a finite stiffness k differs from it as 1/k;
* the published wobble band for the Jamis with the Relaxed rider and a steel frame and fork.

The shipped code against a fresh derivation: tests/test_models_derive.py (every combination).
"""

from dataclasses import replace

import numpy as np
import pytest

import bikemass as bm
import flexible_reference as reference
from bikemass.models.compliance import Compliance
from bikemass.models.family import build, linear_model, state_coefficients, values
from bikemass.models.family import values as family_values      # a test below names its eigenvalues values
from bikemass.fe.flexible import compliances
from bikemass.models.flexible import COORDINATES, Compliances
from bikemass.models.lean import LeanJoint
from bikemass.rider.lean_split import rider_lean_parameters
from bikemass.models.tyres import Tyre, Tyres
from bikemass.models.whipple import whipple_model
from bikemass.models.canonical import canonical_matrices

BENCHMARK = bm.load_bicycle("benchmark").published


def random_compliances(seed):
    """Compliances with random axes, stiffnesses, modal inertias, damping ratios and steering damping."""
    rng = np.random.default_rng(seed)
    made = []
    for name in ("frame", "fork"):
        angle = rng.uniform(0, 2 * np.pi)
        made.append(Compliance(name, (rng.uniform(0.3, 1.2), rng.uniform(-1.2, -0.2)), (np.cos(angle), np.sin(angle)),
                               rng.uniform(1e3, 1e4), rng.uniform(0.05, 0.3), rng.uniform(-0.2, 0.2, 2),
                               rng.uniform(0.01, 0.1)))
    made = [replace(c, damping_ratio=rng.uniform(0.01, 0.2)) for c in made]
    return Compliances(*made, steer_damping=rng.uniform(0.1, 2.0))


def random_values(seed, rigid=None):
    """The flexible model's values: a rigid set (the benchmark unless given) and random compliances."""
    return values("flexible", rigid or BENCHMARK, compliances=random_compliances(seed))


def matrices(p, damping=False):
    """``(M, C1, K0, K2)`` of the flexible model at values ``p`` (from its LinearModel's mechanics); with
    ``damping``, ``(M, C0, C1, K0, K2)``."""
    mech = linear_model("flexible", p).mechanics
    if damping:
        return mech.M, mech.C[0], mech.C[1], mech.K[0], mech.K[2]
    return mech.M, mech.C[1], mech.K[0], mech.K[2]


@pytest.fixture(scope="module")
def jamis():
    bike = bm.load_bicycle("jamis")
    return bike, bm.parameters(bike, bm.load_rider("relaxed")), compliances(bike, "steel")


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_roll_steer_block_is_meijaard(seed, jamis):
    """Whatever the compliances, the equations' roll-steer block is the rigid bicycle's: Meijaard et
    al. (2007), Appendix A (bikemass.models.canonical), for the benchmark and the Jamis."""
    for rigid in (BENCHMARK, jamis[1]):
        M, C1, K0, K2 = matrices(random_values(seed, rigid))
        m = canonical_matrices(rigid)
        for ours, theirs in ((M, m.M), (C1, m.C1), (K0, m.gK0), (K2, m.K2)):
            np.testing.assert_allclose(ours[:2, :2], theirs, rtol=1e-12, atol=1e-12 * np.abs(theirs).max())


@pytest.mark.parametrize("seed, speed", [(3, 5.0), (4, 2.0)])
def test_independent_numerical_kane(seed, speed):
    """M, C(v) and K(v) of all four coordinates equal an independent numerical linearisation of Kane's
    equations (finite differences of exact rotations; observed agreement 1e-8 .. 1e-6), the frame's, the
    fork's and the steering bearing's dampers included (random coefficients; the reference adds each as
    a Rayleigh dissipation of its own coordinate's rate)."""
    p = random_values(seed)
    assert min(p["cr"], p["cf"], p["cs"]) > 0
    M, C0, C1, K0, K2 = matrices(p, damping=True)
    Mn, Cn, Kn = reference.linear_matrices(p, speed)
    for ours, theirs in ((M, Mn), (C0 + speed * C1, Cn), (K0 + speed ** 2 * K2, Kn)):
        np.testing.assert_allclose(ours, theirs, atol=2e-5 * np.abs(ours).max())


def test_static_stiffness_is_the_potential_hessian():
    """K0 is the Hessian of the potential energy (gravity on every mass, the springs) with the pitch
    keeping the front wheel on the ground."""
    p = random_values(5)
    np.testing.assert_allclose(matrices(p)[2], reference.static_stiffness(p), rtol=1e-6, atol=1e-6)


def test_heading_by_hand():
    """The rear frame's heading rate by hand: the front contact's lateral velocity ``v psi + w psi' +
    d_i q_i'`` (``d_i`` the contact's sideways displacement per unit coordinate, the steer's
    ``-c cos(lam)``) equals ``v`` times the front wheel's heading ``psi + e_i q_i`` (``e_i`` the
    coordinate's yaw component: ``cos(lam)`` for the steer, ``n_z`` for a compliance), so
    ``psi' = (v e . q - d . q') / w``."""
    p = random_values(6)
    model = linear_model("flexible", p)
    row = model.state_index("heading")
    w, c, lam = p["w"], p["c"], p["lam"]
    d, e = [0.0, -c * np.cos(lam)], [0.0, np.cos(lam)]
    for key in "rf":
        d.append(p[f"n{key}z"] * (w - p[f"x{key}"]) + p[f"n{key}x"] * p[f"z{key}"])
        e.append(p[f"n{key}z"])
    np.testing.assert_allclose(model.A[0][row, 4:8], -np.array(d) / w, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(model.A[1][row, 0:4], np.array(e) / w, rtol=1e-12, atol=1e-15)


def test_elementwise_over_parameter_arrays():
    """The generated code broadcasts: parameters as arrays give each point's state matrix."""
    points = [random_values(s) for s in (10, 11, 12)]
    stacked = {k: np.array([p[k] for p in points]) for k in points[0]}
    A, _ = state_coefficients("flexible", stacked)
    for i, p in enumerate(points):
        np.testing.assert_allclose(A[i], linear_model("flexible", p).A, rtol=1e-14, atol=1e-14)


def test_infinite_stiffness_is_the_rigid_bicycle(jamis):
    """Both compliances infinitely stiff (their coordinates held): the Whipple bicycle's eigenvalues
    (Meijaard's matrices) to 1e-12; a finite stiffness k times a factor f: the four bicycle roots
    differ from those by a constant over f (1/k), so the limit is the rigid bicycle."""
    _, params, flexible = jamis
    rigid = whipple_model(params)
    for v in (1.0, 5.0, 8.0):
        expected = np.sort_complex(np.linalg.eigvals(rigid.dynamic_matrix(v)))
        held = build("flexible", params, compliances=flexible.rigid())
        limit = np.sort_complex(np.linalg.eigvals(held.dynamic_matrix(v)))
        np.testing.assert_allclose(limit, expected, atol=1e-12 * np.abs(expected).max())
        errors = []
        for factor in (1e4, 1e6, 1e8):
            roots = np.linalg.eigvals(build("flexible", params, compliances=flexible.scaled(factor)).dynamic_matrix(v))
            slow = roots[np.argsort(np.abs(roots))[:4]]
            errors.append(max(np.min(np.abs(slow - x)) for x in expected) * factor)
        np.testing.assert_allclose(errors, errors[0], rtol=2e-2)
        assert errors[0] / 1e10 < 1e-9


def test_combinations_without_their_compliances(jamis):
    """With both compliances held, ``tyre+flexible`` is the tyre model and ``rider-lean+tyre+flexible``
    the leaning rider on tyres, to round-off: the combinations' code carries the other members intact."""
    bike, params, flexible = jamis
    lean = rider_lean_parameters(bike, bm.seated_rider(bike, "relaxed"))
    for model, rigid_params in (("tyre", params), ("rider-lean+tyre", lean), ("rider-lean", lean)):
        ours = build(f"{model}+flexible", rigid_params, compliances=flexible.rigid())
        theirs = build(model, rigid_params)
        assert ours.state_names == theirs.state_names and ours.families == theirs.families
        for v in (2.0, 8.0):
            np.testing.assert_allclose(ours.state_matrix(v), theirs.state_matrix(v), rtol=1e-10,
                                       atol=1e-10 * np.abs(theirs.state_matrix(v)).max())


@pytest.mark.parametrize("speed", [1.0, 4.0, 8.0])
def test_combinations_in_the_other_members_limits(jamis, speed):
    """The flexible member's combinations reduce to the flexible model where the other members vanish:
    very stiff tyres (1e5 /rad, no camber, 1e-5 m) give back ``flexible``'s roots (1e-3, as the tyre
    member's own knife-edge limit), a stiff hip joint (1e9 N m/rad) ``flexible`` of the rigid rider (1e-5)."""
    bike, params, flexible = jamis
    stiff = Tyre(cornering_coefficient=1e5, camber_coefficient=0.0, relaxation_length=1e-5)
    lean = rider_lean_parameters(bike, bm.seated_rider(bike, "relaxed"), joint=LeanJoint(stiffness=1e9, damping=0.0))
    expected = np.linalg.eigvals(build("flexible", lean.rigid(), compliances=flexible).dynamic_matrix(speed))
    for model, rigid_params, tyres, rtol in (("tyre+flexible", lean.rigid(), Tyres(stiff, stiff), 1e-3),
                                              ("rider-lean+flexible", lean, None, 1e-5),
                                              ("rider-lean+tyre+flexible", lean, Tyres(stiff, stiff), 1e-3)):
        roots = np.linalg.eigvals(build(model, rigid_params, tyres, compliances=flexible).dynamic_matrix(speed))
        for z in expected:
            assert np.min(np.abs(roots - z)) <= rtol * abs(z), (model, z)


def modes_at(model, speed):
    """Eigenvalues and the coordinates' part of the eigenvectors of the dynamic block at ``speed``."""
    values, vectors = np.linalg.eig(model.dynamic_matrix(speed))
    return values, vectors[:model.n_dynamic // 2]


def test_jamis_wobble_in_the_published_band(jamis):
    """The Jamis with the Relaxed rider, steel frame and fork: of the two oscillations of the
    compliances' family (wobble), the slower one, followed from standstill to 8 m/s, is steer-dominated
    (steer the largest coordinate of its shape) at about 7.35 Hz, inside the 6-9 Hz of Ploechl et al.
    (2012); the faster one is the fork's own bending vibration (64 Hz).  The frequency at 8 m/s
    against the independent numerical Kane linearisation (tests/flexible_reference.py) of the same
    values: a root of ``det(M s^2 + C s + K) = 0`` within 1e-4 relative (its matrices agree to
    ~1e-6)."""
    _, params, flexible = jamis
    model = build("flexible", params, compliances=flexible)
    assert dict(model.families)["wobble"] == (2, 3, 6, 7)
    standstill, X = np.linalg.eig(model.dynamic_matrix(0.0))
    share = np.abs(X * np.linalg.inv(X).T)                 # participation factors
    roots = standstill[share[[2, 3, 6, 7]].sum(axis=0) > 0.5]
    frequencies = np.sort(np.abs(roots.imag)) / (2 * np.pi)
    assert len(roots) == 4 and frequencies[0] > 3.0
    root = 1j * 2 * np.pi * frequencies[0]
    for v in np.linspace(0, 8, 161)[1:]:
        values, vectors = modes_at(model, v)
        k = np.argmin(np.abs(values - root))
        root = values[k]
    frequency = abs(root.imag) / (2 * np.pi)
    assert 6.0 <= frequency <= 9.0
    Mn, Cn, Kn = reference.linear_matrices(family_values("flexible", params, compliances=flexible), 8.0)
    n = len(Mn)
    A = np.block([[np.zeros((n, n)), np.eye(n)], [-np.linalg.solve(Mn, Kn), -np.linalg.solve(Mn, Cn)]])
    independent = np.linalg.eigvals(A)
    assert np.min(np.abs(independent - root)) <= 1e-4 * abs(root)
    assert np.argmax(np.abs(vectors[:, k])) == 1            # steer-dominated
    assert np.max(np.abs(values.imag)) / (2 * np.pi) > 30


def test_frame_only(jamis):
    """A compliance held rigid drops its coordinate and its equation."""
    _, params, flexible = jamis
    model = build("flexible", params, compliances=Compliances(frame=flexible.frame))
    assert model.state_names[:6] == ("roll-angle", "steer-angle", "frame-twist", "roll-rate", "steer-rate",
                                     "frame-twist-rate")
    assert dict(model.families)["wobble"] == (2, 5)
    assert Compliances(frame=flexible.frame).held == (COORDINATES["fork"],)
    assert values("flexible", params, compliances=flexible)["kr"] == flexible.frame.stiffness


def test_modal_particle_carries_the_field(jamis):
    """The particle that carries a Ritz field (mass L**2/m at (Jz/L, -Jx/L), sideways m/L per radian) has
    the field's L, J and m; tubes without inertia carry none."""
    _, params, flexible = jamis
    p = values("flexible", params, compliances=flexible)
    for key, c in (("r", flexible.frame), ("f", flexible.fork)):
        mass, x, z, d = (p[f"{s}t{key}"] for s in "mxzd")
        assert mass * d == pytest.approx(c.modal_momentum, rel=1e-14)
        assert (-z * mass * d, x * mass * d) == pytest.approx(c.modal_moment, rel=1e-14)
        assert mass * d ** 2 == pytest.approx(c.modal_mass, rel=1e-14)
    empty = values("flexible", params, compliances=flexible.massless())
    assert empty["mtr"] == empty["mtf"] == 0.0
