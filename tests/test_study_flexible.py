"""The study's flexible part (bikemass.study.flexible: the thesis's question asked again with the
frame's inertia and the fork's compliance), checked against the models computed directly, by
another route than the study's:

* the parameters from the public API (``bm.parameters``, the rider as the thesis placed it), the
  compliances by material name (``fe.flexible.compliances``), the model from ``family.build``;
* the wobble's root followed by hand from standstill (plain numpy, not the engine's tracking), its
  frequency and growth at 8 m/s and its unstable speeds from the sign of its real part (Brent's
  method where it changes);
* every capsize speed where the model's stiffness ``K0 + v^2 K2`` is singular (a real root at zero:
  no eigenvalues, no tracking), every weave speed where a low-frequency pair's real part changes sign
  (Brent's method), the rigid rider's also against ``bm.stability``;
* the limit: a very stiff frame and fork give back the rigid bicycle's weave and capsize speeds, the
  difference falling as 1/stiffness, and the wobble's frequency grows as sqrt(stiffness).
"""

import csv
import re
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

import bikemass as bm
from bikemass.core.errors import BikemassWarning
from bikemass.fe.flexible import compliances
from bikemass.models.family import build
from bikemass.models.whipple import whipple_model
from bikemass.rider.lean_split import rider_lean_parameters
from bikemass.study import flexible
from bikemass.study.configurations import THESIS_NAMES

NAMES = {label: name for name, label in THESIS_NAMES.items()}
GRID = np.round(np.arange(0.0, 30.0 + 1e-9, 0.05), 12)
K8 = int(np.flatnonzero(GRID == 8.0)[0])


def read_csv(path):
    with open(path, newline="") as fh:
        rows = list(csv.DictReader(fh))
    return rows


def number(cell):
    return None if cell == "" else float(cell)


@pytest.fixture(scope="module")
def direct():
    """``{bike: Bicycle}``, cached parameters and compliances, built through the public API."""
    bikes = {b: bm.load_bicycle(b) for b in ("jamis", "cargo")}
    params, flex = {}, {}

    def parameters(bike, rider):
        if (bike, rider) not in params:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", BikemassWarning)          # the thesis's riders sit off contact
                params[bike, rider] = bm.parameters(bikes[bike], rider, method="exact", allow_off_contact=True)
        return params[bike, rider]

    def compliance(bike, material):
        if (bike, material) not in flex:
            flex[bike, material] = compliances(bikes[bike], material)
        return flex[bike, material]
    return bikes, parameters, compliance


def followed_wobble(model):
    """The steer-dominated root of the compliances' family followed from standstill over GRID: the
    slowest oscillation at standstill whose largest participation lies in the compliances' states."""
    values, X = np.linalg.eig(model.dynamic_matrix(0.0))
    share = np.abs(X * np.linalg.inv(X).T)
    states = list(dict(model.families)["wobble"])
    mine = [k for k in range(len(values)) if share[states, k].sum() > 0.5 and values[k].imag > 0]
    root, roots = values[min(mine, key=lambda k: values[k].imag)], []
    A = np.einsum("nk,kij->nij", GRID[:, None] ** np.arange(len(model.dynamic_coefficients)),
                  np.asarray(model.dynamic_coefficients))                 # A(v) = sum_k v^k A_k at every speed
    for values in np.linalg.eigvals(A):
        root = values[np.argmin(np.abs(values - root))]
        roots.append(root)
    return np.array(roots)


def nearest_real_part(model, target):
    """``Re`` of the root of ``model`` nearest ``target`` (1/s), as a function of speed."""
    def f(v):
        values = np.linalg.eigvals(model.dynamic_matrix(v))
        return values[np.argmin(np.abs(values - target))].real
    return f


def capsize_at(model, guess):
    """The speed (m/s) near ``guess`` where ``det(K0 + v^2 K2)`` changes sign."""
    det = lambda v: np.linalg.det(model.mechanics.stiffness(v))       # noqa: E731
    return brentq(det, guess - 0.01, guess + 0.01, xtol=1e-12)


def weave_at(model, guess):
    """The speed (m/s) near ``guess`` where an oscillation below 3 Hz crosses ``Re = 0``, and its frequency (Hz)."""
    values = np.linalg.eigvals(model.dynamic_matrix(guess))
    slow = values[(values.imag > 1e-6) & (values.imag < 2 * np.pi * 3.0)]
    root = slow[np.argmin(np.abs(slow.real))]
    speed = brentq(nearest_real_part(model, root), guess - 0.01, guess + 0.01, xtol=1e-12)
    return speed, root.imag / (2 * np.pi)


@pytest.fixture(scope="module")
def table(study):
    return read_csv(study[0] / "flexible_wobble.csv")


def test_every_bicycle_rider_and_material(table):
    keys = {(r["bicycle"], r["rider"], r["material"]) for r in table}
    assert len(table) == len(keys) == 2 * 5 * 3


