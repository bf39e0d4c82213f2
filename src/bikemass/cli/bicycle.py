"""``bikemass params``, ``bikemass draw`` and ``bikemass export``: a bicycle (+ rider) as
benchmark parameters, a side-view drawing, or a 3D model."""

import argparse
import re
import textwrap
import warnings
from pathlib import Path

from ..core.choices import PARAMETER_FORMATS
from ..core.errors import BikemassWarning, InputError
from ..core.paths import available, frames_dir
from . import dialect
from .sizes import add_size_option, every_size

MODEL_FORMATS = ("glb", "stl", "obj")


class WholeNames(argparse.HelpFormatter):
    """argparse's help layout, but a line never breaks inside a hyphenated name (``salsa-fargo``)."""

    def _fill_text(self, text, width, indent):
        return textwrap.fill(re.sub(r"\s+", " ", text).strip(), width, initial_indent=indent,
                             subsequent_indent=indent, break_on_hyphens=False)


def _params_description():
    """``params --help``'s description, with the shipped bicycles listed (or why none are)."""
    try:
        shipped = ", ".join(available(frames_dir()))
    except InputError as exc:
        shipped = f"none found: {exc}"
    return ("The 26 benchmark parameters (SI, radians) of BIKE with an optional rider. "
            f"BIKE: a shipped bicycle ({shipped}), a bicycle YAML file (docs/bicycles.md) "
            "or a benchmark parameter file (YAML/JSON with the 26 names, BicycleParameters' <Name>Benchmark.txt) "
            "or measured-data file (BicycleParameters' <Name>Measured.txt: the parameters computed from "
            "the measurements, with standard deviations, which the YAML, JSON, table and csv output keep). "
            "The YAML and JSON "
            "output is itself a parameter file. --format bicycleparameters-yaml writes BicycleParameters' "
            "parameter-set YAML: Meijaard2007, or with --model rider-lean the MooreRiderLean2012 set "
            "(the rider split at the hips), which BicycleParameters and bikemass read back.")


def register(sub):
    params = sub.add_parser(
        "params", help="benchmark parameters (Meijaard et al. 2007) of a bicycle with a rider",
        description=_params_description, formatter_class=WholeNames)
    _bike_and_rider(params)
    dialect.add_combine(params)
    dialect.add_method(params)
    dialect.add_stiffness(params)
    dialect.add_model(params)
    params.add_argument("--compare", metavar="BIKE2",
                        help="every parameter beside BIKE2's (e.g. jamis vs jamis-thesis, the published "
                             "values) with the differences (default format: table)")
    dialect.add_output(params, PARAMETER_FORMATS, "yaml", "the parameters")
    add_size_option(params, "--size", "--bike-size")
    params.set_defaults(run=every_size(run_params))

    draw = sub.add_parser("draw", help="side view: parts, body centres of mass, inertia ellipses",
                          description="Side view (x-z plane) of BIKE with an optional rider: every part's "
                                      "outline, each body's centre of mass and its ellipse of gyration; "
                                      "axes in metres, height up.")
    _bike_and_rider(draw)
    dialect.add_plot(draw, "the side view", "x forward, m", "height, m", required=True)
    dialect.add_quiet(draw)
    add_size_option(draw, "--bike-size")
    draw.set_defaults(run=every_size(run_draw, many=False))

    export = sub.add_parser("export", help="the assembled 3D model (glb, stl, obj)",
                            description="Write the assembled 3D model of BIKE (+ rider) in the benchmark "
                                        "frame (x forward, y right, z down, metres); lumped bodies appear "
                                        "as their equivalent uniform ellipsoids.")
    _bike_and_rider(export)
    export.add_argument("-o", "--output", metavar="FILE", required=True,
                        help="model file; the format follows the suffix (.glb, .stl, .obj)")
    export.add_argument("--up", choices=("z-down", "y"), default="z-down",
                        help="z-down: the benchmark frame as it is (default); y: glTF's frame, as viewers expect "
                             "(y up, the bicycle's forward along +z, its right along -x; a rotation, nothing "
                             "mirrored)")
    dialect.add_quiet(export)
    add_size_option(export, "--bike-size")
    export.set_defaults(run=every_size(run_export, many=False))


def _bike_and_rider(p):
    dialect.add_bike(p)
    dialect.add_rider(p)
    allow_off_contact_option(p)


def allow_off_contact_option(p):
    """``--allow-off-contact``: use a rider pose as written even off the bicycle's contacts."""
    p.add_argument("--allow-off-contact", action="store_true",
                   help="use the pose as written even where it misses the bicycle's saddle, grips or "
                        "pedals by more than 1 mm (the thesis's riders; each gap is warned about)")


