"""The ``bikemass`` command line: sub-commands registered from :mod:`bikemass.cli`."""

import argparse
import importlib
import os
import re
import sys
import warnings

from .. import __version__
from ..core.errors import BikemassWarning, InputError, one_line
from ..core.stopping import Terminated, stop_on_signals
from .dialect import LATE_HELP, check_output, resolve_model
from .options import check_outputs

COMMAND_MODULES = (
    "bicycle",
    "geometry",
    "rider",
    "frame",
    "stability",
    "pose",
    "study",
    "serve",
    "analysis",
    "handling",
    "optimise",
    "nonlinear",
)
"""Modules under ``bikemass.cli`` whose ``register(subparsers)`` adds sub-commands."""

EPILOG = """\
Bicycles: a shipped name (bikemass params --help lists them) or a YAML file.
Riders:   a shipped pose name or a pose YAML file; see README.md.
All output is SI in the benchmark frame: x forward, y right, z down, origin at
the rear contact; products of inertia are tensor elements.
Bad input: one line naming the file, the key and what was expected, exit status 2.
Unusual input (negative trail, a rider far from the bicycle, ...): one warning line
each on stderr (and under "warnings" in JSON output); --strict makes them errors.
Interrupted: exit status 130 (Ctrl-C) or 143 (SIGTERM), no files half-written.
Williams (2015): corrected by default; the thesis's way by name (--as-printed,
--combine thesis, --procedure thesis, --allow-off-contact); why: docs/thesis.md.
"""


class Parser(argparse.ArgumentParser):
    """argparse with its errors on one line (the usage is one ``--help`` away)."""

    def parse_known_args(self, args=None, namespace=None):
        """argparse's, where a value that starts with a minus sign (``--ylim -15:60``,
        ``--speeds -1:5:0.1``) goes to the option before it, as ``--ylim=-15:60`` would."""
        args = sys.argv[1:] if args is None else list(args)
        return super().parse_known_args(_joined_negative_values(self, args), namespace)

    def error(self, message):
        self.exit(2, f"{self.prog}: error: {one_line(message, 600)} (see {self.prog} --help)\n")

    def format_help(self):
        """The help; a description given as a function (one listing shipped files, say) and an
        option's late help (:func:`bikemass.cli.dialect.late_help`) are called only now, so building
        the parser reads no data, loads no library and ``--version`` never depends on them."""
        if callable(self.description):
            self.description = self.description()
        for action in self._actions:
            text = getattr(action, LATE_HELP, None)
            if text is not None:
                action.help = text()
        return super().format_help()


NEGATIVE_VALUE = re.compile(r"-(\d|\.\d|inf\b|nan\b)", re.IGNORECASE)
"""A command-line word that starts like a negative number (argparse would take ``-15:60`` or
``-1e-3,2`` for an unknown option)."""


def _joined_negative_values(parser, args):
    """``args`` with each option that takes one value joined to a following word that starts
    like a negative number (``--ylim -15:60`` -> ``--ylim=-15:60``); words after ``--`` untouched."""
    out, i = [], 0
    while i < len(args):
        word = args[i]
        if word == "--":
            return out + args[i:]
        action = parser._option_string_actions.get(word)
        if (action is not None and action.nargs is None and action.option_strings and word.startswith("--")
                and i + 1 < len(args) and NEGATIVE_VALUE.match(args[i + 1])
                and args[i + 1] not in parser._option_string_actions):
            out.append(f"{word}={args[i + 1]}")
            i += 2
            continue
        out.append(word)
        i += 1
    return out


def build_parser():
    parser = Parser(
        prog="bikemass",
        description="Bicycle + rider geometry (YAML) -> mass properties, benchmark "
                    "parameters, frame stiffness and stability.",
        epilog=EPILOG, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"bikemass {__version__}")
    sub = parser.add_subparsers(title="commands", metavar="COMMAND", required=True)
    for name in COMMAND_MODULES:
        importlib.import_module(f"bikemass.cli.{name}").register(sub)
    for command in sub.choices.values():
        command.add_argument("--strict", action="store_true",
                             help="treat warnings about unusual input as errors (exit status 2)")
    return parser


def main(argv=None):
    """Entry point: run one sub-command and return its exit status; bad input (options included)
    -> one line on stderr, status 2; warnings -> one ``bikemass: warning:`` line each.
    ``--help`` exits (SystemExit 0) as argparse does."""
    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:
        if not exc.code:
            raise
        return exc.code
    with stop_on_signals():
        return _run(args)


BLAS_THREADS = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "OMP_NUM_THREADS")
"""The environment variables that size the BLAS thread pools; the command line sets each to 1 unless it is set."""


def one_blas_thread_for_the_process():
    """Size BLAS's thread pools to one thread for this command's process (and the workers it starts), unless
    the environment says otherwise: bikemass's linear algebra is small (4x4 to a few thousand DOF), where
    a second BLAS thread only spins (measured: ``bikemass stability benchmark`` 0.28 -> 0.22 s of CPU and
    0.34 -> 0.29 s wall on 2 cores). Effective when numpy is not loaded yet, as in a command's own process."""
    for name in BLAS_THREADS:
        os.environ.setdefault(name, "1")


def _run(args):
    one_blas_thread_for_the_process()
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.gate import track_inputs
    from ..core.output import collect_warnings, warning_lines
    status = 0
    with warnings.catch_warnings(record=True) as caught, collect_warnings(caught), track_inputs():
        warnings.simplefilter("always")
        warnings.simplefilter("ignore", DeprecationWarning)
        warnings.simplefilter("ignore", ResourceWarning)    # the interpreter's (garbage collected leftovers), not the input's
        if getattr(args, "strict", False):
            warnings.simplefilter("error", BikemassWarning)
        try:
            check_outputs(args)
            check_output(args)
            resolve_model(args)
            status = args.run(args) or 0
        except InputError as exc:
            return _error(exc)
        except BikemassWarning as exc:
            return _error(f"{exc} (an error under --strict)")
        except KeyboardInterrupt:
            return _error("interrupted", 130)
        except Terminated:
            return _error("terminated", 143)
        except BrokenPipeError:
            return 0
        except MemoryError:
            return _error("out of memory", 1)
        except OSError as exc:             # the system's, not a bug: a full disk, a quota, an I/O error
            return _error(f"{exc.filename or '(system)'}: {exc.strerror or exc} (nothing was half-written)")
        except Exception as exc:           # a bug: one line unless BIKEMASS_DEBUG asks for the traceback
            if os.environ.get("BIKEMASS_DEBUG"):
                raise
            return _error(f"internal error {type(exc).__name__}: {exc} (please report it; set "
                          "BIKEMASS_DEBUG=1 for the traceback)", 1)
    for line in warning_lines(caught):
        print(f"bikemass: warning: {one_line(line, 600)}", file=sys.stderr)
    return status


def _error(message, status=2):
    print(f"bikemass: error: {one_line(message, 900)}", file=sys.stderr)
    return status


if __name__ == "__main__":
    sys.exit(main())
