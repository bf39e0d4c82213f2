"""Benchmark parameter sets as text: YAML, JSON, or the BicycleParameters parameter file.

YAML and JSON hold the 26 Meijaard names (SI, radians), plus ``rider_included: true``
when the rear body B holds a rider, so the output is itself a benchmark parameter
file that bikemass reads back (and refuses to add a second rider to).  The
``bicycleparameters`` format is the ``<Name>Benchmark.txt`` file that the
BicycleParameters package reads from ``bicycles/<Name>/Parameters/``: one
``name = value`` line per parameter, ``#`` comment lines allowed.  Values are
written with ``repr`` (17 significant digits) so they read back bit for bit.
"""

from .output import dumps
from .parameters import NAMES

FORMATS = ("yaml", "json", "bicycleparameters")


def format_parameters(params, fmt, title="", rider_included=False):
    """Text of ``params`` (:class:`~bikemass.parameters.BenchmarkParameters`) in ``fmt``;
    ``rider_included``: the rear body B holds a rider."""
    if fmt in ("yaml", "json"):
        return dumps({**params.to_dict(), **({"rider_included": True} if rider_included else {})}, fmt)
    if fmt == "bicycleparameters":
        return bicycleparameters_text(params, title + (" (rider included in B)" if rider_included else ""))
    raise ValueError(f"format must be one of {', '.join(FORMATS)}, got {fmt!r}")


def bicycleparameters_text(params, title=""):
    """The BicycleParameters ``<Name>Benchmark.txt`` text (no blank lines: its reader rejects them)."""
    values = params.to_dict()
    header = [f"# {line}" for line in (title, "written by bikemass; SI units, radians") if line]
    return "\n".join(header + [f"{name} = {values[name]!r}" for name in NAMES]) + "\n"