def _seated(args):
    """(bicycle, rider seated on it or None) of BIKE and --rider."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario import catalog
    bicycle = catalog.load_bicycle(args.bike)
    return bicycle, catalog.seated_rider(bicycle, args.rider, args.allow_off_contact)


def bicycleparameters_writer(choice):
    """How ``--format bicycleparameters-yaml`` writes the model ``choice``: ``None`` for the Whipple
    bicycle's own set, ``(member, write)`` for a model of one member that writes its own BicycleParameters
    set (its ``bicycleparameters_yaml`` hook), ``False`` for a model BicycleParameters has no set for."""
    if not choice.members:
        return None
    write = choice.specs[0].hook("bicycleparameters_yaml") if len(choice.specs) == 1 else None
    return (choice.specs[0], write) if write is not None else False


def bicycleparameters_models():
    """The ``--model`` values BicycleParameters has a parameter set for (the Whipple bicycle's, and each
    member's that writes one), for a message."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..models.registry import BASE, SPECS
    return " or ".join((BASE, *(s.name for s in SPECS if s.hook("bicycleparameters_yaml") is not None)))


def run_params(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..models.parameter_export import format_parameters

    if args.compare:
        args.default_format = "table"                   # a comparison is read, not read back
    fmt = dialect.data_format(args)
    if args.compare and fmt.startswith("bicycleparameters"):
        raise InputError("--format", fmt, "table, csv, json or yaml with --compare")
    scenario = dialect.scenario(args)
    writer = bicycleparameters_writer(scenario.model)
    if fmt == "bicycleparameters-yaml" and writer is False:
        raise InputError("--format", fmt, f"--model {bicycleparameters_models()}: BicycleParameters has no "
                         f"parameter set for --model {args.model}")
    params = scenario.parameters()
    carried = args.stiffness is None and scenario.frame_label() != dialect.stiffness_label(None)
    richer = args.model != "whipple" or args.stiffness not in (None, "infinite", "rigid") or carried
    if args.compare:
        if richer:
            _only_the_26(f"--compare compares the 26 benchmark parameters and leaves out "
                         f"{_richer(args, scenario)}")
        reference = scenario.replace(bicycle=args.compare).parameters()
        dialect.emit(args, lambda f: comparison(params, reference, args.bike, args.compare, f))
    elif fmt == "bicycleparameters-yaml" and writer is not None:
        spec, write = writer
        typed = scenario.build().members[spec.name]
        dialect.emit(args, lambda f: write(typed))
    else:
        title = f"{dialect.bike_name(args.bike)} with rider {args.rider} (combine {args.combine})"
        included = (args.rider not in (None, "none") or scenario.inputs.lean_set is not None
                    or scenario.inputs.bicycle().rider_included)
        # a measured bicycle's standard deviations belong to its own parameters: not with a rider added
        std = scenario.file_std if args.rider in (None, "none") and args.model == "whipple" else None
        if fmt in ("yaml", "json") and richer:
            # every parameter the model uses, members included: a file every command reads back as it
            # lazy: the library loads numpy; bikemass --help must not
            from ..models.parameter_export import member_document, member_units
            built = scenario.build()
            data = member_document(built.choice, params, built.members, built.stiffness, included, args.stiffness)
            dialect.emit(args, lambda f: dialect.document(data, f, member_units(built.choice)))
        else:
            if richer:
                _only_the_26(f"--format {fmt} holds the 26 benchmark parameters and leaves out "
                             f"{_richer(args, scenario)} (--format yaml or json writes them)")
            dialect.emit(args, lambda f: format_parameters(params, f, title, included, std))
    return 0


def _richer(args, scenario):
    """What a command's scenario has beyond the 26 parameters of the rigid Whipple bicycle, in words."""
    parts = [f"the {args.model} model's own parameters"] if args.model != "whipple" else []
    if scenario.model.name == "whipple" and dialect.frame_name(args) != dialect.stiffness_label(None):
        parts.append("the frame stiffness")
    return " and ".join(parts) or "the model"


def _only_the_26(message):
    """A warning that an output leaves out what the scenario has beyond the 26 parameters."""
    warnings.warn(message, BikemassWarning, stacklevel=2)


def comparison(params, reference, name, reference_name, fmt):
    """Every parameter of ``params`` beside ``reference`` with the difference, in ``fmt``."""
    ours, theirs = params.to_dict(), reference.to_dict()
    if fmt in ("json", "yaml"):
        return dialect.document({name: ours, reference_name: theirs,
                                 "difference": {k: ours[k] - theirs[k] for k in ours}}, fmt)
    if fmt == "csv":
        # lazy: the library loads numpy; bikemass --help must not
        from ..models.parameters import parameter_units
        units = parameter_units()
        return dialect.csv_text(["parameter", "unit", name, reference_name, "difference"],
                                [[k, units[k], ours[k], theirs[k], ours[k] - theirs[k]] for k in ours])
    return comparison_table(params, reference, name, reference_name)


def comparison_table(params, reference, name, reference_name):
    """Plain-text table: each parameter of ``params`` beside ``reference`` and their difference."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table
    from ..models.parameters import DESCRIPTIONS

    ours, theirs = params.to_dict(), reference.to_dict()
    rows = []
    for key, description in DESCRIPTIONS.items():
        a, b = ours[key], theirs[key]
        relative = f"{100 * (a - b) / abs(b):+.1f} %" if b else "-"
        rows.append([key, description, a, b, a - b, relative])
    return table(["parameter", "meaning", name, reference_name, "difference", "relative"], rows,
                 floatfmt="{:.4f}")


def run_draw(args):
    # lazy: plots/ load matplotlib; only the figure needs it
    from ..plots.side_view import plot_side_view

    options = dialect.figure_checked(args)
    bicycle, rider = _seated(args)
    title = bicycle.name + (f" + rider {rider.name}" if rider is not None else "")
    fig = plot_side_view(bicycle, rider, title, options.size, **options.limits())
    if bicycle.chart is not None:
        # lazy: plots/ load matplotlib; only the figure needs it
        from ..plots.chart import annotate_chart
        annotate_chart(fig.axes[0], bicycle)
    dialect.save_plot(args, fig, options)
    return 0


def run_export(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..bicycle.scene import build_scene, export_scene
    from ..core.output import write_atomic

    fmt = Path(args.output).suffix.lower().lstrip(".")
    if fmt not in MODEL_FORMATS:
        raise InputError(args.output, "(file)", "a model file name ending in .glb, .stl or .obj")
    bicycle, rider = _seated(args)
    write_atomic(args.output, export_scene(build_scene(bicycle, rider, args.up), fmt))
    return 0
