"""Argument types and limits of the command line: every number finite and in range, every output
path checked before any work is done.

An ``argparse`` type from :func:`number` refuses ``nan``, ``inf`` and values outside its stated
range with one line.  The work limits below keep an accidental option from exhausting the
machine; each is stated in ``--help`` and raised by an explicit flag.
"""

import argparse
import math
import os

from ..core.errors import InputError, short
from ..core.limits import MAX_SPEED, MAX_SPEEDS, MIN_SPEED_STEP  # noqa: F401 (the limits --help states)

MAX_MODES = 200
"""Most natural frequencies asked for at once (``--max-modes`` raises it)."""


def number(low=-math.inf, high=math.inf, integer=False, open_low=False, what="a number"):
    """An argparse type: a finite float (or int) in [low, high] (``open_low``: above ``low``)."""
    def parse(text):
        try:
            value = _whole(text) if integer else float(text)
        except (ValueError, OverflowError):
            raise argparse.ArgumentTypeError(f"{what}, got {short(text, 40)}") from None
        inside = (value > low if open_low else value >= low) and value <= high
        if not (math.isfinite(value) and inside):
            bounds = f"{'above' if open_low else 'at least'} {low:g}" if math.isfinite(low) else ""
            if math.isfinite(high):
                bounds += (" and " if bounds else "") + f"at most {high:g}"
            raise argparse.ArgumentTypeError(f"{what} (finite{', ' + bounds if bounds else ''}), "
                                             f"got {short(text, 40)}")
        return value
    parse.__name__ = what     # argparse names the type in its messages
    return parse


def _whole(text):
    """``text`` as an int: digits (``1000``) or any number that is whole (``1e3``, ``1000.0``);
    ValueError for a fraction or no number."""
    try:
        return int(text)
    except ValueError:
        value = float(text)
        if not (math.isfinite(value) and value.is_integer()):
            raise ValueError(text) from None
        return int(value)


def whole(what="a whole number"):
    """An argparse type: an int written as digits or as a whole number (``1e3``); the range is
    the library's to check."""
    return number(integer=True, what=what)


def count(low=1, high=10**9, what="a whole number"):
    """An argparse type: an int in [low, high]."""
    return number(low, high, integer=True, what=what)


def jobs(text):
    """``--jobs``: a number of processes >= 1, capped at this machine's CPU count."""
    return min(count(1, what="a number of processes")(text), os.cpu_count() or 1)


def angle(limit):
    """An argparse type: an angle in degrees within [-limit, limit]."""
    return number(-limit, limit, what="an angle in degrees")


OUTPUT_OPTIONS = ("output", "plot", "out", "lane_change")
"""Attributes of parsed arguments that name an output file (a folder where a command says so)."""
FIGURE_OPTIONS = ("plot", "lane_change")
"""Those of them that name a figure file."""


def check_outputs(args):
    """Refuse bad output paths of ``args`` before the command runs (:func:`bikemass.core.output.check_output`):
    folders where files are wanted, unwritable places, and the command's own input files."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import check_folder, check_output, STUDY_MARK

    folders = getattr(args, "folder_outputs", ())
    inputs = [v for key, value in vars(args).items() if key not in OUTPUT_OPTIONS
              for v in (value if isinstance(value, list) else [value]) if isinstance(v, str)]
    for key in OUTPUT_OPTIONS:
        path = getattr(args, key, None)
        if not isinstance(path, str) or not path:
            continue
        option = "-o" if key == "output" else f"--{key.replace('_', '-')}"
        if key in folders:
            check_folder(path, getattr(args, "folder_mark", None) or STUDY_MARK, option=option)
        elif key in FIGURE_OPTIONS:
            _check_figure_name(path, option)
            check_output(path, None, inputs, "a figure file", option)
        else:
            check_output(path, None, inputs, "an output file", option)


def _check_figure_name(path, option):
    # lazy: plots/ load matplotlib; only the figure needs it
    from ..plots.figure import figure_format
    try:
        figure_format(path)
    except ValueError as exc:
        raise InputError(path, option, f"{getattr(exc, 'expected', exc)}, got {short(os.path.basename(path), 30)}") from None