def test_wobble_against_the_model_built_directly(table, direct):
    _, parameters, compliance = direct
    for row in table:
        bike, rider, material = NAMES[row["bicycle"]], NAMES[row["rider"]], NAMES[row["material"]]
        model = build("flexible", parameters(bike, rider), compliances=compliance(bike, material))
        roots = followed_wobble(model)
        at8 = roots[K8]
        assert float(row["wobble at 8 m/s (Hz)"]) == pytest.approx(at8.imag / (2 * np.pi), rel=1e-9), row
        assert float(row["wobble growth at 8 m/s (1/s)"]) == pytest.approx(at8.real, rel=1e-9, abs=1e-9), row
        start = number(row["wobble unstable from (m/s)"])
        growing = roots[1:].real > 0
        if start is None:
            assert not growing.any(), row
        elif start == 0.0:
            assert growing.all(), row
        else:
            i = int(np.flatnonzero(growing)[0]) + 1
            assert not growing[:i - 1].any() and growing[i - 1], row     # the first onset (damped, it may end)
            speed = brentq(nearest_real_part(model, roots[i]), GRID[i - 1], GRID[i], xtol=1e-12)
            assert start == pytest.approx(speed, abs=1e-7), row
        capsize = number(row["flexible capsize (m/s)"])
        assert capsize == pytest.approx(capsize_at(model, capsize), abs=1e-7), row


def test_rigid_frame_and_the_thesis_spring_against_their_stiffness(table, direct):
    bikes, parameters, _ = direct
    for row in table:
        bike, rider, material = NAMES[row["bicycle"]], NAMES[row["rider"]], NAMES[row["material"]]
        params = parameters(bike, rider)
        S = bm.stiffness(bikes[bike], material, source="computed")
        for name, model in (("rigid", whipple_model(params)), ("spring", whipple_model(params, S))):
            capsize, weave = number(row[f"{name} capsize (m/s)"]), number(row[f"{name} weave (m/s)"])
            assert capsize == pytest.approx(capsize_at(model, capsize), abs=1e-7), (name, row)
            if weave is not None:
                speed, hz = weave_at(model, weave)
                assert weave == pytest.approx(speed, abs=1e-7) and hz < 3.0, (name, row)
        assert number(row["rigid weave (m/s)"]) == pytest.approx(bm.stability(params).weave_speeds[0], abs=1e-9)


def test_leaning_rider_against_the_model_built_directly(study, direct):
    bikes, parameters, _ = direct
    rows = read_csv(study[0] / "rider_lean_weave.csv")
    assert len(rows) == 2 * 5
    for row in rows:
        bike, rider = NAMES[row["bicycle"]], NAMES[row["rider"]]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BikemassWarning)
            seated = bm.seated_rider(bikes[bike], rider, allow_off_contact=True)
        leaning = rider_lean_parameters(bikes[bike], seated, "exact")
        model = build("rider-lean", leaning)
        weave = float(row["leaning rider weave (m/s)"])
        speed, hz = weave_at(model, weave)
        assert weave == pytest.approx(speed, abs=1e-7) and hz < 3.0, row
        capsize = float(row["leaning rider capsize (m/s)"])
        assert capsize == pytest.approx(capsize_at(model, capsize), abs=1e-7), row
        rigid = bm.stability(parameters(bike, rider))
        assert float(row["rigid rider weave (m/s)"]) == pytest.approx(rigid.weave_speeds[0], abs=1e-9)
        assert float(row["weave change (m/s)"]) == pytest.approx(weave - rigid.weave_speeds[0], abs=1e-12)


def test_a_very_stiff_frame_gives_back_the_rigid_bicycle(direct):
    """Stiffness times f: the weave and capsize speeds approach the rigid ones as 1/f, the compliances'
    slowest oscillation's frequency grows as sqrt(f) (its inertia fixed), and so far above the published
    wobble band (15 Hz at most) none of it is named wobble."""
    _, parameters, compliance = direct
    for bike in ("jamis", "cargo"):
        params = parameters(bike, "relaxed")
        rigid = bm.stability(params)
        models = {f: build("flexible", params, compliances=compliance(bike, "steel").undamped().scaled(f))
                  for f in (1e4, 1e6)}
        stiff = {f: flexible.wobble(m) for f, m in models.items()}
        for which in ("weave_speeds", "capsize_speeds"):
            error = {f: abs(getattr(w, which)[0] - getattr(rigid, which)[0]) for f, w in stiff.items()}
            assert error[1e6] < 1e-4 and error[1e4] / error[1e6] == pytest.approx(100, rel=0.2), (bike, which)
        slowest = {f: min(abs(z.imag) for z in np.linalg.eigvals(m.dynamic_matrix(8.0)) if abs(z.imag) > 2 * np.pi * 15)
                   for f, m in models.items()}
        assert slowest[1e6] / slowest[1e4] == pytest.approx(10.0, rel=1e-3)
        assert all(w.frequency is None for w in stiff.values())


