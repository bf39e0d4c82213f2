"""The one dialect every command speaks (docs/cli.md):

* ``-o/--output FILE``: the data output (a file instead of stdout);
* ``--format``: table, csv, json, yaml (where it fits; ``params`` also
  bicycleparameters); default: the ``-o`` file's suffix if it names one, else the
  command's own default;
* ``--plot FILE``: the figure (any format matplotlib writes, with ``--size``, ``--dpi``
  and, where they make sense, ``--xlim``/``--ylim``);
* stdout carries the data only: nothing when ``-o`` took it, nothing when ``--plot`` is
  given without ``--format`` (a figure alone was asked for), nothing with ``--quiet``;
  files are written silently (atomically: never half-written);
* warnings and errors go to stderr, one line each; ``--quiet`` also drops progress bars,
  never warnings or errors;
* JSON and YAML documents carry their units in one top-level ``units`` block
  (:func:`bikemass.core.output.with_units`).

Arguments shared by several commands (BIKE, ``--rider``, ``--combine``, ``--stiffness``,
``--model`` and the members' options, ``--speeds``, ``--method``) are defined here once, and
:func:`scenario` makes the one :class:`~bikemass.scenario.scenario.Scenario` of a command's
arguments.  Only the standard library, :mod:`bikemass.core.choices` and the model family's names
(:mod:`bikemass.models.registry`) are imported, so ``bikemass --help`` stays fast.
"""

import argparse
import sys
from pathlib import Path

from ..core.choices import Combine, Format, Method
from ..core.errors import InputError
from .figure_options import add_figure_options, figure_options, write_figure
from ..core.limits import MAX_SPEEDS
from ..models.registry import BASE, SPECS, model_help, parse_model

TABULAR = (Format.TABLE.value, Format.CSV.value, Format.JSON.value, Format.YAML.value)
"""The formats of every command's data (``params`` adds ``bicycleparameters``)."""

SUFFIX_FORMATS = {".csv": "csv", ".json": "json", ".yaml": "yaml", ".yml": "yaml", ".txt": "table",
                  ".mat": "mat", ".npz": "npz"}
"""An ``-o`` file's suffix -> its format when ``--format`` is not given (``.mat`` and ``.npz`` where the
command writes them: ``state-space``)."""

DEFAULT_SPEEDS = "0:30:0.05"

IMAGE_SUFFIXES = (".png", ".pdf", ".svg", ".svgz", ".eps", ".ps", ".jpg", ".jpeg", ".tif", ".tiff", ".webp")
"""Figure files: named by ``--plot``, never by ``-o``."""


LATE_HELP = "late_help"
"""The attribute of an argparse action that holds the function giving its help (:func:`late_help`)."""


def late_help(action, text):
    """``action``'s help becomes ``text()`` when a help is printed, not when the parser is built
    (``text`` may load the library, which building the parser for ``bikemass --help`` must not;
    :meth:`bikemass.cli.main.Parser.format_help` calls it)."""
    setattr(action, LATE_HELP, text)


def add_output(p, formats=TABULAR, default=Format.TABLE.value, what="the data"):
    """``-o/--output``, ``--format`` and ``--quiet``."""
    p.add_argument("-o", "--output", metavar="FILE",
                   help=f"write {what} to FILE instead of stdout (format from --format, else the suffix: "
                        ".csv, .json, .yaml, else the default)")
    p.add_argument("--format", choices=formats, default=None,
                   help=f"{', '.join(formats)} (default {default}; JSON and YAML carry a units block)")
    add_quiet(p)
    p.set_defaults(default_format=default, format_choices=tuple(formats))


def add_quiet(p):
    p.add_argument("--quiet", action="store_true",
                   help="print no data on stdout and no progress bar (errors and warnings still show)")


def add_plot(p, what, xlim=None, ylim=None, required=False, options=True):
    """``--plot FILE`` and (unless ``options`` is false) the figure options."""
    p.add_argument("--plot", metavar="FILE", required=required,
                   help=f"draw {what} into FILE (.png, .pdf, .svg, ...)")
    if options:
        add_figure_options(p, xlim, ylim)


