"""bikemass's models against measured bicycles (docs/validation-measured.md).

The references are measurements, not models: the weave eigenvalues Kooijman, Schwab & Meijaard
(2008) fitted to the roll rate of their riderless instrumented bicycle (Fig. 7, digitised from the
paper's vector drawing, and the one eigenvalue the text prints), and those Haitjema (2023) fitted on
the TU Delft balance-assist bicycle (Tables 3-5 of his note), all in ``reference/measured_weave.yaml``;
the bicycles' parameters are the shipped ``kooijman2008`` (the paper's Table 1) and
``gazelle-balance-assist`` (BicycleParameters' raw measurements of the same bicycle).

Each tolerance is the measurement's own scatter, computed here from the measured values alone:

* Kooijman et al. give no error bars on the eigenvalues (the bars are the speed range of a run):
  the scatter is the standard deviation of the 26 measured real (imaginary) parts about a quadratic
  in speed (residual sum of squares over n - 3): 0.121 (0.115) 1/s.  A run agrees with the model
  when its value lies within 3 of those of the model's values over the run's own speed range.
* The balance-assist note gives the mean of three perturbations per speed; at 5.0 m/s the steering
  law gives no torque, so its three gain settings are three repeats of the uncontrolled bicycle:
  their standard deviation (0.58 1/s of the imaginary part) is the scatter.

Where a model misses, the test holds the miss as documented: larger than the scatter, in the
stated direction; the model's own output is never the reference.  The printed model values of
Kooijman et al. (their Eq. 5 matrices, their weave and capsize speeds) are checked to the printed
digits: a check of the transcription and of the code, not of the model.
"""

from pathlib import Path

import numpy as np
import pytest
import yaml

import bikemass as bm

ROOT = Path(__file__).parents[1]
REFERENCE = yaml.safe_load((ROOT / "reference" / "measured_weave.yaml").read_text())
KSM = REFERENCE["kooijman2008"]
ASSIST = REFERENCE["balance_assist"]
RUNS = np.array(KSM["weave"])                       # v_low, v_high, re, im per run
MID = RUNS[:, :2].mean(axis=1)


def weave(params, speeds, **kwargs):
    """The weave eigenvalue at each speed (1/s): the oscillating root of lowest frequency, taken with
    positive imaginary part (the tyre member's tyre modes oscillate at 35-60 1/s).  Picked by value,
    not by label: with the steering law closed in, the mode followed across speed from standstill
    carries another label below 5 m/s."""
    modes = bm.eigenvalues(params, speeds=np.asarray(speeds, dtype=float), **kwargs)
    out = []
    for row in np.asarray(modes.eigenvalues):
        oscillating = row[row.imag > 1e-6]
        out.append(oscillating[np.argmin(oscillating.imag)])
    return np.array(out)


def scatter(values):
    """Standard deviation of measured values about a quadratic in speed (n - 3 degrees of freedom)."""
    residual = values - np.polyval(np.polyfit(MID, values, 2), MID)
    return float(np.sqrt(residual @ residual / (len(values) - 3)))


SIGMA_RE, SIGMA_IM = scatter(RUNS[:, 2]), scatter(RUNS[:, 3])


def canonical_weave(m, speed, roll_rate_gain=0.0, steer_inertia=0.0, steer_damping=0.0):
    """Weave of ``M q'' + (v C1 - K_c + D) q' + (g K0 + v^2 K2) q = 0`` by numpy alone: ``K_c`` feeds
    the roll rate into the steer torque, ``steer_inertia`` (kg m^2) is added to ``M[1, 1]`` and
    ``steer_damping`` (N m s/rad) to the steer rate's ``D[1, 1]`` (an independent closed loop)."""
    M = np.array(m.M, dtype=float)
    M[1, 1] += steer_inertia
    C = speed * np.array(m.C1, dtype=float)
    C[1, 0] -= roll_rate_gain
    C[1, 1] += steer_damping
    K = m.g * np.array(m.K0, dtype=float) + speed ** 2 * np.array(m.K2, dtype=float)
    A = np.block([[np.zeros((2, 2)), np.eye(2)], [-np.linalg.solve(M, K), -np.linalg.solve(M, C)]])
    roots = np.linalg.eigvals(A)
    oscillating = roots[roots.imag > 1e-6]
    return oscillating[np.argmin(oscillating.imag)]


def assist_law(setting):
    """The note's steering law T = k (5.0 - v) roll rate below 5.0 m/s as a bikemass control mapping."""
    return {"steer-torque": {"roll-rate": {"speeds": [0.0, 5.0], "gains": [5.0 * setting, 0.0]}}}


# --- Kooijman et al. (2008): the paper's own printed model values --------------------------------

