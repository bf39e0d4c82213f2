"""Stability core against Meijaard et al. (2007), BicycleParameters and LAPACK."""

from itertools import permutations

import numpy as np
import pytest
from scipy.optimize import linear_sum_assignment

from bikemass.analysis.engine.eigen import eigen_sweep
from bikemass.analysis.engine.modes import follow_modes
from bikemass.analysis.engine.quartic import quartic_roots
from bikemass.analysis.engine.ranges import intersect
from bikemass.analysis.engine.stability import analyse
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.analysis.engine.tracking import partners, step_costs, track
from bikemass.scenario.scenario import parameters
from bikemass.models.canonical import canonical_matrices
from bikemass.models.flexible_static import static_stiffness, with_frame_stiffness
from bikemass.models.linear import Signal, second_order_model
from bikemass.models.whipple import whipple_model
from thesis_sets import RIDERS, stiffness, thesis_set

BENCHMARK = parameters("benchmark")  # frames/benchmark.yaml (Meijaard 2007, Table 1)

# Meijaard et al. 2007, Sec. 4 / Appendix A (printed in the thesis as Table 3-13, K0 without g).
TABLE_3_13 = {
    "M": [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]],
    "C1": [[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]],
    "K0": [[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]],
    "K2": [[0.0, 76.59734589573222], [0.0, 2.65431523794604]],
}

# Meijaard et al. 2007, Table 2 (thesis Table 4-1): v, weave (re, im), capsize, castor.
# At v = 0 the two weave roots are real: 3.13164324790656 and 5.53094371765393.
TABLE_4_1 = [
    (1, 3.52696170990070, 0.80774027519930, -3.13423125066578, -7.11008014637442),
    (2, 2.68234517512745, 1.68066296590675, -3.07158645641514, -8.67387984831735),
    (3, 1.70675605663975, 2.31582447384325, -2.63366137253667, -10.35101467245920),
    (4, 0.41325331521125, 3.07910818603206, -1.42944427361326, -12.15861426576447),
    (5, -0.77534188219585, 4.46486771378823, -0.32286642900409, -14.07838969279822),
    (6, -1.52644486584142, 5.87673060598709, -0.00406690076970, -16.08537123098026),
    (7, -2.13875644258362, 7.19525913329805, 0.10268170574766, -18.15788466125262),
    (8, -2.69348683581097, 8.46037971396931, 0.14327879765713, -20.27940894394569),
    (9, -3.21675402252485, 9.69377351531791, 0.15790184030917, -22.43788559040858),
    (10, -3.72016840437287, 10.90681139476287, 0.16105338653172, -24.62459635017404),
]


def model(p, S=None):
    return whipple_model(p, S)


def from_matrices(m):
    """A Whipple-form model of canonical matrices (no kinematics): for matrices no parameter set has."""
    q = [Signal("roll-angle", "rad"), Signal("steer-angle", "rad")]
    r = [Signal("roll-rate", "rad/s"), Signal("steer-rate", "rad/s")]
    return second_order_model("matrices", q, r, m.M, [None, m.C1], [m.gK0, None, m.K2], np.eye(2),
                              [Signal("roll-torque", "N m"), Signal("steer-torque", "N m")])


def test_canonical_matrices_match_table_3_13_to_1e_13():
    m = canonical_matrices(BENCHMARK)
    for name, ref in TABLE_3_13.items():
        got, ref = getattr(m, name), np.array(ref)
        assert np.all(got[ref == 0] == 0), name
        np.testing.assert_allclose(got[ref != 0], ref[ref != 0], rtol=1e-13, atol=0, err_msg=name)
    assert m.g == 9.81


def test_eigenvalues_match_table_4_1_to_1e_12():
    modes = follow_modes(model(BENCHMARK), np.arange(11.0))
    at0 = {label: modes[label][0] for label in modes.labels}
    assert at0["weave 1"] == pytest.approx(3.13164324790656, abs=1e-12)
    assert at0["weave 2"] == pytest.approx(5.53094371765393, abs=1e-12)
    assert at0["capsize"] == pytest.approx(-3.13164324790656, abs=1e-12)
    assert at0["caster"] == pytest.approx(-5.53094371765393, abs=1e-12)
    for v, re, im, capsize, castor in TABLE_4_1:
        pair = sorted([modes["weave 1"][v], modes["weave 2"][v]], key=lambda z: z.imag)
        assert abs(pair[0] - complex(re, -im)) < 1e-12 and abs(pair[1] - complex(re, im)) < 1e-12
        assert abs(modes["capsize"][v] - capsize) < 1e-12
        assert abs(modes["caster"][v] - castor) < 1e-12


