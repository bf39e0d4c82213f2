"""The ``bikemass`` command line: sub-commands registered from :mod:`bikemass.commands`."""

import argparse
import importlib
import sys
import warnings

from .errors import InputError

COMMAND_MODULES = (
    "bicycle",
    "geometry",
    "rider",
    "frame",
    "stability",
    "pose",
    "study",
    "serve",
)
"""Modules under ``bikemass.commands`` whose ``register(subparsers)`` adds sub-commands."""

EPILOG = """\
Bicycles: a shipped name (bikemass params --help lists them) or a YAML file.
Riders:   a shipped pose name or a pose YAML file; see README.md.
All output is SI in the benchmark frame: x forward, y right, z down, origin at
the rear contact; products of inertia are tensor elements.
"""


def build_parser():
    parser = argparse.ArgumentParser(
        prog="bikemass",
        description="Bicycle + rider geometry (YAML) -> mass properties, benchmark "
                    "parameters, frame stiffness and stability.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(title="commands", metavar="COMMAND", required=True)
    for name in COMMAND_MODULES:
        importlib.import_module(f"bikemass.commands.{name}").register(sub)
    return parser


def show_warning(message, category, filename, lineno, file=None, line=None):
    """Every warning raised while a command runs, as one line on stderr."""
    print(f"bikemass: warning: {message}", file=sys.stderr)


def main(argv=None):
    """Entry point: run one sub-command; bad input -> one line on stderr, exit status 2;
    warnings -> one ``bikemass: warning:`` line each."""
    args = build_parser().parse_args(argv)
    with warnings.catch_warnings():
        warnings.simplefilter("always")
        warnings.showwarning = show_warning
        try:
            return args.run(args) or 0
        except InputError as exc:
            print(f"bikemass: error: {exc}", file=sys.stderr)
            return 2
        except BrokenPipeError:
            return 0


if __name__ == "__main__":
    sys.exit(main())