def add_bike(p, what="shipped bicycle name, bicycle YAML or parameter file"):
    p.add_argument("bike", metavar="BIKE", help=f"{what} (a misspelt name suggests the closest)")


class Once(argparse.Action):
    """Stores an option's value; the option given twice with another value first is an error (the last
    would silently win: ``--tyres a.yaml --tyres b.yaml``)."""

    def __call__(self, parser, namespace, values, option_string=None):
        before = getattr(namespace, self.dest, self.default)
        if before != self.default and before != values:
            raise argparse.ArgumentError(self, f"given twice ({before} and {values}): give it once")
        setattr(namespace, self.dest, values)


def add_rider(p):
    p.add_argument("--rider", metavar="POSE", default="none", action=Once,
                   help="rider pose name or pose YAML file, or 'none' (default none)")


def add_combine(p):
    p.add_argument("--combine", choices=Combine.values(), default=Combine.EXACT.value,
                   help="rider + frame: parallel-axis theorem (exact, default) or the thesis's Eq. 3.6 "
                        "(inertias added without parallel-axis terms; see docs/thesis.md)")


def add_method(p):
    p.add_argument("--method", choices=Method.values(), default=Method.MESH.value,
                   help="mass properties from trimesh meshes (default) or closed-form solids")


def add_stiffness(p, many=False):
    if many:
        p.add_argument("--stiffnesses", metavar="S", default=None,
                       help="comma-separated stiffnesses as for stability --stiffness "
                            "(e.g. infinite,steel,aluminum; default: the bicycle's own)")
        return
    action = p.add_argument("--stiffness", metavar="S", default=None, action=Once,
                            help="rear-frame stiffness: infinite (rigid; the default, unless BIKE is a parameter "
                                 "file carrying its own frame stiffness), a material (steel, titanium, "
                                 "aluminum, carbon, ...: the bicycle's published S if it carries one, else the "
                                 "beam model of its own tube sections in that material) or a YAML file with S: "
                                 "[[..], [..]] in N m/rad")
    late_help(action, lambda: STIFFNESS_HELP.format(materials=materials_or_note()))


STIFFNESS_HELP = (
    "rear-frame stiffness: infinite (rigid; the default, unless BIKE is a parameter file carrying its own "
    "frame stiffness, which is then taken); a material: {materials} (frames/materials.yaml): the "
    "bicycle's published S if it carries one, else the beam models of the bicycle's own tube sections with "
    "that material's properties (a steel bicycle's tubes in carbon fibre are not a carbon frame); or a YAML "
    "file with S: [[..], [..]] in N m/rad. With the flexible member a parameter file written by params "
    "--model flexible carries its own compliances (measured values may be edited in)")


def materials_or_note():
    """:func:`material_list`, or where the shipped data cannot be found (``--help`` works without
    them) a note saying where the materials would come from."""
    try:
        return material_list()
    except InputError:
        return "those of the shipped frames/materials.yaml (not found here: see BIKEMASS_DATA in README.md)"


def material_list():
    """Every material ``--stiffness`` offers, with its names and modulus (frames/materials.yaml)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..mass.materials import load_materials
    table = load_materials()
    by = {}
    for name, m in table.items():
        by.setdefault(m.key, (m, []))[1].append(name)
    return "; ".join(f"{' or '.join(sorted(set(names), key=len))} ({m.name}, E {m.E / 1e9:g} GPa)"
                     for m, names in by.values())


def stiffness_label(stiffness):
    """What a stiffness choice is, for a title (:func:`bikemass.mass.materials.frame_label`)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..mass.materials import frame_label
    return frame_label(stiffness)


def frame_name(args, stiffness=None, rider=None):
    """The frame of a command's scenario in words for a title: ``stiffness`` (default ``--stiffness``) as
    :func:`stiffness_label` names it, or with none given the bicycle's own
    (:meth:`~bikemass.scenario.scenario.Scenario.frame_label`: a parameter file's frame stiffness, else
    rigid)."""
    stiffness = getattr(args, "stiffness", None) if stiffness is None else stiffness
    if stiffness is not None:
        return stiffness_label(stiffness)
    try:
        return scenario(args, rider=rider).frame_label()
    except InputError:
        return stiffness_label(None)


