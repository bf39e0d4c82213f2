"""The flexible member: the Whipple bicycle with a twisting rear frame and a bending fork
(bikemass.models.members.flexible.derivation, bikemass.models.members.flexible.parameters).  Checked against

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
from bikemass.core.errors import InputError
from bikemass.models.compliance import DAMPING_RATIO, Compliance
from bikemass.models.family import build, linear_model, state_coefficients, values
from bikemass.models.family import values as family_values      # a test below names its eigenvalues values
from bikemass.fe.flexible import compliances
from bikemass.models.members.flexible.parameters import COORDINATES, STEER_DAMPING, Compliances
from bikemass.models.members.rider_lean.parameters import LeanJoint
from bikemass.rider.lean_split import rider_lean_parameters
from bikemass.models.members.tyre.parameters import TRAIL_TYRES, Tyre, Tyres
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
    differ from those by a constant over f (1/k), so the limit is the rigid bicycle (the member undamped:
    its steering damper would stay in the limit)."""
    _, params, flexible = jamis
    rigid = whipple_model(params)
    for v in (1.0, 5.0, 8.0):
        expected = np.sort_complex(np.linalg.eigvals(rigid.dynamic_matrix(v)))
        held = build("flexible", params, compliances=flexible.rigid())
        limit = np.sort_complex(np.linalg.eigvals(held.dynamic_matrix(v)))
        np.testing.assert_allclose(limit, expected, atol=1e-12 * np.abs(expected).max())
        errors = []
        for factor in (1e4, 1e6, 1e8):
            roots = np.linalg.eigvals(build("flexible", params, compliances=flexible.undamped().scaled(factor)).dynamic_matrix(v))
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
        roots = np.linalg.eigvals(build(model, rigid_params, tyres=tyres, compliances=flexible).dynamic_matrix(speed))
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


def test_clamped_inertias_are_the_parallel_axis_sums():
    """The inertia a compliance moves with its parent clamped, for axes where the sum is a hand calculation:
    the fork bending about the front axle's own x line (the wheel's IFxx plus the tubes' modal mass), and
    the frame twisting about the vertical through the front frame's centre of mass (IHzz, the wheel's IFxx
    about its vertical diameter and its mass at the lever w - xH, plus the modal mass)."""
    p = BENCHMARK
    b = {name: getattr(p, name) for name in ("w", "rF", "xH", "zH", "mH", "IHxx", "IHyy", "IHzz", "IHxz", "mF",
                                             "IFxx", "IFyy")}
    fork = Compliance("fork", (p.w, -p.rF), (1.0, 0.0), 5e3, 0.0, (0.0, 0.0), 0.0)
    frame = Compliance("frame", (p.xH, 0.0), (0.0, 1.0), 5e3, 0.1, (0.0, 0.0), 0.03)
    J = Compliances(frame, fork).clamped_inertias(b)
    assert J["fork"] == pytest.approx(p.IFxx, rel=1e-14)
    assert J["frame"] == pytest.approx(p.IHzz + p.IFxx + p.mF * (p.w - p.xH) ** 2 + 0.03, rel=1e-14)


