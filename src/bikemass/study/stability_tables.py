"""Tables 4-2..4-7 and 5-1..5-3: every entry of a run beside the thesis's, with its match status.

An entry is the first or last speed (m/s) of the single stable run on the
0..30 m/s grid, or that run's length, or "none" (the thesis's "-").  It matches when
it is within one grid step (:data:`TOLERANCE`) of the printed value, or both are none.
"""

from dataclasses import dataclass

from .configurations import BENCHMARK_CONFIGURATION, RIDERS, STIFFNESSES, THESIS_NAMES, Configuration
from .reference import stability_tables
from .tables import Table

TOLERANCE = 0.05
"""m/s: one step of the thesis's speed grid."""

CHAPTER4 = {"T4_2": ("jamis", "strict"), "T4_3": ("jamis", "marginal"),
            "T4_4": ("cargo", "strict"), "T4_5": ("cargo", "marginal"),
            "T4_6": ("cargo-loaded", "strict"), "T4_7": ("cargo-loaded", "marginal")}
"""Chapter-4 table -> (bicycle, criterion); rigid frame, per-mode columns."""
CHAPTER5 = {"T5_1": "jamis", "T5_2": "cargo", "T5_3": "cargo-loaded"}
"""Chapter-5 table -> bicycle; four stiffnesses, overall ranges, strict and marginal."""

CH4_COLUMNS = tuple((f"{mode} {part}", None, mode, part)
                    for mode in ("caster", "weave 1", "weave 2", "capsize") for part in ("start", "stop")) + \
    tuple((part, None, "overall", part) for part in ("start", "stop", "range"))
CH5_COLUMNS = tuple((name, criterion, "overall", part)
                    for criterion, prefix in (("strict", ""), ("marginal", "marginal "))
                    for part, name in ((p, prefix + p) for p in ("start", "stop", "range")))
"""(column name, criterion or None = the table's, mode, part) in the thesis's column order."""


@dataclass(frozen=True)
class Entry:
    """One printed number of a stability table and ours."""

    table: str
    configuration: Configuration
    column: str
    criterion: str
    mode: str
    part: str
    ours: float
    thesis: float
    several: bool = False

    @property
    def match(self):
        if self.several:
            return False
        if self.ours is None or self.thesis is None:
            return self.ours is None and self.thesis is None
        return abs(self.ours - self.thesis) <= TOLERANCE + 1e-9

    @property
    def row(self):
        """The thesis's row label, e.g. ``Steel / Relaxed`` or ``Benchmark``."""
        rider = THESIS_NAMES[self.configuration.rider]
        if self.table.startswith("T5"):
            return f"{THESIS_NAMES[self.configuration.stiffness]} / {rider}"
        return rider


def single_run(ranges, part):
    """``part`` (start|stop|range) of the one stable run in ``ranges``, and whether there were several."""
    if not ranges:
        return None, False
    start, stop = ranges[0]
    value = {"start": start, "stop": stop, "range": round(stop - start, 10)}[part]
    return value, len(ranges) > 1


def _entry(table, configuration, column, criterion, printed, outcome):
    name, _, mode, part = column
    ours, several = single_run(outcome.ranges["grid"][criterion][mode], part)
    return Entry(table, configuration, name, criterion, mode, part, ours, printed, several)


def table_rows():
    """[(table, configuration, criterion or None, printed row)] of every printed row, thesis order."""
    tables = stability_tables()
    rows = []
    for table, (bike, criterion) in CHAPTER4.items():
        for rider_label, printed in tables[table].items():
            c = (BENCHMARK_CONFIGURATION if rider_label == "Benchmark"
                 else Configuration(bike, _name(rider_label, RIDERS), "infinite"))
            rows.append((table, c, criterion, printed))
    for table, bike in CHAPTER5.items():
        for material, block in tables[table].items():
            for rider_label, printed in block.items():
                rows.append((table, Configuration(bike, _name(rider_label, RIDERS),
                                                  _name(material, STIFFNESSES)), None, printed))
    return rows


def _name(label, names):
    return next(n for n in names if THESIS_NAMES[n] == label)


def compare(outcomes):
    """Every :class:`Entry` of the nine tables for a run's ``{configuration: Outcome}``."""
    entries = []
    for table, c, criterion, printed in table_rows():
        columns = CH4_COLUMNS if table.startswith("T4") else CH5_COLUMNS
        if len(printed) != len(columns):
            raise ValueError(f"{table} {c.label}: {len(printed)} printed values, expected {len(columns)}")
        for column, value in zip(columns, printed):
            entries.append(_entry(table, c, column, column[1] or criterion, value, outcomes[c]))
    return entries


def title(table):
    """``Table 4-2: jamis, strict`` style heading of a thesis table."""
    number = table[1:].replace("_", "-")
    if table in CHAPTER4:
        bike, criterion = CHAPTER4[table]
        what = "stable ranges per mode and overall, rigid frame, " + (
            "strict (every Re < 0)" if criterion == "strict" else "including marginal (|lambda| < 2 rad/s)")
    else:
        bike, what = CHAPTER5[table], "overall stable ranges, strict and including marginal, four stiffnesses"
    return f"Table {number}: {bike}, {what}"


def entry_table(table, entries, explanations):
    """:class:`~bikemass.study.tables.Table` (long form) of one thesis table's entries."""
    rows = [[e.row, e.column, e.ours, e.thesis, e.match, explanations.get(e, "")]
            for e in entries if e.table == table]
    return Table(f"table_{table[1:]}", title(table),
                 ("row", "column", "bikemass (m/s)", "thesis (m/s)", "match", "explanation"), rows,
                 formats={2: "{:.2f}", 3: "{:.2f}"})
