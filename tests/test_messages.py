"""Messages a new user meets (issue 35): values shown as typed or as plain numbers (never a numpy
repr), the rule stated as it is checked, a sweep key that cannot vary named with what can, a long
legal output name accepted, the study's sentence about its misses in the right grammatical number,
and one root accuracy stated by README, ``--help`` and the code, measured against 40-digit
arithmetic."""

import re
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

import bikemass as bm
from bikemass.cli.main import build_parser, main
from bikemass.core.errors import short
from bikemass.core.output import new_folder, write_atomic
from bikemass.study.report import misses_sentence

ROOT = Path(__file__).parents[1]


def _error(capsys, argv):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0, err
    return err


def test_numbers_in_messages_are_plain(capsys):
    assert short(np.float64(1e6)) == "1000000.0" and short(np.array([1e6, 2.0])) == "[1000000.0, 2.0]"
    assert short([np.float64(1.5), 2]) == "[1.5, 2]" and short(np.int64(3)) == "3"
    err = _error(capsys, ["handling", "benchmark", "--speeds", "1e6"])
    assert "--speeds: 1e6:" in err and "array" not in err
    with pytest.raises(bm.InputError) as exc:
        bm.handling(bm.parameters("benchmark"), speeds=np.array([1e6]))
    assert "array" not in str(exc.value) and "[1000000.0]" in str(exc.value)


def test_frequencies_state_the_rule_they_check(capsys, tmp_path):
    """``0.1:100:1e3`` is 1000 points, whole: accepted; a fractional N or one out of range gets the
    rule as checked (range of START and STOP, N a whole number within its limits)."""
    out = tmp_path / "b.csv"
    assert main(["bode", "benchmark", "--speed", "5", "--input", "steer-torque", "--output", "roll-angle",
                 "--frequencies", "0.1:100:1e3", "-o", str(out)]) == 0
    assert len(out.read_text().splitlines()) == 1 + 1000
    for bad in ("0.1:100:2.5", "0.1:100:1", "0.1:100:1e7", "100:0.1:10", "0.1:x:10"):
        err = _error(capsys, ["bode", "benchmark", "--speed", "5", "--input", "steer-torque", "--output",
                              "roll-angle", "--frequencies", bad])
        assert f"--frequencies: {bad}: " in err and "a whole number of points, 2 <= N <= 1000000" in err
        assert "1e-09 <= START < STOP <= 1e+09" in err


@pytest.mark.parametrize("key, value", [("model", "[whipple, tyre]"), ("rider", "[relaxed, aero-tuck]"),
                                        ("bike", "[jamis, cargo]"), ("tyres", "[a.yaml]")])
def test_a_key_that_cannot_vary_says_what_can(capsys, tmp_path, key, value):
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"bike: benchmark\nvary:\n  {key}: {value}\n")
    err = _error(capsys, ["sweep", str(spec), "--out", str(tmp_path / "out")])
    assert f"vary.{key}: a key that varies one input: one of the 26 benchmark parameter names" in err
    assert f"{key} is set once for the whole sweep" in err and "plain number" not in err


def test_a_word_for_a_number_in_a_sweep_says_number_or_number_with_unit(capsys, tmp_path):
    spec = tmp_path / "spec.yaml"
    spec.write_text("bike: jamis\nvary:\n  chart.stack: [high, 0.2 m]\n")
    err = _error(capsys, ["sweep", str(spec), "--out", str(tmp_path / "out")])
    assert "vary.chart.stack[0]: a number, or '<number> <unit>'" in err and "'high'" in err


def test_a_long_legal_output_name_is_written(tmp_path):
    """A name of 255 bytes (the file system's limit) is legal: the file, and a folder (the study's
    and the sweep's -o DIR), are written, through temporary names that fit the limit too."""
    name = "r" * 255
    write_atomic(tmp_path / name, b"data")
    assert (tmp_path / name).read_bytes() == b"data"
    folder = tmp_path / ("s" * 250 + "\u00e9\u00e9")             # 254 bytes, two of them two-byte characters
    with new_folder(folder) as tmp:
        (Path(tmp) / "report.md").write_text("ok")
    assert (folder / "report.md").read_text() == "ok"
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted([name, folder.name])   # no temporary left
    spec = tmp_path / "spec.yaml"
    spec.write_text("bike: benchmark\nvary:\n  c: [0.05, 0.08]\n")
    out = tmp_path / ("w" * 255)
    assert main(["sweep", str(spec), "--out", str(out), "--quiet", "--no-figures"]) == 0
    assert len((out / "results.csv").read_text().splitlines()) == 3


def test_a_name_past_the_limit_is_refused_in_one_line(capsys, tmp_path):
    err = _error(capsys, ["params", "benchmark", "-o", str(tmp_path / ("p" * 256 + ".yaml"))])
    assert "File name too long" in err and ".tmp" not in err


