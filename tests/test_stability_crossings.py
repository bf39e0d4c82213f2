"""Crossings of Re = 0 named by the root that crosses, and critical speeds as exact as before.

* Every sign change of the overall stability margin on a 0.01 m/s grid, found here from
  the eigenvalues ``bikemass eig`` prints (the root with the largest real part on the
  unstable side: real or complex), appears in ``crossings`` with that kind, and
  ``weave_speeds`` / ``capsize_speeds`` hold only crossings of their kind.
* Reference numbers: the critical speeds and range ends printed by the implementation
  before the fast root finder (scipy's brentq on the vectorised quartic), for thesis
  parameter sets whose crossings include split weave pairs; the new ones agree to 1e-12 m/s
  (both are roots to 1e-13 m/s of the same eigenvalue functions).
"""

import json
import subprocess
import sys
from functools import lru_cache

import numpy as np
import pytest

from bikemass.scenario import catalog
from bikemass.cli.main import main
from bikemass.models.canonical import canonical_matrices
from bikemass.analysis.stability import critical_speeds, follow_modes, stability, state_matrices
from bikemass.models.flexible_static import with_frame_stiffness
from bikemass.analysis.stability.analysis import speed_grid
from bikemass.analysis.stability.critical import SpeedEigenvalues
from bikemass.analysis.stability.roots import brent
from thesis_sets import stiffness as thesis_stiffness
from thesis_sets import thesis_set

FINE = speed_grid(0.0, 30.0, 0.01)


def grid_crossings(matrices):
    """``[(v_k, v_k+1, kind)]``: sign changes of the largest real part on the fine grid."""
    values = follow_modes(matrices, FINE).eigenvalues          # what `bikemass eig` prints
    top = values.real.max(axis=1)
    sign = np.where(top > 1e-10, 1, np.where(top < -1e-10, -1, 0))
    out = []
    nonzero = np.flatnonzero(sign)
    for a, b in zip(nonzero[:-1], nonzero[1:]):
        if sign[a] != sign[b]:
            unstable = a if sign[a] > 0 else b
            root = values[unstable, np.argmax(values[unstable].real)]
            out.append((FINE[a], FINE[b], "real" if root.imag == 0 else "oscillatory"))
    return out


def check_crossings(matrices):
    st = stability(matrices)
    found = grid_crossings(matrices)
    for a, b, kind in found:
        assert any(a - 1e-9 <= c.speed <= b + 1e-9 and c.kind == kind for c in st.crossings), (a, b, kind)
    state = lambda v: np.linalg.eigvals(state_matrices(matrices, [v])[0])    # noqa: E731
    for speeds, kind in ((st.weave_speeds, "oscillatory"), (st.capsize_speeds, "real")):
        for v in speeds:
            roots = state(v)
            crossing = roots[np.argmin(np.abs(roots.real))]
            assert abs(crossing.real) < 1e-9
            assert (crossing.imag != 0) == (kind == "oscillatory"), (v, kind, roots)
    return st, found


JAMIS_RIDERS = ("no-hands-thesis", "relaxed-thesis", "on-hoods-thesis", "aerobars-thesis", "aero-tuck-thesis")


@lru_cache(maxsize=None)
def jamis_matrices(rider):
    return canonical_matrices(catalog.parameters("jamis", rider))


@pytest.mark.parametrize("material", ("steel", "titanium", "aluminum"))
def test_jamis_frames_with_thesis_riders(material):
    S = catalog.stiffness("jamis", material)
    kinds = set()
    for rider in JAMIS_RIDERS:
        m = with_frame_stiffness(jamis_matrices(rider), S)
        st, found = check_crossings(m)
        kinds |= {k for _, _, k in found}
    assert "oscillatory" in kinds


@pytest.mark.parametrize("bike, rider", [("benchmark", "none"), ("cargo", "none"), ("cargo", "relaxed-thesis"),
                                         ("cargo-loaded", "none"), ("cargo-loaded", "no-hands")])