def test_findings_answer_from_the_table(study, table):
    """The report's answer counts what the table holds, and --no-figures drew nothing."""
    report = (study[0] / "report.md").read_text()
    unstable = sum(r["wobble unstable from (m/s)"] != "" for r in table)
    answer = re.search(r"Does frame stiffness matter\?[^\n]*", report).group(0)
    assert f"in {unstable} of {len(table)} combinations" in answer
    assert "## Frame stiffness with the frame's inertia" in report and "(CSV: `flexible_wobble.csv`)" in report
    assert "Does frame stiffness matter?" in (study[0] / "report.html").read_text()
    assert not (study[0] / "figures").exists()


def test_figure_shows_the_table(study, table):
    """The figure's frequency panels read back (from their artists) the table's frequencies."""
    from bikemass.study import figures
    from bikemass.study.pipeline import figure_jobs
    from bikemass.study.runs import Inputs
    jobs = figure_jobs(study[2], Inputs(), study[0] / "unused")
    job, = [j for j in jobs if figures.job_path(j).name == "flexible.png"]
    function, *args, _, title = job
    fig = function(*args, title)
    for bike, ax in zip(("Jamis", "Cargo"), fig.axes[::3]):
        drawn = sorted(round(y, 9) for line in ax.get_lines() if line.get_linestyle() == "-" for y in line.get_ydata())
        expected = sorted(round(float(r["wobble at 8 m/s (Hz)"]), 9) for r in table if r["bicycle"] == bike)
        assert drawn == expected


def test_damped_wobble_against_the_model_built_directly(study, direct):
    """The damped table (compliance, tyres and the arms at their zero defaults) against ``tyre+flexible``
    built directly (the arms' zeros are the model without them): the table's wobble is a root of that
    model at 8 m/s, and followed by hand (nearest root, plain numpy) down and up the grid its first
    onset is where its real part changes sign (Brent's method)."""
    _, parameters, compliance = direct
    rows = read_csv(study[0] / "damped_wobble.csv")
    assert len(rows) == len({(r["bicycle"], r["rider"], r["material"]) for r in rows}) == 2 * 5 * 3
    for row in rows:
        bike, rider, material = NAMES[row["bicycle"]], NAMES[row["rider"]], NAMES[row["material"]]
        model = build("tyre+flexible", parameters(bike, rider), compliances=compliance(bike, material))
        target = float(row["wobble growth at 8 m/s (1/s)"]) + 2j * np.pi * float(row["wobble at 8 m/s (Hz)"])
        at8 = np.linalg.eigvals(model.dynamic_matrix(8.0))
        assert np.min(np.abs(at8 - target)) < 1e-8 * abs(target), row
        A = np.einsum("nk,kij->nij", GRID[:, None] ** np.arange(len(model.dynamic_coefficients)),
                      np.asarray(model.dynamic_coefficients))
        every = np.linalg.eigvals(A)
        roots = np.empty(len(GRID), complex)
        roots[K8] = at8[np.argmin(np.abs(at8 - target))]
        for order in (range(K8 - 1, -1, -1), range(K8 + 1, len(GRID))):
            previous = roots[K8]
            for i in order:
                previous = roots[i] = every[i][np.argmin(np.abs(every[i] - previous))]
        growing = roots[1:].real > 0
        start = number(row["wobble onset (m/s)"])
        if start is None:
            assert not growing.any(), row
        else:
            i = int(np.flatnonzero(growing)[0]) + 1
            speed = brentq(nearest_real_part(model, roots[i]), GRID[i - 1], GRID[i], xtol=1e-12)
            assert start == pytest.approx(speed, abs=1e-7), row


def test_damped_model_with_zero_arms_is_the_model_without_them(direct):
    """Contract test: the study's damped model (the arms at their zero defaults) has the eigenvalues of
    ``tyre+flexible`` (the arms add no coordinate)."""
    _, parameters, compliance = direct
    params, flex = parameters("jamis", "relaxed"), compliance("jamis", "steel")
    with_arms = flexible.damped_model(params, flex, "relaxed")
    without = build("tyre+flexible", params, compliances=flex)
    for v in (0.5, 4.0, 8.0):
        a = np.sort_complex(np.linalg.eigvals(with_arms.dynamic_matrix(v)))
        b = np.sort_complex(np.linalg.eigvals(without.dynamic_matrix(v)))
        assert np.allclose(a, b, rtol=1e-10, atol=1e-9)


def test_damped_findings_count_the_table(study):
    report = (study[0] / "report.md").read_text()
    rows = read_csv(study[0] / "damped_wobble.csv")
    unstable = sum(r["wobble onset (m/s)"] != "" for r in rows)
    assert "## The wobble with damping and the arms" in report and "(CSV: `damped_wobble.csv`)" in report
    assert f"in {unstable} of {len(rows)} bicycle x rider x material combinations" in report