def riderless_label(args):
    """A title's words for a command run without ``--rider``
    (:meth:`~bikemass.scenario.scenario.Scenario.rider_label`: ``"no rider"``, or ``"rider in the
    parameter set"`` for a parameter file whose set holds its rider)."""
    try:
        return scenario(args, rider="none").rider_label()
    except InputError:
        return "no rider"


MODEL_HELP = f"the linear model: {model_help()}; see docs/models.md"


def model_choice(text):
    """``--model``'s value checked (argparse type): the combination's canonical name."""
    try:
        return parse_model(text, "--model").name
    except InputError as exc:
        raise argparse.ArgumentTypeError(exc.expected) from None


def add_model(p):
    """``--model`` and each member's parameter file option (``--tyres``, ``--arms``: the members declare them)."""
    p.add_argument("--model", type=model_choice, default=None, metavar="MODEL", action=Once,
                   help=MODEL_HELP + "; default: the bicycle's own (rider-lean for a MooreRiderLean2012 "
                                     "parameter set), else whipple")
    for spec in SPECS:
        if spec.option:
            p.add_argument(spec.option, dest=spec.keyword, metavar="FILE", help=spec.option_help, action=Once)


def add_control(p):
    """``--control FILE``: a linear feedback scheduled in speed, added to the model's inputs."""
    p.add_argument("--control", metavar="FILE",
                   help="close the loop with a control file: for each input, the signals fed back into it "
                        "(states or outputs by name) and each gain's schedule in speed, e.g. 'steer-torque: "
                        "{roll-rate: {speeds: [0, 1.5, 4.7], gains: [0, 12.5, 0]}}' (gains in SI, linear "
                        "between the speeds, constant outside; u = K(v) y is added to the inputs, so a positive "
                        "roll-rate -> steer-torque gain steers into the fall); docs/stability.md, Closed loops")


def resolve_model(args):
    """``args.model`` made a model's name where ``--model`` was not given: the bicycle's own
    (:func:`~bikemass.scenario.scenario.own_model`: ``rider-lean`` for a MooreRiderLean2012 set), else
    the Whipple bicycle's."""
    if getattr(args, "model", "") is None:
        args.model_given = False                       # (compare --models replaces it: no conflict)
        bike = getattr(args, "bike", None)
        if bike is None:
            args.model = BASE
        else:
            # lazy: the library loads numpy; bikemass --help must not
            from ..scenario.scenario import own_model
            args.model = own_model(bike).name


def scenario(args, rider=None, stiffness=None, bike=None, origin=None):
    """The :class:`~bikemass.scenario.scenario.Scenario` of a command's BIKE, ``--rider``,
    ``--stiffness``, ``--combine``, ``--method``, ``--allow-off-contact``, ``--model``, ``--tyres`` and ``--arms``
    (each where the command has it; ``rider``, ``stiffness`` and ``bike`` replace the options'; errors
    about changed inputs name ``origin``, default BIKE)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario.scenario import Scenario

    members = {}
    for spec in SPECS:                                    # a member's file only with the member
        given = getattr(args, spec.keyword, None) if spec.option else None
        if given and not parse_model(args.model).has(spec.name):
            wanted = parse_model(args.model).with_member(spec.name).name
            raise InputError(spec.option, given, f"a --model with the {spec.name} member (e.g. --model {wanted}); "
                             f"--model {args.model} has no {spec.name} member")
        if given is not None:
            members[spec.keyword] = given
    options = {k: getattr(args, k) for k in ("combine", "method", "allow_off_contact", "model")
               if getattr(args, k, None) is not None}
    if not isinstance(options.get("method"), str) or options["method"] not in Method.values():
        options.pop("method", None)                       # uncertainty's --method is its own
    bike = args.bike if bike is None else bike
    return Scenario(bike, rider or getattr(args, "rider", None), stiffness or getattr(args, "stiffness", None),
                    origin=origin or bike, member_inputs=members, **options)


def bike_name(bike):
    """The name titles give BIKE: the ``name:`` its file declares (a parameter file: the file's
    stem), else BIKE as typed (a file that is not a bicycle, such as a rider-lean parameter set)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario.loading import load_bicycle

    try:
        return load_bicycle(bike).name or str(bike)
    except InputError:
        return str(bike)


