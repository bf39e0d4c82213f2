"""Issue 35: a speed whose closed loop is unstable (or has no gains) gets no handling level.

The HQM of an unstable closed loop is the magnitude of a response never reached, so it grades
nothing: ``level`` is ``None`` (``null`` in JSON), ``gain_source`` says why, the table says
``unstable`` and the figure draws no point in a Level band at that speed.  These are contract
tests (the grade against the code's own stability verdict); the verdict itself is checked here
against the closed-loop eigenvalues formed from the loop matrices.
"""

import json
import warnings

import numpy as np
import pytest

import bikemass as bm
from bikemass.analysis.handling.rider import loop_system, rider_plant
from bikemass.cli.main import main

PUBLISHED_5 = (46.5457, -0.0522, 12.6611, 0.1849, 0.0959)
"""Moore's benchmark gains at 5 m/s (HumanControl ``BenchmarkSteerGains.txt``)."""


def handled(*args, **kwargs):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        result = bm.handling(*args, **kwargs)
    return result, [str(w.message) for w in caught if issubclass(w.category, bm.BikemassWarning)]


def closed_eigenvalues(p, speed, gains):
    """Eigenvalues of the whole closed loop (every loop closed), from the loop matrices."""
    plant = rider_plant(bm.linear_model(p), speed)
    A, _, _ = loop_system(plant, tuple(gains), 4, (True,) * 5)
    return np.linalg.eigvals(A)


@pytest.mark.parametrize("speeds, gains", [
    ([1.0, 2.0], None),                                              # tuned, unstable (the 2 m/s)
    ([5.0], tuple(-g for g in PUBLISHED_5)),                         # published gains, signs flipped
    ([5.0], (1e300, *PUBLISHED_5[1:])),                              # absurd k_delta
    ([5.0], (1e6, *PUBLISHED_5[1:])),
    ([6.0], (*PUBLISHED_5[:2], -PUBLISHED_5[2], *PUBLISHED_5[3:])),  # one sign flipped
])
def test_an_unstable_closed_loop_gets_no_level(speeds, gains):
    p = bm.parameters("benchmark")
    r, said = handled(p, speeds, gains=gains)
    for k, v in enumerate(r.speeds):
        eig = closed_eigenvalues(p, v, r.gains[k])
        assert not (np.all(np.isfinite(eig)) and eig.real.max() < 0)        # unstable, or not computable
        assert not r.closed_loop_stable[k] and not r.graded[k] and r.levels[k] is None
        assert "closed loop unstable, no handling level" in r.gain_source[k]
        assert any(f"at {v:g} m/s" in s and "no handling level" in s for s in said)
    d = r.to_dict()
    assert d["level"] == [None] * len(speeds)


def test_a_stable_closed_loop_keeps_its_level():
    p = bm.parameters("benchmark")
    r, said = handled(p, [5.0], gains=PUBLISHED_5)
    assert closed_eigenvalues(p, 5.0, PUBLISHED_5).real.max() < 0
    # BMD 2016 (hqmbenchmark.csv): the benchmark's peak at 5 m/s is 4.64 on 100 points; < 5 is Level 1
    assert r.levels == (1,) and r.gain_source == ("given",) and said == []
    assert r.hqm_peak[0] == pytest.approx(4.686, abs=0.01)


def test_the_table_json_and_csv_say_unstable(capsys, tmp_path):
    gains = tmp_path / "g.csv"
    gains.write_text("speed,kDelta,kPhiDot,kPhi,kPsi,kY\n5.0,1e300,-0.0522,12.6611,0.1849,0.0959\n"
                     "6.0,46.5457,-0.0522,12.6611,0.1849,0.0959\n")
    assert main(["handling", "benchmark", "--gains", str(gains)]) == 0
    out, err = capsys.readouterr()
    row5 = next(line for line in out.splitlines() if line.startswith("5.0"))
    assert "unstable" in row5 and "1e+300" in row5 and len(row5) < 200          # no 300-digit integer
    assert "at 5 m/s with the given gains: closed loop unstable" in err
    assert main(["handling", "benchmark", "--speeds", "2,5", "--format", "json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["level"] == [None, 1] and d["gain_source"][0].startswith("tuned: closed loop unstable")
    assert main(["handling", "benchmark", "--speeds", "2", "--format", "csv"]) == 0
    row = capsys.readouterr().out.splitlines()[1].split(",")
    assert row[6] == "False" and row[-1] == ""


def test_the_figure_puts_no_ungraded_speed_in_a_level_band():
    import matplotlib.lines
    r, _ = handled(bm.parameters("benchmark"), [1.0, 2.0, 3.0, 5.0])
    fig = bm.plot_handling(r)
    peaks = fig.axes[1]
    drawn = [(x, y) for line in peaks.get_lines() if isinstance(line, matplotlib.lines.Line2D)
             for x, y in zip(np.atleast_1d(line.get_xdata()), np.atleast_1d(line.get_ydata()))
             if np.isfinite(y) and line.get_linestyle() != "--" and line.get_marker() not in ("None", "")]
    assert {float(x) for x, _ in drawn} == {3.0, 5.0}                     # only the graded speeds as points
    labels = peaks.get_legend_handles_labels()[1]
    assert "closed loop unstable: no level" in labels
    # the dashed markers stand at the unstable speeds and span the axes, not a band
    dashed = [line for line in peaks.get_lines() if line.get_linestyle() == "--"]
    assert sorted(float(line.get_xdata()[0]) for line in dashed) == [1.0, 2.0]
    # the left panel draws only the graded speeds' curves
    assert [line.get_label() for line in fig.axes[0].get_lines()] == ["3 m/s", "5 m/s"]


def test_the_lane_change_leaves_out_unstable_loops(capsys, tmp_path):
    lane = tmp_path / "lane.png"
    assert main(["handling", "benchmark", "--speeds", "2,5", "--lane-change", str(lane), "--dpi", "40"]) == 0
    err = capsys.readouterr().err
    assert lane.is_file() and "not drawn at 2 m/s" in err
    alone = tmp_path / "alone.png"
    assert main(["handling", "benchmark", "--speeds", "2", "--lane-change", str(alone)]) == 0
    assert not alone.exists() and "not written" in capsys.readouterr().err
