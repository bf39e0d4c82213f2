"""Numbers bikemass prints are the same on every machine where they can be: quantities that are
zero in exact arithmetic are written as 0 below ``output.ZERO``, text tables decide rounding
ties from 12 significant digits (docs/cli.md, "Numbers"); and the same commands print the
same text under two OpenBLAS kernels."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import bikemass
from bikemass.cli.main import main
from bikemass.core.output import (SIGNIFICANT, ZERO, as_shown, as_written, csv_text, dumps, formatted, table,
                                  with_units)
from bikemass.core.results import declared_units
from bikemass.mass.inertia import MassProperties

NOISE = 3e-17
"""Rounding noise of a zero computed from numbers of order 1 (a few units of 2**-53)."""


def test_zero_threshold_applies_to_quantities_of_the_listed_units_only():
    assert as_written(NOISE, "m") == 0.0 and as_written(-NOISE, "kg m^2") == 0.0
    assert str(as_written(-0.0, "m")) == "0.0"                              # no "-0.0"
    assert as_written(2 * ZERO, "m") == 2 * ZERO                            # above: every digit
    assert as_written(0.5 * ZERO * 1e3, "mm") == 0.0 and as_written(2e-9, "mm") == 2e-9   # 1e-12 m = 1e-9 mm
    assert as_written(NOISE, "m/s per Pa") == NOISE and as_written(NOISE, None) == NOISE
    assert as_written(0.1 + 0.2, "m") == 0.1 + 0.2


def test_documents_write_zero_by_their_units_block():
    doc = with_units({"com": np.array([0.33, NOISE, -1.2]), "inertia": np.diag([12.5, 12.7, 2.3]) + NOISE,
                      "weave_speed": {"placement": NOISE}, "d_speed": {"torso.angle": -NOISE}},
                     {**declared_units(MassProperties), "weave_speed": "m/s", "d_speed": "m/s per kg m^2"})
    for fmt, load in (("json", json.loads), ("yaml", __import__("yaml").safe_load)):
        back = load(dumps(doc, fmt))
        assert back["com"] == [0.33, 0.0, -1.2]
        assert back["inertia"][0] == [12.5 + NOISE, 0.0, 0.0]              # off-diagonal noise -> 0
        assert back["weave_speed"]["placement"] == 0.0                     # a key without a unit: its parent's
        assert back["d_speed"]["torso.angle"] == -NOISE                           # a derivative: in full


def test_csv_writes_zero_by_the_unit_in_the_header():
    text = csv_text(["name", "y (m)", "gap (mm)", "d (m/s per Pa)", "n"], [["a", -NOISE, 1e-11, NOISE, 3]])
    assert text.splitlines()[1] == f"a,0.0,0.0,{NOISE!r},3"


def test_text_tables_round_ties_the_same_whatever_the_noise():
    ties = [-1.23625 + d for d in (-2.2e-16, 0.0, 2.2e-16)]                # -1.2362499999999998, ...
    assert len({table(["z"], [[z]], "{:.4f}") for z in ties}) == 1
    assert len({f"{as_shown(x):.3f}" for x in (2.0005 - 4e-16, 2.0005 + 4e-16)}) == 1
    assert as_shown(1 / 3) == float(f"{1 / 3:.{SIGNIFICANT}g}") and str(as_shown(-0.0)) == "0.0"
    assert np.isnan(as_shown(float("nan"))) and as_shown(float("inf")) == float("inf")
    assert [formatted(f, -NOISE) for f in ("{:.4f}", "{:+.3f}", "{:.1f} %")] == ["0.0000", "+0.000", "0.0 %"]
    assert formatted("{:.4f}", -0.5) == "-0.5000" and "-0.0" not in table(["y"], [[-NOISE]], "{:.1f}")


def test_zero_quantities_of_a_symmetric_rider_and_a_chain_pose_print_as_zero(capsys):
    assert main(["rider", "relaxed", "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["com"][1] == 0.0                                             # mirror symmetric: exactly 0
    assert [doc["inertia"][i][j] for i, j in ((0, 1), (1, 0), (1, 2), (2, 1))] == [0.0] * 4
    assert main(["pose", "jamis", "--torso-lean", "30", "--hands", "hoods"]) == 0
    out = capsys.readouterr().out
    assert "largest gap at a joint: 0.0000 mm" in out                       # 1e-14 mm of noise before
    assert "-0.0000" not in out


UPRIGHT = """name: Upright, hands on the bars
body: thesis_rider
segments:
  head:      {location: [0.266, 0.000, -1.919], angle: 5 deg}
  torso:     {location: [0.240, 0.000, -1.625], angle: 5 deg}
  upper_arm: {location: [0.240, 0.238, -1.625], angle: -30 deg, mirror: true}
  lower_arm: {location: [0.395, 0.238, -1.356], angle: -60 deg, mirror: true, frame: front}
  thigh:     {location: [0.153, 0.086, -1.084], angle: -45.220 deg, mirror: true}
  lower_leg: {location: [0.529, 0.086, -0.706], angle: 15.043 deg, mirror: true}
"""
"""The worked example of docs/riders.md: its forearms' CoM z is -1.23625 m in exact arithmetic,
printed to 4 decimals (-1.2362499999999998 with one OpenBLAS kernel, -1.2362500000000003 with
another, on this project's machine)."""


def _printed(tmp_path, coretype=None):
    """Text of three commands in a fresh interpreter with OpenBLAS kernel ``coretype`` (None: the
    kernel OpenBLAS picks for this CPU)."""
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_CORETYPE"}
    env["PYTHONPATH"] = os.pathsep.join([str(Path(bikemass.__file__).resolve().parents[1]),
                                         os.environ.get("PYTHONPATH", "")])
    if coretype:
        env["OPENBLAS_CORETYPE"] = coretype
    code = ("import contextlib, io, json, sys\n"
            "from bikemass.cli.main import main\n"
            "for argv in (['rider', sys.argv[1]], ['pose', 'jamis', '--torso-lean', '30', '--hands', 'hoods'],\n"
            "             ['rider', 'relaxed', '--bike', 'jamis']):\n"
            "    assert main(argv) == 0\n")
    path = tmp_path / "upright.yaml"
    path.write_text(UPRIGHT)
    return subprocess.run([sys.executable, "-c", code, str(path)], capture_output=True, text=True,
                          env=env, check=True, cwd=tmp_path).stdout


@pytest.mark.slow     # two fresh interpreters, each running the analyses (~8 s)
def test_two_openblas_kernels_print_the_same_text(tmp_path):
    """Prescott kernels (SSE3 only, which every x86-64 CPU runs) against the kernel OpenBLAS picks
    for this CPU (Haswell's AVX2, SkylakeX's AVX-512, ...): different rounding in the BLAS, the same
    printed text.  A kernel this CPU lacks is never forced (that would be an illegal instruction);
    where OpenBLAS ignores the setting (not x86) both runs are alike."""
    old, new = _printed(tmp_path, "Prescott"), _printed(tmp_path)
    assert "lower_arm_left" in old and "largest gap at a joint" in old
    assert old == new
