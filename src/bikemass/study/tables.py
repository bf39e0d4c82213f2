"""A result table of the study: raw values for CSV, formatted values for the Markdown report."""

from dataclasses import dataclass, field

from ..core.output import csv_text, formatted


@dataclass(frozen=True)
class Table:
    """``key`` (CSV file stem), ``title``, column ``headers``, ``rows`` of raw values.

    ``formats`` maps a column index to a format string for the report (floats
    default to ``{:.3f}``); ``None`` is written as an empty CSV cell and ``-`` in Markdown.
    """

    key: str
    title: str
    headers: tuple
    rows: list
    formats: dict = field(default_factory=dict)
    notes: tuple = ()

    def to_csv(self):
        """CSV text, header line first (:func:`bikemass.core.output.csv_text`: full precision)."""
        return csv_text(self.headers, self.rows)

    def cell(self, column, value):
        if value is None:
            return "-"
        if isinstance(value, bool):
            return "yes" if value else "no"
        if isinstance(value, float):
            return formatted(self.formats.get(column, "{:.3f}"), value)        # no "-0.000"
        return str(value)

    def to_markdown(self):
        """A GitHub-style Markdown table (numbers right-aligned)."""
        numeric = [any(isinstance(r[i], (int, float)) and not isinstance(r[i], bool) for r in self.rows)
                   for i in range(len(self.headers))]
        lines = ["| " + " | ".join(self.headers) + " |",
                 "|" + "|".join("---:" if n else "---" for n in numeric) + "|"]
        lines += ["| " + " | ".join(self.cell(i, v) for i, v in enumerate(row)) + " |" for row in self.rows]
        return "\n".join(lines) + "\n"
