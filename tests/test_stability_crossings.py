"""Crossings of Re = 0 named by the root that crosses, against an independent counting reference.

* The reference (``count_crossings``) knows nothing of the engine: on a grid of 30,001 speeds it
  counts the eigenvalues with Re > 0 (LAPACK on the state matrix), bisects every change of the
  count to 1e-12 m/s, and tells a real root (the count changes by 1) from a pair (by 2).  Every
  crossing of ``bikemass stability`` equals one of it (speed to 1e-9 m/s, same kind), and every
  one of it is reported; the strict stable ranges are the runs where the count is 0.
* ``weave_speeds`` / ``capsize_speeds`` hold only crossings of their kind.
"""

import json

import numpy as np
import pytest

from bikemass.scenario import catalog
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.analysis.engine.modes import follow_modes
from bikemass.analysis.engine.stability import analyse
from bikemass.analysis.engine.speeds import speed_grid
from bikemass.cli.main import main
from bikemass.models.whipple import whipple_model
from thesis_sets import stiffness as thesis_stiffness
from thesis_sets import thesis_set


def count_crossings(model, lo=0.0, hi=30.0, points=30001):
    """``[(speed, kind)]`` and the strict stable ranges, from the number of unstable roots alone."""
    A = model.dynamic_coefficients

    def unstable(v):
        v = np.atleast_1d(np.asarray(v, dtype=float))
        roots = np.linalg.eigvals(np.tensordot(v[:, None] ** np.arange(len(A)), A, axes=1))
        return np.sum(roots.real > 0, axis=1)
    v = np.linspace(lo, hi, points)
    # At standstill the roots come in +-pairs: an imaginary pair's real part is 0 to rounding, and
    # its sign there depends on the LAPACK build.  The range (lo, hi] is open at lo: count just above.
    v[0] = lo + 1e-9
    counts = unstable(v)
    found = []
    for k in np.flatnonzero(counts[1:] != counts[:-1]):
        a, b, ca = v[k], v[k + 1], counts[k]
        while b - a > 1e-12:
            m = 0.5 * (a + b)
            a, b = (m, b) if unstable(m)[0] == ca else (a, m)
        found.append((0.5 * (a + b), "real" if abs(int(counts[k + 1]) - int(ca)) == 1 else "oscillatory"))
    ends = [lo, *[s for s, _ in found], hi]
    stable = [(x, y) for x, y in zip(ends, ends[1:]) if unstable(0.5 * (x + y))[0] == 0]
    return found, stable


def check_crossings(model):
    st = analyse(model)
    ref, stable = count_crossings(model)
    got = [(c.speed, c.kind) for c in st.crossings if c.direction != "touching"]
    assert len(got) == len(ref), (got, ref)
    for (s, k), (rs, rk) in zip(got, ref):
        assert k == rk and s == pytest.approx(rs, abs=1e-9), (got, ref)
    exact = st.ranges["strict"]["exact"]
    assert len(exact) == len(stable) and np.allclose(exact, stable, atol=1e-9), (exact, stable)
    assert set(st.weave_speeds) == {c.speed for c in st.crossings if c.kind == "oscillatory"}
    assert set(st.capsize_speeds) == {c.speed for c in st.crossings if c.kind == "real"}
    for c in st.crossings:
        roots = np.linalg.eigvals(model.dynamic_matrix(c.speed))
        crossing = roots[np.argmin(np.abs(roots - 1j * c.frequency))]
        assert abs(crossing.real) < 1e-9 and (abs(crossing.imag) > 1e-9) == (c.kind == "oscillatory")
    return st, ref


JAMIS_RIDERS = ("no-hands-thesis", "relaxed-thesis", "on-hoods-thesis", "aerobars-thesis", "aero-tuck-thesis")


@pytest.mark.parametrize("material", ("steel", "titanium", "aluminum"))
def test_jamis_frames_with_thesis_riders(material):
    S = catalog.stiffness("jamis", material)
    kinds = set()
    for rider in JAMIS_RIDERS:
        st, found = check_crossings(whipple_model(scenario_parameters("jamis", rider), S))
        kinds |= {k for _, k in found}
    assert "oscillatory" in kinds


@pytest.mark.parametrize("bike, rider", [("benchmark", "none"), ("cargo", "none"), ("cargo", "relaxed-thesis"),
                                         ("cargo-loaded", "none"), ("cargo-loaded", "no-hands")])
def test_benchmark_and_cargo(bike, rider):
    check_crossings(whipple_model(scenario_parameters(bike, rider)))


