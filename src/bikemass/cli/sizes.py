"""Size runs on the command line: pick one size (``BIKE@SIZE`` or an option) or run every size.

:func:`every_size` wraps a command's ``run(args)``: for a size-run BIKE without a size it
runs once per size and joins the outputs, JSON/YAML as one object keyed by size, text
under a ``size NAME`` heading each.
"""

import contextlib
import io
from copy import copy

from ..core.errors import InputError
from .dialect import data_format, document

DATA_FORMATS = ("json", "yaml")


def add_size_option(parser, *flags):
    """Add the size option (``flags``, e.g. ``--size``/``--bike-size``) to ``parser``."""
    parser.add_argument(*flags, dest="bike_size", metavar="SIZE",
                        help="size of a size-run bicycle file (default: every size; same as BIKE@SIZE)")


def every_size(run, many=True):
    """``run`` for one bicycle, or once per size of a size run with the outputs joined
    (``many=False``: the size must be picked)."""
    def wrapped(args):
        # lazy: the library loads numpy; bikemass --help must not
        from ..bicycle.loader import bicycle_sizes
        from ..core.output import write_atomic

        if args.bike_size is not None:
            args.bike = f"{args.bike}@{args.bike_size}"
            return run(args)
        sizes = bicycle_sizes(args.bike) if many else ()
        if not sizes:
            return run(args)
        fmt = data_format(args) if hasattr(args, "format_choices") else "table"
        if getattr(args, "plot", None) or getattr(args, "compare", None) or fmt not in DATA_FORMATS + ("table",):
            raise InputError(args.bike, "sizes", f"one size (BIKE@SIZE or --bike-size) for this output: "
                                                 f"one of {', '.join(sizes)}")
        outputs = {}
        for size in sizes:
            one = copy(args)
            one.bike, one.output, one.format, one.quiet = f"{args.bike}@{size}", None, fmt, False
            buffer = io.StringIO()
            with contextlib.redirect_stdout(buffer):
                run(one)
            outputs[size] = buffer.getvalue()
        if fmt in DATA_FORMATS:
            # lazy: json and yaml stay out of bikemass --help (this module is loaded to build it)
            import json
            import yaml
            load = json.loads if fmt == "json" else yaml.safe_load
            documents = {size: load(out) for size, out in outputs.items()}
            declared = {k: u for d in documents.values() for k, u in d.get("units", {}).items()}
            text = document({size: {k: v for k, v in d.items() if k != "units"} for size, d in documents.items()},
                            fmt, declared)
        else:
            text = "\n".join(f"size {size}\n{out}" for size, out in outputs.items())
        if getattr(args, "output", None):
            write_atomic(args.output, text)
        elif not getattr(args, "quiet", False):
            print(text, end="")
        return 0
    return wrapped