def test_benchmark_and_cargo(bike, rider):
    check_crossings(canonical_matrices(catalog.parameters(bike, rider)))


def test_issue_cases_a_split_weave_pair_destabilises_as_a_real_root(capsys):
    # the issue's loaded Cargo (No Hands as the thesis placed it): 20.785 m/s was listed as a weave
    # speed; a real root crosses there
    assert main(["stability", "cargo-loaded", "--rider", "no-hands", "--allow-off-contact", "--format", "json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["weave_speeds"] == [pytest.approx(11.707856716414494, abs=1e-9)]
    assert d["capsize_speeds"] == [pytest.approx(20.785440946227254, abs=1e-9)]
    split = [c for c in d["crossings"] if c["speed"] > 20]
    assert split == [{"speed": pytest.approx(20.785440946227254, abs=1e-9), "kind": "real",
                      "direction": "destabilising", "mode": "weave 1"}]
    assert main(["stability", "cargo-loaded", "--rider", "no-hands", "--allow-off-contact"]) == 0
    text = capsys.readouterr().out
    shown = next(line for line in text.splitlines() if line.startswith("capsize speeds (a real root crosses"))
    assert float(shown.split(":")[1]) == pytest.approx(20.785440946227254, abs=1e-9)   # printed to 1e-12
    assert "weave, real (upper)" in text


# (bicycle, rider, stiffness): {label: [(speed, direction, kind)]}, strict and marginal exact ranges,
# speeds as printed before issue 14
REFERENCE = {
    ("Jamis", "No Hands", "Titanium"): (
        {"weave 1": [(5.912964194214748, "stabilising", "oscillatory"), (6.865939143293001, "destabilising", "real")],
         "weave 2": [(5.912964194214748, "stabilising", "oscillatory")]},
        [[5.912964194214748, 6.865939143293001]], [[4.106553303224433, 30.0]]),
    ("Cargo", "No Hands", "Aluminum"): (
        {"weave 1": [(4.382662375101977, "stabilising", "real"), (5.824913952132582, "destabilising", "oscillatory")],
         "capsize": [(5.824913952132582, "destabilising", "oscillatory")]},
        [], []),
    ("Cargo load", "No Rider", "Infinite"): (
        {"weave 1": [(7.735477052476577, "stabilising", "oscillatory"), (22.11854621989917, "destabilising", "real")],
         "weave 2": [(7.735477052476577, "stabilising", "oscillatory")]},
        [[7.735477052476577, 22.11854621989917]], [[6.8609110180638835, 30.0]]),
    ("Cargo load", "No Hands", "Steel"): (
        {"weave 1": [(7.868337715424532, "stabilising", "oscillatory"), (7.945294688434055, "destabilising", "real")],
         "weave 2": [(7.868337715424532, "stabilising", "oscillatory")]},
        [[7.868337715424532, 7.945294688434055]], [[6.412258107300248, 30.0]]),
    ("Cargo load", "Relaxed", "Titanium"): (
        {"weave 1": [(6.0930039035017165, "stabilising", "real")]}, [], [[26.32236703940915, 30.0]]),
    ("Jamis", "Aero Tuck", "Steel"): (
        {"weave 1": [(6.815813016721855, "stabilising", "oscillatory")],
         "weave 2": [(6.815813016721855, "stabilising", "oscillatory")],
         "capsize": [(10.757220605482416, "destabilising", "real")]},
        [[6.815813016721855, 10.757220605482416]], [[6.815813016721855, 30.0]]),
}


@pytest.mark.parametrize("key", REFERENCE)
def test_critical_speeds_equal_the_previous_implementation_to_1e_12(key):
    bicycle, rider, material = key
    crossings, strict, marginal = REFERENCE[key]
    S = thesis_stiffness("Cargo" if bicycle == "Cargo load" else bicycle, material)
    m = with_frame_stiffness(canonical_matrices(thesis_set(bicycle, rider)), S)
    st = stability(m)
    got = {label: [(c.speed, c.direction, c.kind) for c in st.mode_crossings(label)] for label in st.modes.labels}
    assert {k: v for k, v in got.items() if v}.keys() == crossings.keys()
    for label, expected in crossings.items():
        assert len(got[label]) == len(expected)
        for (s, d, k), (s0, d0, k0) in zip(got[label], expected):
            assert abs(s - s0) <= 1e-12 and (d, k) == (d0, k0)
    for ranges, expected in ((st.ranges["strict"]["exact"], strict), (st.ranges["marginal"]["exact"], marginal)):
        assert np.allclose(ranges, expected, rtol=0, atol=1e-12) and len(ranges) == len(expected)
    assert set(st.weave_speeds) == {c.speed for c in st.crossings if c.kind == "oscillatory"}
    assert critical_speeds(m) == st.crossings


def test_mode_names_one_weave_while_a_pair_and_real_branches_after_the_split():
    modes = follow_modes(canonical_matrices(thesis_set("Cargo load", "No Rider")), speed_grid())
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


def test_brent_finds_roots_to_the_tolerance():
    calls = []

    def f(x):
        calls.append(x)
        return np.cos(x) - x

    root = brent(f, 0.0, 1.0)
    assert abs(root - 0.7390851332151607) < 1e-13 and len(calls) < 12
    assert brent(lambda x: (x - 2.0) ** 3, 0.0, 3.5) == pytest.approx(2.0, abs=1e-9)   # flat triple root
    assert brent(lambda x: x - 0.3, 0.3, 1.0) == 0.3
    with pytest.raises(ValueError):
        brent(lambda x: x * x + 1, -1.0, 1.0)


def test_single_speed_eigenvalues_are_memoised_and_equal_lapack():
    m = canonical_matrices(thesis_set("Benchmark", "Benchmark"))
    at = SpeedEigenvalues(m)
    a = at(4.5)
    assert at(4.5) is a and at.evaluations == 1
    ref = np.linalg.eigvals(state_matrices(m, [4.5])[0])
    assert np.allclose(np.sort_complex(a), np.sort_complex(ref), rtol=0, atol=1e-12)


def test_critical_speeds_need_no_scipy_optimize():
    code = ("import sys\n"
            "from bikemass.models.parameters import BenchmarkParameters\n"
            "from bikemass.models.canonical import canonical_matrices\n"
            "from bikemass.analysis.stability import stability\n"
            "p = BenchmarkParameters(w=1.02, c=0.08, lam=0.3141592653589793, g=9.81, rR=0.3, mR=2.0,"
            " IRxx=0.0603, IRyy=0.12, xB=0.3, zB=-0.9, mB=85.0, IBxx=9.2, IByy=11.0, IBzz=2.8, IBxz=2.4,"
            " xH=0.9, zH=-0.7, mH=4.0, IHxx=0.05892, IHyy=0.06, IHzz=0.00708, IHxz=-0.00756, rF=0.35,"
            " mF=3.0, IFxx=0.1405, IFyy=0.28)\n"
            "st = stability(canonical_matrices(p))\n"
            "print(st.weave_speeds[0], 'scipy.optimize' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split()
    assert float(out[0]) == pytest.approx(4.29238253634110, abs=1e-9) and out[1] == "False"


def test_eig_table_shows_the_weave_as_one_mode(capsys):
    assert main(["eig", "cargo-loaded-thesis", "--speeds", "0:30:6"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split()[:5] == ["speed", "weave", "re", "weave", "im"] and "weave 1" not in lines[0]
    rows = {float(line.split()[0]): line for line in lines[2:]}
    assert rows[6.0].split()[1:3] == ["0.893508", "+-1.969310"]           # the pair, once
    assert rows[24.0].split()[1:4] == ["0.009079,", "-6.479137", "real"]   # two real roots, larger first
    assert main(["eig", "cargo-loaded-thesis", "--speeds", "0:30:6", "--format", "csv"]) == 0
    assert capsys.readouterr().out.startswith("speed,weave_1_re,weave_1_im,weave_2_re")   # CSV: every root