def test_weave_and_capsize_speeds_are_roots_to_1e_9():
    st = analyse(model(BENCHMARK))
    assert len(st.weave_speeds) == 1 and len(st.capsize_speeds) == 1
    assert abs(st.weave_speeds[0] - 4.29238253634110) < 1e-9   # Meijaard 2007: exact (prints ...111)
    assert abs(st.capsize_speeds[0] - 6.02426201538836) < 1e-9
    assert st.ranges["strict"]["exact"] == ((st.weave_speeds[0], st.capsize_speeds[0]),)
    assert st.ranges["strict"]["grid"] == ((4.3, 6.0),)          # thesis Table 4-2, Benchmark
    assert st.ranges["marginal"]["grid"] == ((4.3, 30.0),)       # thesis Table 4-3


def sets():
    yield "Benchmark", thesis_set("Benchmark", "Benchmark"), None
    for bike in ("Jamis", "Cargo", "Cargo load"):
        for rider in ("No Rider",) + RIDERS:
            yield f"{bike} {rider}", thesis_set(bike, rider), None
    yield "Cargo load Relaxed titanium", thesis_set("Cargo load", "Relaxed"), stiffness("Cargo", "Titanium")


def test_bicycleparameters_gives_same_matrices_and_eigenvalues_to_1e_10():
    models = pytest.importorskip("bicycleparameters.models")
    psets = pytest.importorskip("bicycleparameters.parameter_sets")
    speeds = np.linspace(0, 20, 41)
    for name, p, S in sets():
        if S is not None:       # BicycleParameters has no flexible frame
            continue
        peer = models.Meijaard2007Model(psets.Meijaard2007ParameterSet({**p.to_dict(), "v": 0.0}, True))
        ours = canonical_matrices(p)
        for got, ref in zip((ours.M, ours.C1, ours.K0, ours.K2), peer.form_reduced_canonical_matrices()):
            np.testing.assert_allclose(got, ref, rtol=1e-10, atol=1e-10, err_msg=name)
        ref_values, _ = peer.calc_eigen(v=speeds)
        got_values = eigen_sweep(model(p), speeds).eigenvalues
        for g, r in zip(got_values, ref_values):
            rows, cols = linear_sum_assignment(np.abs(g[:, None] - r[None, :]))
            assert np.max(np.abs(g[rows] - r[cols])) < 1e-10, name


def test_batched_eigen_solve_agrees_with_lapack_and_eigenvectors_solve_the_state_equation():
    v = speed_grid()
    for name, p, S in sets():
        m = model(p, S)
        sweep = eigen_sweep(m, v)
        A = m.dynamic_matrix(v)
        ref = np.linalg.eigvals(A)
        for k in range(len(v)):   # no double roots fall on these grids: 1e-11 holds (found 2.3e-13)
            rows, cols = linear_sum_assignment(np.abs(sweep.eigenvalues[k][:, None] - ref[k][None, :]))
            assert np.max(np.abs(sweep.eigenvalues[k][rows] - ref[k][cols])) < 1e-11, (name, v[k])
        residual = A @ sweep.eigenvectors - sweep.eigenvectors * sweep.eigenvalues[:, None, :]
        assert np.max(np.abs(residual)) < 1e-10, name
        np.testing.assert_allclose(np.linalg.norm(sweep.eigenvectors, axis=1), 1.0, rtol=1e-12)


def test_quartic_roots_against_numpy_roots_and_multiple_roots():
    rng = np.random.default_rng(1)
    coeffs = rng.normal(size=(500, 5))
    for c, r in zip(coeffs, quartic_roots(coeffs)):
        ref = np.roots(c)
        rows, cols = linear_sum_assignment(np.abs(r[:, None] - ref[None, :]))
        assert np.max(np.abs(r[rows] - ref[cols])) < 1e-9 * (1 + np.abs(ref).max())
    special = {(1, 0, -5, 0, 4): [-2, -1, 1, 2], (1, 0, 0, 0, 0): [0, 0, 0, 0],
               (1, -4, 6, -4, 1): [1, 1, 1, 1], (2, 0, 2, 0, 0): [0, 0, -1j, 1j]}
    for c, ref in special.items():
        got, ref = quartic_roots([c])[0], np.array(ref)
        rows, cols = linear_sum_assignment(np.abs(got[:, None] - ref[None, :]))
        assert np.max(np.abs(got[rows] - ref[cols])) < 1e-12, c