@pytest.mark.parametrize("misses, explained, sentence", [
    (0, 0, "No entry missed."),
    (1, 1, "The one miss is explained by X."),
    (1, 0, "The one miss is not explained by X."),
    (2, 2, "All 2 misses are explained by X."),
    (3, 1, "Of the 3 misses, one is explained by X."),
    (3, 0, "Of the 3 misses, none is explained by X."),
    (12, 5, "Of the 12 misses, five are explained by X."),
    (40, 12, "Of the 40 misses, 12 are explained by X.")])
def test_the_misses_sentence_is_grammatical(misses, explained, sentence):
    assert misses_sentence(misses, explained, "X") == sentence


def test_readme_help_and_code_state_one_root_accuracy():
    from bikemass.analysis.engine.crossings import XTOL
    readme = (ROOT / "README.md").read_text()
    help_text = build_parser()._subparsers._group_actions[0].choices["stability"].format_help()
    stated = {float(x) for x in re.findall(r"exact roots \(to (1e-\d+) m/s\)", readme)}
    stated |= {float(x) for x in re.findall(r"roots, to (1e-\d+) m/s", " ".join(help_text.split()))}
    assert stated == {XTOL}


def _exact_speeds(p):
    """Weave and capsize speeds of parameter set ``p`` by mpmath at 40 digits from the characteristic
    quartic det(M s^2 + v C1 s + g K0 + v^2 K2) of the canonical matrices the analysis takes (from the
    generated family's code; tests/test_whipple_generated.py holds them to the hand-written formulas): the capsize speed where
    the constant coefficient vanishes (Newton), the weave speed where the real part of the
    oscillatory root pair nearest the imaginary axis changes sign (bisection to 1e-30 m/s)."""
    from bikemass.models.whipple_generated import whipple_matrices
    mp.mp.dps = 40
    c = whipple_matrices(p)
    M, C1, K0, K2 = (mp.matrix([[mp.mpf(float(x)) for x in row] for row in np.asarray(m)])
                     for m in (c.M, c.C1, c.K0, c.K2))
    g = mp.mpf(float(p.g))

    def det(X, Y):
        return X[0, 0] * Y[1, 1] + Y[0, 0] * X[1, 1] - X[0, 1] * Y[1, 0] - Y[0, 1] * X[1, 0]

    def poly(v):
        A, B, C = M, v * C1, g * K0 + v ** 2 * K2
        return [det(A, A) / 2, det(A, B), det(A, C) + det(B, B) / 2, det(B, C), det(C, C) / 2]

    def weave_real(v):
        roots = [r for r in mp.polyroots(poly(v), maxsteps=200, extraprec=80) if abs(r.imag) > mp.mpf("1e-15")]
        return min((r.real for r in roots), key=abs)

    def weave(near):
        a, b = mp.mpf(near) - mp.mpf("1e-9"), mp.mpf(near) + mp.mpf("1e-9")
        fa = weave_real(a)
        assert fa * weave_real(b) < 0
        for _ in range(70):
            m = (a + b) / 2
            fm = weave_real(m)
            a, b, fa = (m, b, fm) if fm * fa > 0 else (a, m, fa)
        return float((a + b) / 2)

    return weave, lambda near: float(mp.findroot(lambda v: poly(v)[-1], near))


@pytest.mark.parametrize("bike, rider", [("benchmark", None), ("jamis", "relaxed"), ("cargo", "no-hands"),
                                         ("bmc-roadmachine@56", "on-hoods"), ("jamis-thesis", "aerobars-thesis")])
def test_critical_speeds_are_found_to_the_stated_accuracy(bike, rider):
    """Against 40-digit arithmetic on the same matrices, every weave and capsize speed is within
    1e-13 m/s, the accuracy README and --help state (measured: at most 5e-14 m/s)."""
    p = bm.parameters(bike, rider)
    result = bm.stability(p)
    weave, capsize = _exact_speeds(p)
    assert result.weave_speeds and result.capsize_speeds
    for v in result.weave_speeds:
        assert abs(weave(v) - v) <= 1e-13
    for v in result.capsize_speeds:
        assert abs(capsize(v) - v) <= 1e-13


def test_a_whole_number_may_be_written_with_an_exponent(capsys):
    """``--max-speeds 1e4`` is the whole number 10000 (it was refused as 'a whole number'); a
    fraction is refused saying what the option counts."""
    assert main(["eig", "benchmark", "--speeds", "0:2:1", "--max-speeds", "1e4", "--quiet"]) == 0
    err = _error(capsys, ["uncertainty", "benchmark", "--samples", "2.5"])
    assert "--samples: a number of samples, got '2.5'" in err
    err = _error(capsys, ["eig", "benchmark", "--max-speeds", "12.5"])
    assert "a whole number" in err and "12.5" in err


def test_max_speed_has_the_limit_of_every_speed_grid(capsys):
    """``--max-speed`` of sensitivity and uncertainty took up to 1e4 m/s where ``--speeds`` and a spec's
    ``max_speed`` stop at 1000 m/s: one limit, one line."""
    assert main(["sensitivity", "benchmark", "--max-speed", "5000"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--max-speed" in err[0] and "at most 1000" in err[0]
