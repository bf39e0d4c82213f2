"""Williams (2015) Tables 4-2 .. 4-7 and 5-1 .. 5-3 recomputed from the thesis's inputs.

Each table entry (first/last speed of a stable run on the 0..30 m/s, 0.05 grid, its
length, or "-" for none) counts as reproduced when it is within one grid step
(0.05 m/s) of the printed value, or both are "-".  The parameter sets are built as
the thesis did (tests/thesis_sets.py: inertias added without parallel-axis terms).
The one entry that is not reproduced is explained in docs/stability.md.
"""

import pytest

from bikemass.analysis.engine.stability import analyse
from bikemass.models.whipple import whipple_model
from thesis_sets import CHAPTER4, CHAPTER5, TABLES, stiffness, thesis_set

STEP = 0.05
KNOWN_MISSES = {
    # marginal range 4.05..5.35 (1.30) vs printed 4.10..5.30 (1.20): both ends within one step,
    # their difference two steps; the printed trail (0.076 m, +-0.0005) alone moves the ends
    # by about +-0.09 m/s.
    ("T5_2", "Steel", "Relaxed", "marginal range"),
}
CH4_COLUMNS = ("caster start", "caster stop", "weave 1 start", "weave 1 stop", "weave 2 start",
               "weave 2 stop", "capsize start", "capsize stop", "start", "stop", "range")
CH5_COLUMNS = ("start", "stop", "range", "marginal start", "marginal stop", "marginal range")


def _run(ranges):
    """[start, stop, length] of the single stable run on the grid, or three None."""
    assert len(ranges) <= 1, ranges          # the thesis's sets never have two runs
    if not ranges:
        return [None, None, None]
    a, b = ranges[0]
    return [a, b, round(b - a, 10)]


def chapter4_row(st, marginal):
    criterion = "marginal" if marginal else "strict"
    row = []
    for label in ("caster", "weave 1", "weave 2", "capsize"):
        row += _run(st.mode_ranges[label][criterion]["grid"])[:2]
    return row + _run(st.ranges[criterion]["grid"])


def chapter5_row(st):
    return _run(st.ranges["strict"]["grid"]) + _run(st.ranges["marginal"]["grid"])


def same(got, printed):
    if got is None or printed is None:
        return got is None and printed is None
    return abs(got - printed) <= STEP + 1e-9


def compare(key, columns, got, printed):
    return [key + (col,) for col, g, p in zip(columns, got, printed) if not same(g, p)]


@pytest.fixture(scope="module")
def chapter4():
    entries, misses = 0, []
    for table, (bicycle, marginal) in CHAPTER4.items():
        for rider, printed in TABLES[table].items():
            st = analyse(whipple_model(thesis_set(bicycle, rider)))
            entries += len(printed)
            misses += compare((table, rider), CH4_COLUMNS, chapter4_row(st, marginal), printed)
    return entries, misses


@pytest.fixture(scope="module")
def chapter5():
    entries, misses = 0, []
    for table, bicycle in CHAPTER5.items():
        frame = "Jamis" if bicycle == "Jamis" else "Cargo"
        for material, rows in TABLES[table].items():
            S = stiffness(frame, material)
            for rider, printed in rows.items():
                st = analyse(whipple_model(thesis_set(bicycle, rider), S))
                entries += len(printed)
                misses += compare((table, material, rider), CH5_COLUMNS, chapter5_row(st), printed)
    return entries, misses


def test_tables_4_2_to_4_7_all_462_entries_including_per_mode_columns(chapter4):
    entries, misses = chapter4
    assert entries == 462
    assert set(misses) == {m for m in KNOWN_MISSES if m[0].startswith("T4")}


def test_tables_5_1_to_5_3_all_432_entries(chapter5):
    entries, misses = chapter5
    assert entries == 432
    assert set(misses) == {m for m in KNOWN_MISSES if m[0].startswith("T5")}


def test_overall_count(chapter4, chapter5):
    entries = chapter4[0] + chapter5[0]
    reproduced = entries - len(chapter4[1]) - len(chapter5[1])
    assert (reproduced, entries) == (893, 894)
