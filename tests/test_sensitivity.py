"""Exact critical-speed derivatives against central finite differences of independently found speeds."""

import json

import numpy as np
import pytest
from images import is_drawn

from bikemass.scenario import catalog
from bikemass.scenario.scenario import parameters as scenario_parameters
from bikemass.analysis.engine import crossings
from bikemass.analysis.engine.critical import critical_speeds
from bikemass.analysis.model import matrix_derivatives
from bikemass.analysis.sensitivity import sensitivity
from bikemass.cli.main import main
from bikemass.models.canonical import canonical_matrices
from bikemass.models.whipple import whipple_model
from bikemass.models.parameters import NAMES


def general_speeds(params, S=None):
    """Weave and capsize speeds from the engine's general path (polynomial eigenvalue problems of
    the compound matrices), not the closed form that the sensitivities use."""
    found = crossings.axis_crossings(whipple_model(params, S), 0.0, 30.0)
    return (next(s for s, k, _ in found if k == "oscillatory"), next(s for s, k, _ in found if k == "real"))



def test_benchmark_52_derivatives_equal_central_differences(capsys):
    """All 52 derivatives of `bikemass sensitivity benchmark --format json` equal central
    differences (relative step 1e-5) of speeds found by the engine's general path, to 1e-4
    relative.  Derivatives that are zero by the physics (IByy, IHyy; the capsize speed does not
    depend on the inertias that only enter M) are held to 1e-6 in elasticity: FD noise is ~1e-9."""
    assert main(["sensitivity", "benchmark", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    p = scenario_parameters("benchmark")
    assert doc["weave_speed"] == pytest.approx(4.29238253634110, abs=1e-9)   # Meijaard: exact (prints ...111)
    assert doc["capsize_speed"] == pytest.approx(6.02426201538836, abs=1e-9)
    for name in NAMES:
        x = getattr(p, name)
        h = 1e-5 * abs(x)
        hi, lo = general_speeds(p.replace(**{name: x + h})), general_speeds(p.replace(**{name: x - h}))
        for k, key in enumerate(("weave_speed", "capsize_speed")):
            fd = (hi[k] - lo[k]) / (2 * h)
            exact = doc["d_" + key][name]
            assert abs(exact - fd) <= 1e-4 * abs(fd) + 1e-6 * doc[key] / abs(x), (name, key, exact, fd)


def test_elasticity_in_g_is_one_half():
    """Speeds scale with sqrt(g) for a rigid frame (v^2 K2 balances g K0)."""
    r = sensitivity(scenario_parameters("benchmark"))
    assert r.elasticities("weave_speed")["g"] == pytest.approx(0.5, abs=1e-12)
    assert r.elasticities("capsize_speed")["g"] == pytest.approx(0.5, abs=1e-12)


def test_flexible_frame_derivatives_equal_differences():
    """Jamis (thesis bodies) with the Relaxed rider and the published steel S: against differences."""
    p = scenario_parameters("jamis-thesis", "relaxed-thesis", "thesis")
    S = catalog.stiffness("jamis-thesis", "steel")
    r = sensitivity(p, S)

    def speeds(q):
        return general_speeds(q, S)
    for name in ("c", "lam", "mB", "IFyy"):
        x = getattr(p, name)
        h = 1e-6 * abs(x)
        hi, lo = speeds(p.replace(**{name: x + h})), speeds(p.replace(**{name: x - h}))
        for k, key in enumerate(("weave_speed", "capsize_speed")):
            fd = (hi[k] - lo[k]) / (2 * h)
            assert getattr(r, "d_" + key)[name] == pytest.approx(fd, rel=1e-5), (name, key)


def test_matrix_derivatives_complex_step_equal_differences():
    p = scenario_parameters("benchmark")
    d = matrix_derivatives(p)
    for name in ("w", "c", "lam", "xH", "IHxz", "rF"):
        x = getattr(p, name)
        h = 1e-5 * abs(x)
        hi = canonical_matrices(p.replace(**{name: x + h}))
        lo = canonical_matrices(p.replace(**{name: x - h}))
        for m in ("M", "C1", "K0", "K2"):
            np.testing.assert_allclose(d[name][m], (getattr(hi, m) - getattr(lo, m)) / (2 * h),
                                       rtol=1e-6, atol=1e-8)


@pytest.mark.parametrize("bike, rider, stiffness", [
    ("benchmark", None, "infinite"), ("jamis-thesis", None, "aluminum"),
    ("cargo-loaded-thesis", None, "infinite"), ("jamis-thesis", None, "infinite")])
def test_closed_form_crossings_equal_the_general_engines(bike, rider, stiffness):
    """The quadratic-in-v^2 crossings (the fast path of sensitivities and sweeps) equal every
    Re = 0 crossing that the general path finds from the compound matrices, to 1e-9 m/s with
    the same kind, and the strict stable ranges equal the runs of a stable eigenvalue count on a
    0.001 m/s grid."""
    p, S = scenario_parameters(bike, rider), catalog.stiffness(bike, stiffness)
    model = whipple_model(p, S)
    mine = critical_speeds(model)
    general = crossings.axis_crossings(model, 0.0, 30.0)
    assert [c.kind for c in mine.crossings] == [k for _, k, _ in general]
    np.testing.assert_allclose([c.speed for c in mine.crossings], [s for s, _, _ in general], atol=1e-9)
    v = np.arange(0.0005, 30.0, 0.001)
    stable = np.all(np.linalg.eigvals(model.dynamic_matrix(v)).real < 0, axis=1)
    for (a, b) in mine.stable:
        inside = (v > a + 1e-3) & (v < b - 1e-3)
        assert stable[inside].all()
    outside = np.ones_like(stable)
    for (a, b) in mine.stable:
        outside &= ~((v >= a - 1e-3) & (v <= b + 1e-3))
    assert not stable[outside].any()


def test_crossing_kinds_follow_the_root_that_crosses():
    """A real root crossing at s = 0 is a capsize-type crossing even when the tracker calls it
    weave (Cargo loaded, thesis body: the split weave pair's real branch at 22.1 m/s)."""
    p = scenario_parameters("cargo-loaded-thesis")
    model = whipple_model(p)
    mine = critical_speeds(model)
    for c in mine.crossings:
        A = model.dynamic_matrix(c.speed)
        ev = np.linalg.eigvals(A)
        on_axis = ev[np.argmin(np.abs(ev.real))]
        assert abs(on_axis.real) < 1e-8
        assert (c.kind == "real") == (abs(on_axis.imag) < 1e-8)


def test_sensitivity_table_plot_and_bad_input(tmp_path, capsys):
    out = tmp_path / "s.png"
    assert main(["sensitivity", "benchmark", "--plot", str(out), "--format", "table"]) == 0
    text = capsys.readouterr().out
    assert "4.292382536" in text and is_drawn(out)
    assert main(["sensitivity", "benchmark", "--plot", str(tmp_path / "s.xyz")]) == 2
    assert main(["sensitivity", "benchmark", "--max-speed", "-1"]) == 2
    assert main(["sensitivity", "nonexistent-bike"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 3 and all(line.startswith("bikemass: error:") for line in err)


def test_sensitivity_speaks_the_dialect(tmp_path, capsys):
    """--plot alone: the figure and nothing on stdout; --format csv: one row per critical speed and
    parameter, the same numbers as the JSON; -o FILE.csv: CSV by the suffix, stdout empty;
    --quiet: nothing."""
    import csv
    import io
    fig = tmp_path / "bars.svg"
    assert main(["sensitivity", "benchmark", "--plot", str(fig)]) == 0
    assert capsys.readouterr().out == "" and is_drawn(fig)
    stiff = tmp_path / "S.yaml"
    stiff.write_text("S: [[6702.3, 1237.0], [1237.0, 3634.7]]\n")
    assert main(["sensitivity", "benchmark", "--stiffness", str(stiff), "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["units"]["weave_speed"] == "m/s" and "c" not in doc["units"]
    assert main(["sensitivity", "benchmark", "--stiffness", str(stiff), "--format", "csv"]) == 0
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert [r["kind"] for r in rows] == ["speed"] * 2 + ["parameter"] * 26 + ["stiffness"] * 3
    by_name = {r["input"]: r for r in rows}
    assert float(by_name["weave_speed"]["value"]) == pytest.approx(doc["weave_speed"], rel=1e-15)
    for name in NAMES:
        assert float(by_name[name]["d_weave_speed (m/s per unit)"]) == pytest.approx(doc["d_weave_speed"][name],
                                                                                      rel=1e-15, abs=1e-300)
        assert float(by_name[name]["elasticity_capsize_speed"]) == pytest.approx(
            doc["elasticity_capsize_speed"][name], rel=1e-15, abs=1e-300)
    assert by_name["lam"]["unit"] == "rad" and by_name["S_phiphi"]["unit"] == "N m/rad"
    assert main(["sensitivity", "benchmark", "-o", str(tmp_path / "d.csv")]) == 0
    assert capsys.readouterr().out == ""
    assert (tmp_path / "d.csv").read_text().startswith("input,kind,value,unit,")
    assert main(["sensitivity", "benchmark", "--quiet"]) == 0
    assert capsys.readouterr().out == ""


def test_stiffness_derivatives_equal_differences():
    p = scenario_parameters("jamis-thesis", "relaxed-thesis", "thesis")
    S = catalog.stiffness("jamis-thesis", "titanium")
    r = sensitivity(p, S)
    for entry, cells in {"S_phiphi": [(0, 0)], "S_phidelta": [(0, 1), (1, 0)], "S_deltadelta": [(1, 1)]}.items():
        h = 1e-5 * abs(S[cells[0]])
        speeds = []
        for sign in (1, -1):
            Sh = np.array(S, dtype=float)
            for cell in cells:
                Sh[cell] += sign * h
            speeds.append(general_speeds(p, Sh))
        for k, key in enumerate(("weave_speed", "capsize_speed")):
            fd = (speeds[0][k] - speeds[1][k]) / (2 * h)
            assert r.d_stiffness[key][entry] == pytest.approx(fd, rel=1e-5, abs=1e-12), (entry, key)


def test_geometry_chain_equals_direct_difference(capsys):
    """Seat-stay wall of the steel Jamis (mass properties and beam S both change): the chained
    derivative equals the central difference of the critical speeds themselves."""
    from bikemass.scenario.scenario import Scenario
    from bikemass.analysis.sensitivity import geometry_sensitivity
    scenario = Scenario("jamis", None, "steel")
    key = "sections.seat_stay.wall"
    g = geometry_sensitivity(scenario, [key])[key]
    x, h = g["value"], g["step"]
    assert x == pytest.approx(0.040 * 0.0254, rel=1e-12)     # SI: the file writes 0.040 in
    a, b = scenario.build({key: x + h}), scenario.build({key: x - h})
    (pa, Sa), (pb, Sb) = (a.parameters, a.stiffness), (b.parameters, b.stiffness)
    ca, cb = general_speeds(pa, Sa), general_speeds(pb, Sb)
    assert g["weave_speed"] == pytest.approx((ca[0] - cb[0]) / (2 * h), rel=1e-5)
    assert g["capsize_speed"] == pytest.approx((ca[1] - cb[1]) / (2 * h), rel=1e-5)
    assert abs(g["weave_speed"]) > 1 and g["difference_check"] < 1e-4 * abs(g["weave_speed"])
    assert main(["sensitivity", "benchmark", "--inputs", "geometry.no_such_key"]) == 2
    assert "--inputs: geometry.no_such_key" in capsys.readouterr().err


def test_resource_warnings_are_not_the_commands(monkeypatch, capsys):
    """A ResourceWarning while a command runs (the garbage collector finalising something other
    code left open, e.g. a TemporaryDirectory) is neither printed nor put in the JSON: the
    command's warnings are about its input."""
    import warnings

    import bikemass.analysis.sensitivity as module
    from bikemass.core.errors import BikemassWarning
    real = module.sensitivity

    def leaky(*args, **kwargs):
        warnings.warn("Implicitly cleaning up <TemporaryDirectory '/tmp/x'>", ResourceWarning)
        warnings.warn("a warning about the input", BikemassWarning)
        return real(*args, **kwargs)
    monkeypatch.setattr(module, "sensitivity", leaky)
    assert main(["sensitivity", "benchmark", "--format", "json"]) == 0
    captured = capsys.readouterr()
    assert json.loads(captured.out)["warnings"] == ["a warning about the input"]
    assert "TemporaryDirectory" not in captured.err and "a warning about the input" in captured.err


@pytest.mark.parametrize("step", ["1e-300", "nan", "0", "0.5"])
def test_a_step_that_leaves_only_rounding_is_refused(capsys, step):
    """``--step 1e-300`` gave derivatives of 0 (x + h rounds to x) and ``--step nan`` without --inputs passed
    unseen: a relative step outside 1e-10..0.1 is refused in one line, with or without --inputs."""
    assert main(["sensitivity", "jamis", "--inputs", "geometry.trail", "--step", step]) == 2
    assert main(["sensitivity", "benchmark", "--step", step]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all("--step" in line and "1e-10 to 0.1" in line for line in err)