def test_natural_frequency_and_damping_ratio():
    modes = follow_modes(model(BENCHMARK), [5.0])
    lam = modes.eigenvalues[0]
    np.testing.assert_allclose(modes.natural_frequency[0], np.abs(lam))
    np.testing.assert_allclose(modes.damping_ratio[0], -lam.real / np.abs(lam))
    weave = lam[np.abs(lam.imag) > 0][0]
    assert abs(weave) == pytest.approx(np.hypot(-0.77534188219585, 4.46486771378823), abs=1e-12)


def test_tracking_is_the_optimal_assignment_that_keeps_conjugate_pairs():
    """Each step of the tracking is the cheapest of the 24 permutations of four roots among those
    that break no conjugate pair (checked by brute force, without the tracking's own penalty)."""
    m = model(thesis_set("Cargo load", "No Rider"))
    sweep = eigen_sweep(m, speed_grid())
    values, vectors = sweep.eigenvalues, sweep.eigenvectors
    plain = step_costs(values, vectors) - 10.0 * ((np.sign(values.imag)[:-1, :, None]
                                                   * np.sign(values.imag)[1:, None, :]) < 0)
    order = track(values, vectors)
    part = partners(values)
    every = np.array(list(permutations(range(4))))
    for k in range(len(values) - 1):
        step = np.empty(4, dtype=int)
        step[order[k]] = order[k + 1]                      # root i at speed k -> step[i] at k + 1

        def keeps_pairs(q):
            return all(part[k + 1, q[i]] == q[part[k, i]] for i in range(4)
                       if part[k, i] != i and part[k + 1, q[i]] != q[i])
        best = min(plain[k][np.arange(4), q].sum() for q in every if keeps_pairs(q))
        assert keeps_pairs(step) and plain[k][np.arange(4), step].sum() == pytest.approx(best, abs=1e-12)


def test_a_conjugate_pair_passing_a_real_root_stays_a_pair():
    # Jamis + No Hands on the steel frame: near 6.7 m/s the weave pair passes within 0.44 1/s
    # of the capsize root; on the 0.05 grid the nearest-value assignment would swap a member
    modes = follow_modes(model(thesis_set("Jamis", "No Hands"), stiffness("Jamis", "Steel")),
                         speed_grid(6.5, 7.0, 0.05))
    np.testing.assert_allclose(modes["weave 1"], modes["weave 2"].conj(), atol=1e-12)
    assert np.all(modes["capsize"].imag == 0)


def all_thesis_sets():
    yield "Benchmark", thesis_set("Benchmark", "Benchmark"), None
    for bike in ("Jamis", "Cargo", "Cargo load"):
        for rider in ("No Rider",) + RIDERS:
            for material in ("Infinite", "Steel", "Titanium", "Aluminum"):
                S = stiffness("Jamis" if bike == "Jamis" else "Cargo", material)
                yield f"{bike} {rider} {material}", thesis_set(bike, rider), S


def test_tracking_on_the_thesis_grid_agrees_with_a_five_times_finer_grid():
    """All 73 thesis sets: each label carries the same root (up to the conjugate, i.e. up to
    which member of a pair it is) on the 0.05 grid as on a 0.01 grid, where roots move five
    times less per step (a wrong assignment on either grid shows up as a difference)."""
    coarse_v, fine_v = speed_grid(), speed_grid(0, 30, 0.01)
    for name, p, S in all_thesis_sets():
        m = model(p, S)
        coarse, fine = follow_modes(m, coarse_v), follow_modes(m, fine_v)
        for label in coarse.labels:
            a, b = coarse[label], fine[label][::5]
            assert np.max(np.minimum(np.abs(a - b), np.abs(a - b.conj()))) < 1e-9, (name, label)


