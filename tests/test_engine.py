"""The stability engine against independent references: Meijaard et al. (2007) by high-precision
arithmetic, synthetic models of 2 to 8 coordinates by a counting reference, and the closed form.

* Meijaard's printed matrices (Sec. 4 / Appendix A, 15 digits) give the weave and capsize speeds
  with mpmath at 40 digits from the characteristic polynomial alone (no bikemass code): the engine
  agrees to 1e-12 m/s, and both agree with the paper's printed speeds to its last digit.
* The counting reference knows nothing of compounds or polynomial eigenvalue problems: the number
  of eigenvalues with Re > 0, on a grid of 20,001 speeds, changes across every crossing; each
  change is bisected on that count to 1e-12 m/s, and its size (1 or 2) tells a real root from a
  pair.  Models with windows narrower than the engine's own speed grid are included.
"""

import mpmath as mp
import numpy as np
import pytest

from bikemass.analysis.engine import closed_form, crossings
from bikemass.analysis.engine.compound import additive_compound, multiplicative_compound
from bikemass.analysis.engine.stability import analyse
from bikemass.models.linear import Signal, second_order_model
from bikemass.models.whipple import whipple_model
from bikemass.scenario.scenario import parameters

BENCHMARK = parameters("benchmark")
MEIJAARD = {   # Meijaard et al. 2007, Sec. 4 (K0 without g)
    "M": [["80.81722", "2.31941332208709"], ["2.31941332208709", "0.29784188199686"]],
    "C1": [["0", "33.86641391492494"], ["-0.85035641456978", "1.68540397397560"]],
    "K0": [["-80.95", "-2.59951685249872"], ["-2.59951685249872", "-0.80329488458618"]],
    "K2": [["0", "76.59734589573222"], ["0", "2.65431523794604"]],
}
PRINTED = {"weave": 4.29238253634111, "capsize": 6.02426201538837}   # their Sec. 4, 15 digits
EXACT = {"weave": 4.2923825363411039587, "capsize": 6.0242620153883588899}
"""From the exact parameters (lam = pi/10) through Meijaard's Appendix A and the characteristic
polynomial, by mpmath at 50 digits (the printed 15-digit values are these rounded, +-1 in the last)."""


def meijaard_speeds():
    """Weave and capsize speeds from Meijaard's printed matrices, by mpmath (40 digits)."""
    mp.mp.dps = 40
    M, C1, K0, K2 = (mp.matrix(MEIJAARD[k]) for k in ("M", "C1", "K0", "K2"))
    g = mp.mpf("9.81")

    def poly(v):   # coefficients of det(M s^2 + v C1 s + g K0 + v^2 K2), highest first
        A, B, C = M, v * C1, g * K0 + v ** 2 * K2
        det = lambda X, Y: X[0, 0] * Y[1, 1] + Y[0, 0] * X[1, 1] - X[0, 1] * Y[1, 0] - Y[0, 1] * X[1, 0]   # noqa: E731
        return [det(A, A) / 2, det(A, B), det(A, C) + det(B, B) / 2, det(B, C), det(C, C) / 2]

    def top_real(v):       # the largest real part of the roots of the characteristic quartic
        return max(r.real for r in mp.polyroots(poly(v), maxsteps=200, extraprec=80))

    capsize = mp.findroot(lambda v: poly(v)[-1], 6.0)
    weave = mp.findroot(lambda v: top_real(v), (4.2, 4.4), solver="anderson")
    return float(weave), float(capsize)


def test_benchmark_matches_meijaard_to_the_last_digit():
    weave, capsize = meijaard_speeds()
    assert weave == pytest.approx(PRINTED["weave"], abs=1e-13)     # the matrices are printed to 1e-14
    assert capsize == pytest.approx(PRINTED["capsize"], abs=1e-13)
    assert EXACT["weave"] == pytest.approx(weave, abs=1e-13) and EXACT["capsize"] == pytest.approx(capsize, abs=1e-13)
    st = analyse(whipple_model(BENCHMARK))
    assert [c.kind for c in st.crossings] == ["oscillatory", "real"]
    assert st.crossings[0].speed == pytest.approx(EXACT["weave"], abs=1e-13)
    assert st.crossings[1].speed == pytest.approx(EXACT["capsize"], abs=1e-13)
    assert [c.mode for c in st.crossings] == ["weave", "capsize"]
    assert [c.direction for c in st.crossings] == ["stabilising", "destabilising"]
    assert st.ranges["strict"]["exact"] == ((pytest.approx(EXACT["weave"], abs=1e-13),
                                             pytest.approx(EXACT["capsize"], abs=1e-13)),)
    for speed, kind, _ in crossings.axis_crossings(whipple_model(BENCHMARK), 0.0, 30.0):    # the general path
        assert speed == pytest.approx(EXACT["weave" if kind == "oscillatory" else "capsize"], abs=1e-13)


