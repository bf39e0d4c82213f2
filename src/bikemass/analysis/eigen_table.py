"""The eigenvalues over speed as text (``bikemass eig``, the web page's ``eigenvalues.csv``): CSV
with every tracked mode's real and imaginary part, or a table with the weave as one mode."""

from ..core.output import csv_text, table

WEAVE = ("weave 1", "weave 2")


def eig_table(modes, csv=False):
    """Eigenvalues at every speed: CSV (every tracked mode's real and imaginary part, full
    precision) or a text table with the weave as one mode (see :func:`weave_cells`)."""
    if csv:
        headers = ["speed"] + [f"{label}_{part}".replace(" ", "_") for label in modes.labels for part in ("re", "im")]
        rows = [[v] + [x for z in row for x in (z.real, z.imag)] for v, row in zip(modes.speeds, modes.eigenvalues)]
        return csv_text(headers, rows)
    others = [label for label in modes.labels if label not in WEAVE]
    headers = ["speed", "weave re", "weave im"] + [f"{label} {part}" for label in others for part in ("re", "im")]
    w = [modes.labels.index(label) for label in WEAVE]
    rows = [[v, *weave_cells(row[w[0]], row[w[1]], name[w[0]] == "weave"),
             *(x for label in others for x in (row[modes.labels.index(label)].real,
                                               row[modes.labels.index(label)].imag))]
            for v, row, name in zip(modes.speeds, modes.eigenvalues, modes.names())]
    return table(headers, rows, floatfmt="{:.6f}")


def weave_cells(a, b, paired):
    """The two weave roots as one mode: ``re``, ``+-im`` while they are a pair; both real
    parts (larger first) and ``real`` while they are two real roots."""
    if paired:
        return a.real, f"+-{abs(a.imag):.6f}"
    hi, lo = sorted((a.real, b.real), reverse=True)
    return f"{hi:.6f}, {lo:.6f}", "real"