def test_kooijman2008_matrices_equal_the_printed_eq5():
    """Table 1 as shipped gives the paper's M, C1, K0 (with g), K2 to the printed five decimals."""
    m = bm.matrices(bm.parameters("kooijman2008"))
    printed = KSM["printed"]["matrices"]
    half_unit = 0.5e-5 + 1e-12
    np.testing.assert_allclose(m.M, printed["M"], rtol=0, atol=half_unit)
    np.testing.assert_allclose(m.C1, printed["C1"], rtol=0, atol=half_unit)
    np.testing.assert_allclose(m.g * np.asarray(m.K0), printed["K0"], rtol=0, atol=half_unit)
    np.testing.assert_allclose(m.K2, printed["K2"], rtol=0, atol=half_unit)


def test_kooijman2008_critical_speeds_equal_the_printed():
    """Weave and capsize speeds: printed "approximately 4.0" and "7.9" m/s (half a unit: 0.05)."""
    r = bm.stability(bm.parameters("kooijman2008"))
    assert r.weave_speeds[0] == pytest.approx(KSM["printed"]["weave_speed"], abs=0.05)
    assert r.capsize_speeds[0] == pytest.approx(KSM["printed"]["capsize_speed"], abs=0.05)


def test_kooijman2008_digitised_run_52_equals_the_printed():
    """The digitised Fig. 7 holds run 52 as the text prints it (-1.16 +- 5.44i 1/s over 4.8..5.4 m/s):
    the digitisation's check, to the printed two decimals.  The printed speeds (5.4 to 4.8 m/s) are
    the measured speed's fall, the bar its linear regression over the fitted window (4.79..5.34 m/s):
    they agree to 0.1 m/s."""
    run = KSM["printed"]["run_52"]
    row = RUNS[np.argmin(np.abs(RUNS[:, 3] - run["im"]))]
    assert row[2] == pytest.approx(run["re"], abs=0.005)
    assert row[3] == pytest.approx(run["im"], abs=0.005)
    assert row[:2] == pytest.approx([run["v_low"], run["v_high"]], abs=0.1)


# --- Kooijman et al. (2008): the Whipple model against the measured weave -------------------------

def test_kooijman2008_scatter_of_the_measurements():
    """The tolerance the model is held to: about 0.12 1/s on both parts (stated in the docs)."""
    assert SIGMA_RE == pytest.approx(0.121, abs=0.0005)
    assert SIGMA_IM == pytest.approx(0.115, abs=0.0005)


def test_kooijman2008_whipple_agrees_from_the_weave_speed_up():
    """The 10 runs centred at or above 4.0 m/s (3.9..5.3 m/s): each measured real and imaginary part
    within 3 sigma of the Whipple model's values over that run's own speed range."""
    p = bm.parameters("kooijman2008")
    runs = RUNS[MID >= 4.0]
    assert len(runs) == 10
    for v_low, v_high, re, im in runs:
        model = weave(p, np.linspace(v_low, v_high, 21))
        assert model.real.min() - 3 * SIGMA_RE <= re <= model.real.max() + 3 * SIGMA_RE, (v_low, v_high)
        assert model.imag.min() - 3 * SIGMA_IM <= im <= model.imag.max() + 3 * SIGMA_IM, (v_low, v_high)


def test_kooijman2008_whipple_underestimates_the_damping_below_the_weave_speed():
    """The documented miss: the 16 runs centred below 4.0 m/s (3.1..3.9 m/s) are more damped than the
    Whipple model says, by 0.24 1/s on average (more than 3 standard errors of that mean), with
    frequencies 0.23 1/s below the model's (the docs' table)."""
    p = bm.parameters("kooijman2008")
    below = MID < 4.0
    assert below.sum() == 16
    model = weave(p, np.sort(MID[below]))[np.argsort(np.argsort(MID[below]))]
    d_re = RUNS[below, 2] - model.real
    d_im = RUNS[below, 3] - model.imag
    standard_error_re = SIGMA_RE / np.sqrt(below.sum())
    standard_error_im = SIGMA_IM / np.sqrt(below.sum())
    assert d_re.mean() < -3 * standard_error_re
    assert d_im.mean() < -3 * standard_error_im
    assert d_re.mean() == pytest.approx(-0.24, abs=0.005)     # the docs' numbers, to their printed digits
    assert d_im.mean() == pytest.approx(-0.23, abs=0.005)


def test_kooijman2008_standstill_growth_rate():
    """At standstill the Whipple model has two growing roots, 3.67 and 4.05 1/s; the measured growth
    (3.59 and 3.71 1/s, two runs) lies within 0.12 1/s (the scatter) of the slower one."""
    roots = np.sort(np.asarray(bm.eigenvalues(bm.parameters("kooijman2008"), speeds=[0.0]).eigenvalues[0]).real)
    measured = np.asarray(KSM["standstill"])
    assert np.all(np.abs(measured - roots[-2]) < SIGMA_RE)


# --- The balance-assist bicycle: the Whipple model misses the weave frequency ---------------------

def assist_rows():
    speeds = np.asarray(ASSIST["speeds"])
    return speeds, {int(k): np.asarray(v) for k, v in ASSIST["gains"].items()}