def test_damping_ratio_and_steering_damper_enter_as_viscous_coefficients(jamis):
    """c = 2 zeta sqrt(k J) with J the clamped inertia (the damping ratio of the compliance's own vibration
    at sqrt(k / J), as a bench test of the part measures it); the steering damper as given; the default
    steering damper is Moore's (2012) 0.34 N m s/rad, the default structural damping none; held rigid,
    nothing is damped (the rigid bicycle)."""
    _, params, flexible = jamis
    assert flexible.steer_damping == STEER_DAMPING == 0.34
    assert flexible.frame.damping_ratio == flexible.fork.damping_ratio == DAMPING_RATIO == 0.0
    damped = replace(flexible, frame=replace(flexible.frame, damping_ratio=0.03),
                     fork=replace(flexible.fork, damping_ratio=0.05), steer_damping=0.7)
    p = values("flexible", params, compliances=damped)
    J = damped.clamped_inertias(p)
    assert p["cr"] == pytest.approx(2 * 0.03 * np.sqrt(flexible.frame.stiffness * J["frame"]), rel=1e-14)
    assert p["cf"] == pytest.approx(2 * 0.05 * np.sqrt(flexible.fork.stiffness * J["fork"]), rel=1e-14)
    assert p["cs"] == 0.7
    # the clamped frame twist and fork bending of the steel Jamis vibrate at 15.4 and 34.5 Hz
    assert np.sqrt(flexible.frame.stiffness / J["frame"]) / (2 * np.pi) == pytest.approx(15.4, abs=0.1)
    assert np.sqrt(flexible.fork.stiffness / J["fork"]) / (2 * np.pi) == pytest.approx(34.5, abs=0.1)
    rigid = values("flexible", params, compliances=damped.rigid())
    assert rigid["cs"] == rigid["cr"] == rigid["cf"] == 0.0
    with pytest.raises(InputError, match="damping_ratio"):
        replace(flexible.frame, damping_ratio=1.5)
    with pytest.raises(InputError, match="steer_damping"):
        Compliances(steer_damping=-1.0)


def test_a_steering_damper_alone_is_the_whipple_bicycle_with_a_steer_rate_term(jamis):
    """Both compliances held rigid but a steering damper c: the Whipple bicycle whose steer equation has
    c times the steer rate added (Meijaard et al.'s M, C, K with C[1, 1] += c), eigenvalues to 1e-9."""
    _, params, _ = jamis
    model = build("flexible", params, compliances=Compliances(steer_damping=0.5))
    m = canonical_matrices(params)
    for v in (0.5, 3.0, 7.0):
        C = v * m.C1 + np.diag([0.0, 0.5])
        K = m.stiffness(v)
        A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(m.M, K), -np.linalg.solve(m.M, C)]])
        expected = np.sort_complex(np.linalg.eigvals(A))
        ours = np.sort_complex(np.linalg.eigvals(model.dynamic_matrix(v)))
        np.testing.assert_allclose(ours, expected, rtol=1e-9, atol=1e-9)


def _wobble_track(model, top=30.0, step=0.05):
    """The wobble of ``model``: at 8 m/s the least damped steer-dominated oscillation of 4-12 Hz (steer the
    largest coordinate of its shape), followed by nearest root in steps of ``step`` down to 0.1 m/s and up
    to ``top``; ``{speed: eigenvalue}``."""
    values_, vectors = np.linalg.eig(model.dynamic_matrix(8.0))
    coordinates = sum(1 for n in model.state_names if not n.endswith(("rate", "velocity", "force")) and n not in (
        "heading", "lateral"))
    steer = [k for k in range(len(values_)) if values_[k].imag > 0 and 4 <= values_[k].imag / (2 * np.pi) <= 12
             and np.argmax(np.abs(vectors[:coordinates, k])) == 1]
    start = max((values_[k] for k in steer), key=lambda z: z.real)
    track = {8.0: start}
    for grid in (np.arange(8.0, top + 1e-9, step), np.arange(8.0, 0.1 - 1e-9, -step)):
        root = start
        for v in grid[1:]:
            roots = np.linalg.eigvals(model.dynamic_matrix(v))
            root = roots[np.argmin(np.abs(roots - root))]
            track[round(float(v), 6)] = root
    return dict(sorted(track.items()))


def _onset(track):
    """The lowest speed (m/s) at which the tracked root's real part turns positive (linear between grid
    speeds), or None."""
    speeds = list(track)
    for a, b in zip(speeds, speeds[1:]):
        ra, rb = track[a].real, track[b].real
        if ra <= 0 < rb:
            return a + (b - a) * (-ra) / (rb - ra)
    return None


@pytest.fixture(scope="module")
def wobble_tracks():
    """Jamis + Relaxed, tyre+flexible with the default tyres and damping, steel and titanium."""
    bike = bm.load_bicycle("jamis")
    params = bm.parameters(bike, bm.load_rider("relaxed"))
    return {material: _wobble_track(build("tyre+flexible", params, compliances=compliances(bike, material)))
            for material in ("steel", "titanium")}