def test_compounds_have_the_eigenvalue_sums_and_products():
    rng = np.random.default_rng(7)
    for n in (2, 3, 5, 7):
        A = rng.normal(size=(n, n))
        lam = np.linalg.eigvals(A)
        pairs = [(i, j) for i in range(n) for j in range(i + 1, n)]
        for compound, op in ((additive_compound, np.add), (multiplicative_compound, np.multiply)):
            got = np.linalg.eigvals(compound(A))
            for i, j in pairs:
                assert np.min(np.abs(got - op(lam[i], lam[j]))) < 1e-10 * (1 + abs(op(lam[i], lam[j])))


def count_reference(model, lo, hi, points=20001):
    """``[(speed, kind)]``: every change of the number of unstable roots on a fine grid, bisected."""
    A = model.dynamic_coefficients

    def unstable(v):
        v = np.atleast_1d(v)
        roots = np.linalg.eigvals(np.tensordot(v[:, None] ** np.arange(len(A)), A, axes=1))
        return np.sum(roots.real > 0, axis=1)
    v = np.linspace(lo, hi, points)
    counts = unstable(v)
    out = []
    for k in range(points - 1):
        if counts[k] != counts[k + 1]:
            a, b = v[k], v[k + 1]
            ca = counts[k]
            while b - a > 1e-12:
                m = 0.5 * (a + b)
                a, b = (m, b) if unstable(m)[0] == ca else (a, m)
            out.append((0.5 * (a + b), "real" if abs(counts[k + 1] - ca) == 1 else "oscillatory"))
    return out


def assert_same_crossings(model, lo, hi):
    ref = count_reference(model, lo, hi)
    found = [c for c in crossings.axis_crossings(model, lo, hi)]
    assert len(found) == len(ref), (found, ref)
    for (speed, kind, _), (rspeed, rkind) in zip(found, ref):
        assert kind == rkind and speed == pytest.approx(rspeed, abs=1e-9), (found, ref)


def random_model(rng, n):
    """A second-order model with ``n`` coordinates: M s.p.d., C(v) = C0 + v C1, K(v) = K0 + v^2 K2."""
    Q = rng.normal(size=(n, n))
    M = Q @ Q.T + n * np.eye(n)
    C0 = 0.05 * np.eye(n)
    C1 = rng.normal(size=(n, n))
    K0 = rng.normal(size=(n, n)) * 4
    K0 = (K0 + K0.T) / 2
    K2 = rng.normal(size=(n, n))
    coords = [Signal(f"q{i}", "rad") for i in range(n)]
    rates = [Signal(f"q{i}-rate", "rad/s") for i in range(n)]
    return second_order_model(f"random{n}", coords, rates, M, [C0, C1], [K0, None, K2], np.eye(n)[:, :1],
                              [Signal("u", "N m")])


@pytest.mark.parametrize("seed", range(12))
def test_random_models_of_many_coordinates_against_the_counting_reference(seed):
    rng = np.random.default_rng(seed)
    model = random_model(rng, 2 + seed % 4)
    assert_same_crossings(model, 0.0, 8.0)


@pytest.mark.parametrize("change, window", [
    ({"c": 0.0, "lam": 0.2125}, (2.103183, 2.105099)),    # the window the old engine missed
    ({"c": 0.0025, "lam": 0.2}, (2.128609, 2.139240)),    # narrower than the 0.05 m/s grid step
])
def test_narrow_windows_are_found(change, window):
    model = whipple_model(BENCHMARK.replace(**change))
    assert_same_crossings(model, 0.0, 10.0)
    st = analyse(model)
    (a, b), = st.ranges["strict"]["exact"]
    assert (a, b) == (pytest.approx(window[0], abs=1e-6), pytest.approx(window[1], abs=1e-6))
    assert st.ranges["strict"]["grid"] == ()      # no grid speed lies inside the window


def test_the_closed_form_agrees_with_the_general_engine():
    rng = np.random.default_rng(3)
    p = BENCHMARK.to_dict()
    for _ in range(40):
        changed = BENCHMARK.replace(**{k: p[k] * (1 + 0.3 * rng.uniform(-1, 1))
                                       for k in ("c", "lam", "xB", "zB", "mH", "IHzz", "IBxz", "xH")})
        model = whipple_model(changed)
        assert closed_form.applies(model)
        fast = closed_form.axis_crossings(model, 0.0, 30.0)
        general = crossings.axis_crossings(model, 0.0, 30.0)
        assert [k for _, k, _ in fast] == [k for _, k, _ in general]
        for (a, _, wa), (b, _, wb) in zip(fast, general):
            assert a == pytest.approx(b, abs=1e-9) and wa == pytest.approx(wb, abs=1e-7)


def test_no_crossing_is_reported_where_no_eigenvalue_is_on_the_axis():
    rng = np.random.default_rng(11)
    for n in (2, 3, 4):
        model = random_model(rng, n)
        for speed, kind, w in crossings.axis_crossings(model, 0.0, 8.0):
            roots = np.linalg.eigvals(model.dynamic_matrix(speed))
            nearest = roots[np.argmin(np.abs(roots - 1j * w))]
            assert abs(nearest.real) < 1e-9 and (abs(nearest.imag) > 1e-6) == (kind == "oscillatory")