def test_balance_assist_shipped_equals_bicycleparameters_raw_file():
    """frames/gazelle_balance_assist.yaml is BicycleParameters' Balanceassistv1Measured.txt: the same
    26 parameters and standard deviations (1e-12 relative)."""
    raw = ROOT / "tests" / "data" / "bicycleparameters" / "measured" / "Balanceassistv1Measured.txt"
    a, b = bm.load_measured("gazelle-balance-assist"), bm.load_measured(raw)
    for name, value in b.parameters.to_dict().items():
        assert a.parameters.to_dict()[name] == pytest.approx(value, rel=1e-12, abs=1e-15), name
        assert a.std[name] == pytest.approx(b.std[name], rel=1e-12, abs=1e-15), name


def test_balance_assist_closed_loop_equals_an_independent_computation():
    """bikemass's --control closed loop of the note's law equals numpy's eigenvalues of the canonical
    matrices with the roll-rate feedback written in by hand (1e-9 1/s), at every measured speed."""
    p = bm.parameters("gazelle-balance-assist")
    m = bm.matrices(p)
    speeds, _ = assist_rows()
    for setting in (6, 8, 10):
        got = weave(p, speeds, control=assist_law(setting))
        for v, w in zip(speeds, got):
            expected = canonical_weave(m, v, roll_rate_gain=setting * max(5.0 - v, 0.0))
            assert abs(w - expected) < 1e-9, (setting, v)


def test_balance_assist_whipple_overpredicts_the_weave_frequency_at_5_m_s():
    """At 5.0 m/s (no steering torque) the measured weave frequency is 4.72 +- 0.58 1/s (three
    repeats); the Whipple model of the measured parameters says 7.40 1/s: an over-prediction of more
    than 3 repeat standard deviations (1.75 1/s) and more than 40 % (docs: +2.68 1/s, +57 %)."""
    speeds, rows = assist_rows()
    at5 = np.array([rows[k][-1, 1] for k in (6, 8, 10)])
    assert speeds[-1] == 5.0
    mean, sd = at5.mean(), at5.std(ddof=1)
    model = weave(bm.parameters("gazelle-balance-assist"), [5.0])[0].imag
    assert model - mean > 3 * sd
    assert model / mean > 1.4


def test_balance_assist_overpredicted_at_every_speed_and_gain():
    """With the note's steering law closed in (bikemass's control member), the model's weave frequency
    is above the measured one at all 21 points by more than 3 repeat standard deviations."""
    speeds, rows = assist_rows()
    sd = np.array([rows[k][-1, 1] for k in (6, 8, 10)]).std(ddof=1)
    p = bm.parameters("gazelle-balance-assist")
    for setting, measured in rows.items():
        model = weave(p, speeds, control=assist_law(setting))
        assert np.all(model.imag - measured[:, 1] > 3 * sd), setting


def test_balance_assist_tyre_member_does_not_narrow_the_miss():
    """The tyre member (Dressel 2013's measured tyres) still over-predicts at 5.0 m/s by more than
    3 repeat standard deviations: of bikemass's members for a riderless bicycle, none narrows it."""
    _, rows = assist_rows()
    at5 = np.array([rows[k][-1, 1] for k in (6, 8, 10)])
    model = weave(bm.parameters("gazelle-balance-assist"), [5.0], model="tyre")[0].imag
    assert model - at5.mean() > 3 * at5.std(ddof=1)


def test_balance_assist_steer_inertia_and_damping_would_narrow_the_miss():
    """The docs' diagnosis (numpy's eigenvalues of bikemass's canonical matrices, the note's law closed
    in): more steer inertia alone (0.29 kg m^2 on M[1,1] = 0.194 kg m^2) brings the 21 points' RMS
    frequency miss from 4.81 to below 1 1/s but the real parts' from 0.80 to above 1.5 1/s (the
    uncontrolled weave at 5.0 m/s turns unstable); 0.20 kg m^2 with 1.33 N m s/rad of steer damping
    (what a geared steering motor's rotor and drag would add) brings both below the uncorrected ones:
    frequency below 1, real part below 0.5 1/s."""
    speeds, rows = assist_rows()
    m = bm.matrices(bm.parameters("gazelle-balance-assist"))

    def rms(inertia, damping):
        miss = np.array([canonical_weave(m, v, s * max(5.0 - v, 0.0), inertia, damping) - complex(*row)
                         for s, measured in rows.items() for v, row in zip(speeds, measured)])
        return float(np.sqrt(np.mean(miss.real ** 2))), float(np.sqrt(np.mean(miss.imag ** 2)))

    plain_re, plain_im = rms(0.0, 0.0)
    assert plain_im > 4.0 and plain_re < 1.0
    inertia_re, inertia_im = rms(0.29, 0.0)
    assert inertia_im < 1.0 and inertia_re > 1.5
    both_re, both_im = rms(0.20, 1.33)
    assert both_im < 1.0 and both_re < 0.5