def test_labels_follow_the_physics_not_the_solver_order():
    # riderless Jamis: caster and capsize merge at 0.4 m/s and split at 2.15 m/s; after the
    # split capsize is the slow root that goes (marginally) unstable, caster stays stable
    modes = follow_modes(model(thesis_set("Jamis", "No Rider")), speed_grid())
    v = modes.speeds
    split = (v > 2.2)
    assert np.all(modes["capsize"][split].real > modes["caster"][split].real)
    merged = (v > 0.45) & (v < 2.1)
    np.testing.assert_allclose(modes["capsize"][merged], modes["caster"][merged].conj(), atol=1e-12)
    assert np.all(modes["capsize"][merged].imag != 0)
    assert modes["capsize"][-1].real > 0 and modes["caster"][-1].real < -10
    # riderless Cargo: weave 1 and capsize form one oscillation at all speeds (thesis Sec. 4.4)
    modes = follow_modes(model(thesis_set("Cargo", "No Rider")), speed_grid())
    np.testing.assert_allclose(modes["weave 1"], modes["capsize"].conj(), atol=1e-12)
    assert np.all(modes["weave 1"].imag > 0)
    assert np.all(modes["weave 2"].imag == 0) and np.all(modes["caster"].real < 0)
    # the same labels whether or not the sweep starts at standstill
    later = follow_modes(model(BENCHMARK), np.linspace(3, 8, 11))
    whole = follow_modes(model(BENCHMARK), np.linspace(0, 8, 33))
    for label in later.labels:
        np.testing.assert_allclose(later[label], whole[label][12::2], atol=1e-12)


def test_zero_eigenvalues_at_standstill_do_not_break_tracking():
    m = canonical_matrices(BENCHMARK)
    # make g K0 singular: one static mode neutral, two roots exactly 0 at v = 0
    w, V = np.linalg.eigh(m.K0)
    singular = from_matrices(m.replace(K0=V @ np.diag([0.0, w[1]]) @ V.T))
    modes = follow_modes(singular, speed_grid(0, 10, 0.05))
    assert np.all(np.isfinite(modes.eigenvalues))
    assert sorted(np.abs(modes.eigenvalues[0])) [:2] == [0.0, 0.0]
    assert np.all(np.isfinite(modes.eigenvectors))
    st = analyse(singular, speed_grid(0, 10, 0.05))
    assert all(np.isfinite(c.speed) for c in st.crossings)


def test_several_crossings_are_all_reported():
    # loaded Cargo, no rider: weave becomes stable near 7.75 m/s; the pair splits and one of
    # its real roots (tracked as weave 1) turns unstable near 22.1 m/s: a capsize-like crossing
    st = analyse(model(thesis_set("Cargo load", "No Rider")))
    dirs = {label: [c.direction for c in st.mode_crossings(label)] for label in st.modes.labels}
    assert dirs["weave 1"] == ["stabilising", "destabilising"]
    assert dirs["weave 2"] == ["stabilising"]
    w, c = st.weave_speeds, st.capsize_speeds
    assert len(w) == 1 and 7.70 < w[0] < 7.75 and len(c) == 1 and 22.05 < c[0] < 22.15
    assert st.ranges["strict"]["exact"] == ((w[0], c[0]),)


def test_exact_ranges_lie_between_the_grid_points():
    for name, p, S in sets():
        st = analyse(model(p, S))
        for ranges in [st.ranges[c] for c in ("strict", "marginal")] + \
                [st.mode_ranges[m][c] for m in st.mode_ranges for c in ("strict", "marginal")]:
            assert len(ranges["exact"]) == len(ranges["grid"]), name
            for (a, b), (ga, gb) in zip(ranges["exact"], ranges["grid"]):
                assert ga - 0.05 - 1e-9 <= a <= ga and gb <= b <= gb + 0.05 + 1e-9, name


def test_frame_flexibility():
    m = canonical_matrices(thesis_set("Jamis", "Relaxed"))
    S = stiffness("Jamis", "Steel")
    K = static_stiffness(m.gK0, S)
    # Eq. 3.30 is two springs in series: gK0 (gK0 + S)^-1 S
    np.testing.assert_allclose(K, m.gK0 @ np.linalg.solve(m.gK0 + S, S), rtol=1e-12)
    np.testing.assert_allclose(K, K.T, rtol=1e-12)
    assert static_stiffness(m.gK0, None) is not None and with_frame_stiffness(m, None) is m
    stiff = with_frame_stiffness(m, 1e12 * np.eye(2))
    np.testing.assert_allclose(stiff.K0, m.K0, rtol=1e-6)
    flexible = with_frame_stiffness(m, S)
    for name in ("M", "C1", "K2"):
        np.testing.assert_array_equal(getattr(flexible, name), getattr(m, name))
    assert flexible.g * flexible.K0 == pytest.approx(K)


