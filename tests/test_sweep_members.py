"""A model with members swept as arrays (bikemass.sweep.members, bikemass.analysis.engine.batch) against the
engine, configuration by configuration.

The reference is the engine: ``bm.stability(params, model=...)`` (the modes followed and named on the
speed grid, the crossings from the compound matrices' polynomial eigenvalue problems) for the c x lam
grid through ``bm.sweep``, and ``bikemass.sweep.evaluate.evaluate`` (the scenario built, the engine's
critical speeds) for seeded random perturbations of several bicycles with the tyre and rider-lean members.
Tolerance 1e-9 m/s (issue 32's); the two paths share no numerical step (characteristic polynomial,
Routh's array and Newton's method on determinants against eigenvalues and QZ), so the agreement is
limited by the engine's own refinement (Brent's method on eigenvalues' real parts, about 1e-11 m/s).
"""

import dataclasses
import os

import numpy as np
import pytest

import bikemass as bm
from bikemass.analysis.engine.batch import batch_critical_speeds, characteristic
from bikemass.sweep.evaluate import evaluate
from bikemass.sweep.members import evaluate_member_batch
from bikemass.sweep.table import NUMBERS

TOL = 1e-9
SPEEDS = ("weave_speed", "capsize_speed", "stable_from", "stable_to")
KEYS = ("c", "lam", "w", "xB", "zB", "mB", "IBxx", "IBzz", "xH", "zH", "mH", "IHxx", "IFyy", "IRyy")


def _same(got, want):
    """Both ``None``/``nan`` or within TOL (m/s)."""
    if want is None or (isinstance(want, float) and np.isnan(want)):
        return got is None or np.isnan(got)
    return got is not None and not np.isnan(got) and abs(got - want) <= TOL


def test_characteristic_polynomial_is_numpys_poly_of_the_eigenvalues():
    """Faddeev-LeVerrier's coefficients, at any speed, against numpy's polynomial of the eigenvalues."""
    model = bm.Scenario("benchmark", model="tyre").build().model
    P = np.asarray(model.dynamic_coefficients)
    a = characteristic(P[None])[0]
    for v in (0.5, 4.0, 17.0):
        A = sum(v ** k * P[k] for k in range(len(P)))
        want = np.poly(np.linalg.eigvals(A))[::-1]
        got = a @ v ** np.arange(a.shape[1])
        assert np.allclose(got, want, rtol=1e-9, atol=1e-9 * np.abs(want).max())


def test_the_benchmark_tyre_model_as_the_engine_names_it():
    """One row: Meijaard's benchmark with the default tyres, against ``bm.stability`` (modes followed and named)."""
    params = bm.parameters("benchmark")
    result = bm.stability(params, model="tyre")
    model = bm.Scenario("benchmark", model="tyre").build().model
    out = batch_critical_speeds(np.asarray(model.dynamic_coefficients)[None], model.families, 30.0)
    assert out["decided"][0]
    assert abs(out["weave_speed"][0] - result.weave_speeds[0]) <= TOL
    assert abs(out["capsize_speed"][0] - result.capsize_speeds[0]) <= TOL
    assert abs(out["stable_from"][0] - result.stable_speeds[0][0]) <= TOL
    assert abs(out["stable_to"][0] - result.stable_speeds[0][1]) <= TOL


def test_c_lam_tyre_sweep_rows_equal_bm_stability(tmp_path):
    """Issue 32: a ``model: tyre`` sweep of the benchmark's trail x steer tilt through ``bm.sweep``;
    every row equals ``bm.stability(params, model="tyre")`` of its parameters (the first weave and
    capsize crossings and the first stable range) to 1e-9 m/s, rows without a weave crossing or
    without a stable range included."""
    spec = tmp_path / "tyre.yaml"
    spec.write_text("bike: benchmark\nmodel: tyre\nvary:\n  c: {from: 0.0, to: 0.2, num: 21}\n"
                    "  lam: {from: 0.1, to: 0.5, num: 13}\n")
    result = bm.sweep(spec, tmp_path / "out")
    base = bm.parameters("benchmark")
    empty = {"weave_speed": 0, "stable_from": 0}
    for row in result:
        r = bm.stability(dataclasses.replace(base, c=row["c"], lam=row["lam"]), model="tyre")
        want = {"weave_speed": r.weave_speeds[0] if r.weave_speeds else None,
                "capsize_speed": r.capsize_speeds[0] if r.capsize_speeds else None,
                "stable_from": r.stable_speeds[0][0] if r.stable_speeds else None,
                "stable_to": r.stable_speeds[0][1] if r.stable_speeds else None}
        for k in SPEEDS:
            assert _same(row[k], want[k]), (row, k, want[k])
        for k in empty:
            empty[k] += want[k] is None
        assert row["error"] is None
    assert empty["weave_speed"] > 0 and empty["stable_from"] > 0       # rows with no crossing were compared


CASES = [("benchmark", None, "tyre", 0), ("jamis", "relaxed", "rider-lean", 1),
         ("jamis", "relaxed", "rider-lean+tyre", 2), ("browser_measured", None, "tyre", 3)]


@pytest.mark.parametrize("bike, rider, model, seed", CASES)
def test_random_perturbations_equal_the_engine(bike, rider, model, seed):
    """Seeded random perturbations (+-30 % of four parameters at a time) of several bicycles with the
    tyre and rider-lean members: the batch path's rows equal the engine's
    (:func:`~bikemass.sweep.evaluate.evaluate`) to 1e-9 m/s, and its total mass to 1e-12 relative."""
    path = os.path.join(os.path.dirname(bm.__file__), "..", "..", "frames", f"{bike}.yaml")
    scenario = bm.Scenario(path if bike == "browser_measured" else bike, rider, model=model)
    base = scenario.build().values()
    rng = np.random.default_rng(seed)
    count = 120
    keys = list(rng.choice(KEYS, 4, replace=False))
    changes = {k: base[k] * (1 + 0.3 * rng.uniform(-1, 1, count)) for k in keys}
    engine_rows = []

    def reference(config):
        engine_rows.append(config)
        return evaluate(scenario, config, 30.0)
    out = evaluate_member_batch(scenario, changes, count, 30.0, reference)
    assert len(engine_rows) <= count // 4              # the batch decides most rows
    for i in range(count):
        want = evaluate(scenario, {k: float(v[i]) for k, v in changes.items()}, 30.0)
        for k in SPEEDS:
            assert _same(out.values[k][i], want[k]), (i, k, out.values[k][i], want[k])
        if want["total_mass"] is not None:
            assert abs(out.values["total_mass"][i] - want["total_mass"]) <= 1e-12 * want["total_mass"]
        assert out.errors[i] == want["error"]


def test_refused_and_non_numeric_rows_get_the_references_outcome():
    """Contract test of the routing: a value that is not a number and a parameter set the checks refuse go
    to the reference, which gives them its one-line reason; the others are decided by the batch."""
    scenario = bm.Scenario("benchmark", model="tyre")
    changes = {"c": [0.08, "x", 0.08], "w": [1.02, 1.02, -1.0]}
    out = evaluate_member_batch(scenario, changes, 3, 30.0, lambda c: evaluate(scenario, c, 30.0))
    assert out.errors[0] is None and out.errors[1] and out.errors[2]
    assert np.isnan(out.values["weave_speed"][1]) and np.isnan(out.values["weave_speed"][2])
    assert set(out.values) == set(NUMBERS)