def _peer_crossings(params):
    """(weave, real-root) speeds of BicycleParameters' Meijaard2007Model of ``params``: the weave where
    the peer's oscillatory eigenvalues cross (brentq to 1e-14 m/s near 11.7), the real root where
    det(g K0 + v^2 K2) = 0 on the peer's canonical matrices (a quadratic in v^2: closed form)."""
    bp_models = pytest.importorskip("bicycleparameters.models")
    bp_sets = pytest.importorskip("bicycleparameters.parameter_sets")
    from scipy.optimize import brentq
    values = params.to_dict()
    peer = bp_models.Meijaard2007Model(bp_sets.Meijaard2007ParameterSet({**values, "v": 1.0}, includes_rider=True))
    _, _, K0, K2 = peer.form_reduced_canonical_matrices()
    gK0 = values["g"] * np.asarray(K0, dtype=float)
    K2 = np.asarray(K2, dtype=float)
    a, c = np.linalg.det(K2), np.linalg.det(gK0)
    roots = np.roots([a, np.linalg.det(gK0 + K2) - a - c, c])
    real = [float(np.sqrt(r.real)) for r in roots if abs(r.imag) < 1e-12 and r.real > 0]

    def weave_growth(v):
        ev = np.linalg.eigvals(peer.form_state_space_matrices(v=v)[0])
        return max(z.real for z in ev if abs(z.imag) > 1e-6)
    return brentq(weave_growth, 11.5, 11.9, xtol=1e-14), real


def test_issue_cases_a_split_weave_pair_destabilises_as_a_real_root(capsys):
    # the issue's loaded Cargo (No Hands as the thesis placed it): 20.785 m/s was listed as a weave
    # speed; a real root crosses there.  Both speeds against the peer (1e-9 m/s)
    weave, (real,) = _peer_crossings(scenario_parameters("cargo-loaded", "no-hands", allow_off_contact=True))
    assert main(["stability", "cargo-loaded", "--rider", "no-hands", "--allow-off-contact", "--format", "json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["weave_speeds"] == [pytest.approx(weave, abs=1e-9)]
    assert d["capsize_speeds"] == [pytest.approx(real, abs=1e-9)]
    split = [c for c in d["crossings"] if c["speed"] > 20]
    assert split == [{"speed": pytest.approx(real, abs=1e-9), "kind": "real",
                      "direction": "destabilising", "frequency": 0.0, "mode": "weave 1"}]
    assert main(["stability", "cargo-loaded", "--rider", "no-hands", "--allow-off-contact"]) == 0
    text = capsys.readouterr().out
    shown = next(line for line in text.splitlines() if line.startswith("capsize speeds (a real root crosses"))
    assert float(shown.split(":")[1]) == pytest.approx(real, abs=1e-9)   # printed to 1e-12
    assert "weave, real (upper)" in text


THESIS_CASES = [("Jamis", "No Hands", "Titanium"), ("Cargo", "No Hands", "Aluminum"),
                ("Cargo load", "No Rider", "Infinite"), ("Cargo load", "No Hands", "Steel"),
                ("Cargo load", "Relaxed", "Titanium"), ("Jamis", "Aero Tuck", "Steel")]
"""Thesis sets whose crossings include split weave pairs, pairs born from real roots and windows
narrower than the thesis's 0.05 m/s grid."""


@pytest.mark.parametrize("key", THESIS_CASES)
def test_thesis_sets_with_split_and_close_crossings(key):
    bicycle, rider, material = key
    S = thesis_stiffness("Cargo" if bicycle == "Cargo load" else bicycle, material)
    st, _ = check_crossings(whipple_model(thesis_set(bicycle, rider), S))
    for label in st.modes.labels:
        for c in st.mode_crossings(label):
            assert c.mode in (label, label.rpartition(" ")[0])


def test_mode_names_one_weave_while_a_pair_and_real_branches_after_the_split():
    modes = follow_modes(whipple_model(thesis_set("Cargo load", "No Rider")), speed_grid())
    names = modes.names()
    at = {v: names[np.argmin(np.abs(modes.speeds - v))] for v in (0.0, 10.0, 25.0)}
    assert list(at[0.0][:2]) == ["weave, real (lower)", "weave, real (upper)"]     # before the roots merge
    assert list(at[10.0][:2]) == ["weave", "weave"]
    # the heavy load makes capsize and caster one oscillatory pair at 10 m/s: named so
    k10 = np.argmin(np.abs(modes.speeds - 10.0))
    assert modes.eigenvalues[k10, 2] == np.conj(modes.eigenvalues[k10, 3]) != modes.eigenvalues[k10, 3]
    assert list(at[10.0][2:]) == ["capsize + caster oscillation"] * 2
    assert list(names[0, 2:]) == ["capsize", "caster"]
    assert sorted(at[25.0][:2]) == ["weave, real (lower)", "weave, real (upper)"]
    k = np.argmin(np.abs(modes.speeds - 25.0))
    upper = list(at[25.0]).index("weave, real (upper)")
    assert modes.eigenvalues[k, upper].real == modes.eigenvalues[k, :2].real.max()


def test_eig_table_shows_the_weave_as_one_mode(capsys):
    assert main(["eig", "cargo-loaded-thesis", "--speeds", "0:30:6"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split()[:5] == ["speed", "weave", "re", "weave", "im"] and "weave 1" not in lines[0]
    rows = {float(line.split()[0]): line for line in lines[2:]}
    assert rows[6.0].split()[1:3] == ["0.893508", "+-1.969310"]           # the pair, once
    assert rows[24.0].split()[1:4] == ["0.009079,", "-6.479137", "real"]   # two real roots, larger first
    assert main(["eig", "cargo-loaded-thesis", "--speeds", "0:30:6", "--format", "csv"]) == 0
    assert capsys.readouterr().out.startswith("speed,weave_1_re,weave_1_im,weave_2_re")   # CSV: every root
