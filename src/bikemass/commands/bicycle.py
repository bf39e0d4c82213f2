"""``bikemass params``, ``bikemass draw`` and ``bikemass export``: a bicycle (+ rider) as
benchmark parameters, a side-view drawing, or a 3D model."""

from pathlib import Path

from .figure_options import add_figure_options, figure_options, write_figure
from .sizes import add_size_option, every_size

PARAM_FORMATS = ("yaml", "json", "bicycleparameters")
MODEL_FORMATS = ("glb", "stl", "obj")


def _bicycles():
    from ..paths import available, frames_dir
    return ", ".join(available(frames_dir()))


def register(sub):
    shipped = _bicycles()
    params = sub.add_parser(
        "params", help="benchmark parameters (Meijaard et al. 2007) of a bicycle with a rider",
        description="The 26 benchmark parameters (SI, radians) of BIKE with an optional rider. "
                    f"BIKE: a shipped bicycle ({shipped}), a bicycle YAML file (docs/bicycles.md) "
                    "or a benchmark parameter file (YAML/JSON with the 26 names).")
    _bike_and_rider(params, rider_default="none")
    params.add_argument("--combine", choices=("exact", "thesis"), default="exact",
                        help="rider + frame: parallel-axis theorem (exact, default) or the thesis's "
                             "Eq. 3.6 (inertias added without parallel-axis terms)")
    params.add_argument("--method", choices=("mesh", "exact"), default="mesh",
                        help="mass properties from trimesh meshes (default) or closed-form solids")
    params.add_argument("--format", choices=PARAM_FORMATS, default="yaml",
                        help="yaml (default), json, or the BicycleParameters <Name>Benchmark.txt file")
    params.add_argument("--compare", metavar="BIKE2",
                        help="print a table of every parameter beside BIKE2's (e.g. jamis vs "
                             "jamis-thesis, the published values) with the differences")
    params.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")
    add_size_option(params, "--size", "--bike-size")
    params.set_defaults(run=every_size(run_params))

    draw = sub.add_parser("draw", help="side view: parts, body centres of mass, inertia ellipses",
                          description="Side view (x-z plane) of BIKE with an optional rider: every part's "
                                      "outline, each body's centre of mass and its ellipse of gyration; "
                                      "axes in metres, height up.")
    _bike_and_rider(draw, rider_default="none")
    draw.add_argument("-o", "--output", metavar="FILE", required=True, help="image file (.png, .pdf, .svg)")
    add_figure_options(draw, "x forward, m", "height, m")
    add_size_option(draw, "--bike-size")
    draw.set_defaults(run=every_size(run_draw, many=False))

    export = sub.add_parser("export", help="the assembled 3D model (glb, stl, obj)",
                            description="Write the assembled 3D model of BIKE (+ rider) in the benchmark "
                                        "frame (x forward, y right, z down, metres); lumped bodies appear "
                                        "as their equivalent uniform ellipsoids.")
    _bike_and_rider(export, rider_default="none")
    export.add_argument("-o", "--output", metavar="FILE", required=True,
                        help="model file; the format follows the suffix (.glb, .stl, .obj)")
    add_size_option(export, "--bike-size")
    export.set_defaults(run=every_size(run_export, many=False))


def _bike_and_rider(p, rider_default):
    p.add_argument("bike", metavar="BIKE", help="shipped bicycle name, bicycle YAML or parameter file")
    p.add_argument("--rider", metavar="POSE", default=rider_default,
                   help="rider pose name or pose YAML file, or 'none' (default none); seated on BIKE")
    allow_off_contact_option(p)


def allow_off_contact_option(p):
    """``--allow-off-contact``: use a rider pose as written even off the bicycle's contacts."""
    p.add_argument("--allow-off-contact", action="store_true",
                   help="use the pose as written even where it misses the bicycle's saddle, grips or "
                        "pedals by more than 1 mm (the thesis's riders; each gap is warned about)")


def _seated(args):
    """(bicycle, rider seated on it or None) of BIKE and --rider."""
    from .. import catalog
    bicycle = catalog.load_bicycle(args.bike)
    return bicycle, catalog.seated_rider(bicycle, args.rider, args.allow_off_contact)


def run_params(args):
    from .. import catalog
    from ..exporters import format_parameters
    from ..output import write_atomic

    params = catalog.parameters(args.bike, args.rider, args.combine, args.method, args.allow_off_contact)
    if args.compare:
        reference = catalog.parameters(args.compare, args.rider, args.combine, args.method, args.allow_off_contact)
        text = comparison_table(params, reference, args.bike, args.compare)
    else:
        title = f"{args.bike} with rider {args.rider} (combine {args.combine})"
        included = args.rider not in (None, "none") or catalog.load_bicycle(args.bike).rider_included
        text = format_parameters(params, args.format, title, included)
    if args.output:
        write_atomic(args.output, text)
    else:
        print(text, end="")
    return 0


def comparison_table(params, reference, name, reference_name):
    """Plain-text table: each parameter of ``params`` beside ``reference`` and their difference."""
    from ..output import table
    from ..parameters import DESCRIPTIONS

    ours, theirs = params.to_dict(), reference.to_dict()
    rows = []
    for key, description in DESCRIPTIONS.items():
        a, b = ours[key], theirs[key]
        relative = f"{100 * (a - b) / abs(b):+.1f} %" if b else "-"
        rows.append([key, description, a, b, a - b, relative])
    return table(["parameter", "meaning", name, reference_name, "difference", "relative"], rows,
                 floatfmt="{:.4f}")


def run_draw(args):
    from .. import catalog
    from ..bicycle.drawing import plot_side_view

    options = figure_options(args, args.output)
    bicycle, rider = _seated(args)
    title = bicycle.name + (f" + rider {rider.name}" if rider is not None else "")
    fig = plot_side_view(bicycle, rider, title, options.size, **options.limits())
    if bicycle.chart is not None:
        from ..bicycle.chart_drawing import annotate_chart
        annotate_chart(fig.axes[0], bicycle)
    write_figure(fig, args.output, options)
    return 0


def run_export(args):
    from .. import catalog
    from ..bicycle.scene import build_scene, export_scene
    from ..errors import InputError
    from ..output import write_atomic

    fmt = Path(args.output).suffix.lower().lstrip(".")
    if fmt not in MODEL_FORMATS:
        raise InputError(args.output, "(file)", "a model file name ending in .glb, .stl or .obj")
    bicycle, rider = _seated(args)
    write_atomic(args.output, export_scene(build_scene(bicycle, rider), fmt))
    return 0