def test_result_objects_serialise():
    st = analyse(model(BENCHMARK), speed_grid(0, 10, 0.5))
    d = st.to_dict()
    assert set(d) >= {"weave_speeds", "capsize_speeds", "ranges", "modes"}
    assert set(d["ranges"]) == {"strict", "marginal"} and set(d["ranges"]["strict"]) == {"exact", "grid"}
    assert set(d["modes"]) == {"weave", "weave 1", "weave 2", "capsize", "caster"}
    m = st.modes.to_dict()
    assert len(m["speeds"]) == 21 and [x["label"] for x in m["modes"]] == list(st.modes.labels)
    assert len(m["modes"][0]["eigenvalues"][0]) == 2
    assert canonical_matrices(BENCHMARK).to_dict()["K0"][0][0] == pytest.approx(-80.95)


def test_speeds_must_increase():
    m = model(BENCHMARK)
    for bad in ([1.0, 0.5], [-1.0, 2.0], [0.0, np.nan]):
        with pytest.raises(ValueError):
            follow_modes(m, bad)


def test_intersect():
    assert intersect([[0, 2], [3, 5]], [[1, 4]]) == [[1, 2], [3, 4]]
    assert intersect([[0, 1]], [[2, 3]]) == []
    assert intersect([[0, 30]], [[4.3, 30]]) == [[4.3, 30]]
    assert intersect([], [[0, 1]]) == []


def test_weave_ranges_in_json_are_where_both_weave_roots_are_stable():
    """Issue 4's JSON: ``modes.weave`` = intersection of the two weave roots' ranges."""
    st = analyse(model(BENCHMARK))
    doc = st.to_dict()
    assert set(doc["modes"]) == {"weave", "weave 1", "weave 2", "capsize", "caster"}
    strict = doc["modes"]["weave"]["strict"]
    assert strict["exact"][0][0] == pytest.approx(4.29238253634110, abs=1e-9)
    assert strict["grid"] == [[4.3, 30.0]]


def test_tracking_of_a_richer_model_is_scipys_optimal_assignment():
    """Issue 37: the tracking builds the full cost matrices only where a step may move a root to another
    column; every step of a six-root model (the Jamis + Relaxed with the leaning rider, on the thesis
    grid) is still scipy's optimal assignment of the full costs (to 1e-12 in total cost)."""
    from bikemass.scenario.scenario import Scenario
    m = Scenario("jamis", "relaxed", model="rider-lean").build().model
    sweep = eigen_sweep(m, speed_grid())
    values, vectors = sweep.eigenvalues, sweep.eigenvectors
    costs = step_costs(values, vectors)
    order = track(values, vectors)
    rows = np.arange(values.shape[1])
    for k in range(len(values) - 1):
        step = np.empty(len(rows), dtype=int)
        step[order[k]] = order[k + 1]                      # root i at speed k -> step[i] at k + 1
        best = costs[k][rows, linear_sum_assignment(costs[k])[1]].sum()
        assert costs[k][rows, step].sum() == pytest.approx(best, abs=1e-12)


def test_marginal_and_mode_ranges_are_made_when_first_read():
    """Issue 37: the marginal ranges and each mode's ranges are computed on first reading (a LazyMap),
    read-only, and a pickled result holds them as plain read-only maps; the marginal grid range of the
    benchmark is checked against the grid eigenvalues themselves (every root stable or slower than 2
    rad/s)."""
    import pickle
    from bikemass.core.frozen import FrozenMap, LazyMap
    result = analyse(whipple_model(BENCHMARK), speed_grid(), 2.0)
    lazy = result.ranges["marginal"]
    assert isinstance(lazy, LazyMap) and lazy._data is None and result.mode_ranges._data is None
    E = result.eigenvalues
    mask = np.all((E.real < -1e-10) | (np.abs(E) < 2.0), axis=1)
    v = result.speeds
    first = np.flatnonzero(mask)
    assert lazy["grid"][0] == (v[first[0]], v[first[-1]]) and np.all(mask[first[0]:first[-1] + 1])
    with pytest.raises(AttributeError):
        lazy.x = 1
    copy = pickle.loads(pickle.dumps(result))
    assert type(copy.mode_ranges) is FrozenMap and dict(copy.mode_ranges["capsize"]) == dict(result.mode_ranges["capsize"])
    assert copy.ranges["marginal"] == lazy