@pytest.fixture(scope="module")
def trail_tracks():
    """Jamis + Relaxed, tyre+flexible with the default damping and the measured pneumatic trail (TRAIL_TYRES),
    steel and titanium."""
    bike = bm.load_bicycle("jamis")
    params = bm.parameters(bike, bm.load_rider("relaxed"))
    return {material: _wobble_track(build("tyre+flexible", params, tyres=TRAIL_TYRES, compliances=compliances(bike, material)))
            for material in ("steel", "titanium")}


def test_wobble_with_the_measured_pneumatic_trail(trail_tracks):
    """With the measured 16.6 mm trail (Dell'Orto et al. 2024; no twisting torque) the stiffer frame and fork
    (steel beside titanium) still raises the wobble's frequency at 8 m/s and does not lower its onset; the
    published pattern (damped at 1 m/s, onset at 2 m/s or above) is not reached: the steel wobble grows at 1 m/s
    and crosses below 1 m/s (docs/models.md says so with the numbers)."""
    steel, titanium = trail_tracks["steel"], trail_tracks["titanium"]
    f = {m: t[8.0].imag / (2 * np.pi) for m, t in trail_tracks.items()}
    assert 4.0 <= f["titanium"] < f["steel"] <= 12.0
    assert _onset(steel) >= _onset(titanium)
    assert steel[0.1].real < 0 < steel[1.0].real and _onset(steel) < 1.0


def test_contract_docs_models_md_prints_the_trail_wobble(trail_tracks, wobble_tracks):
    """Contract test: docs/models.md's table of the Jamis's wobble with the measured trail, to its printed digits."""
    rows = {"steel, force-only tyres": wobble_tracks["steel"], "steel, 16.6 mm trail": trail_tracks["steel"],
            "titanium, 16.6 mm trail": trail_tracks["titanium"]}
    text = (__import__("pathlib").Path(__file__).parents[1] / "docs" / "models.md").read_text()
    for label, track in rows.items():
        line = next(x for x in text.splitlines() if x.startswith(f"| {label} |"))
        cells = [c.strip() for c in line.strip("|").split("|")]
        assert cells[1] == f"{track[8.0].imag / (2 * np.pi):.2f} Hz, {track[8.0].real:+.2f} /s"
        assert cells[2] == f"{track[1.0].real:+.3f} /s" and cells[3] == f"{track[0.1].real:+.2f} /s"
        assert cells[4].startswith(f"{_onset(track):.2f} m/s")


def test_wobble_of_the_tyre_and_flexible_jamis_with_the_default_damping(wobble_tracks):
    """The wobble (steer-dominated, in the published 4-12 Hz band at 8 m/s; 6.48 Hz for the steel Jamis) stays
    below 15 Hz from 0.1 to 30 m/s (no mode above 15 Hz is this mode); the steering bearing's damping
    damps it at standstill (real part below -0.5 /s at 0.1 m/s, where the undamped member left 1e-14);
    the stiffer frame and fork (steel, beside titanium's 56 % modulus) raises its frequency (6.48 against
    5.26 Hz at 8 m/s) and does not lower its onset speed."""
    steel, titanium = wobble_tracks["steel"], wobble_tracks["titanium"]
    hz = {m: {v: z.imag / (2 * np.pi) for v, z in t.items()} for m, t in wobble_tracks.items()}
    assert 4.0 <= hz["steel"][8.0] <= 12.0 and 4.0 <= hz["titanium"][8.0] <= 12.0       # the published wobble band
    assert all(4.0 <= f < 15.0 for m in hz for f in hz[m].values())
    assert steel[0.1].real < -0.5 and titanium[0.1].real < -0.5
    assert hz["steel"][8.0] > hz["titanium"][8.0]
    assert _onset(steel) >= _onset(titanium)