def add_speeds(p):
    p.add_argument("--speeds", metavar="START:STOP:STEP", default=DEFAULT_SPEEDS,
                   help=f"speed grid in m/s (default {DEFAULT_SPEEDS}, the thesis's)")


def parse_speeds(text, max_speeds=None, raise_option=None):
    """``"start:stop:step"`` -> speed grid (m/s); InputError if malformed, out of the limits or over
    ``max_speeds`` (:func:`bikemass.analysis.engine.speeds.speed_range`), naming ``raise_option`` (the
    command's ``--max-speeds``) where the command has one."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.engine.speeds import speed_range

    try:
        start, stop, step = (float(x) for x in text.split(":"))
    except ValueError:
        start = stop = step = None                          # speed_range names what is expected
    return speed_range(start, stop, step, max_speeds or MAX_SPEEDS, "--speeds", text, raise_option)


def check_output(args):
    """Before any work: an ``-o`` file that looks like a figure is refused (figures go to --plot)."""
    if getattr(args, "format_choices", None) and args.output and \
            Path(args.output).suffix.lower() in IMAGE_SUFFIXES:
        raise InputError(args.output, "-o", "a data file (table, csv, json, yaml); a figure goes to --plot FILE")


def data_format(args):
    """The format of the data: ``--format``, else the ``-o`` suffix's, else the command's default."""
    if args.format:
        return args.format
    if args.output:
        fmt = SUFFIX_FORMATS.get(Path(args.output).suffix.lower())
        if fmt in args.format_choices:
            return fmt
    return args.default_format


def wants_data(args):
    """Whether the data is written at all (see the module docstring)."""
    if args.output:
        return True
    if args.quiet:
        return False
    return not (getattr(args, "plot", None) and not args.format)


def emit(args, render):
    """Write the data: ``render(fmt)`` -> text, to ``-o`` (atomically) or stdout."""
    if not wants_data(args):
        return
    text = render(data_format(args))
    if args.output:
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import write_atomic
        write_atomic(args.output, text)
    else:
        sys.stdout.write(text)


def write_data(args, text):
    """Write already rendered data: to ``-o`` (atomically) or stdout, unless ``--quiet``."""
    if getattr(args, "output", None):
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import write_atomic
        write_atomic(args.output, text)
    elif not getattr(args, "quiet", False):
        sys.stdout.write(text)


def figure_checked(args):
    """The checked figure options of ``--plot`` (call before the work), or None without a plot."""
    return figure_options(args, args.plot) if getattr(args, "plot", None) else None


def save_plot(args, fig, options):
    """Write the figure to ``--plot``."""
    write_figure(fig, args.plot, options)


def result_document(data, units, fmt):
    """A typed result's plain ``data`` (``to_dict()``) as JSON or YAML text with the ``units`` block its
    fields declare (``units``: ``result.units()``), none guessed from the keys' names."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import dumps
    from ..core.results import with_declared_units
    return dumps(with_declared_units(data, units), fmt)


def document(data, fmt, units=None):
    """``data`` as JSON or YAML text with its ``units`` block: the benchmark parameters' and the
    declared ``units`` (``{key: unit}`` from the types that made ``data``; a typed result
    declares its own, :func:`result_document`), none guessed from a key's name."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import dumps, with_units
    from ..models.parameters import parameter_units
    return dumps(with_units(data, {**parameter_units(), **(units or {})}), fmt)


def csv_text(headers, rows):
    """CSV text (:func:`bikemass.core.output.csv_text`: numbers in full, below ``ZERO`` as 0)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import csv_text as text
    return text(headers, rows)
