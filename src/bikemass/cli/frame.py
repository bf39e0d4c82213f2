"""``bikemass stiffness`` and ``bikemass modes``: the rear frame's beam model (S and natural frequencies)."""

from ..core.choices import Beam, Procedure, Support
from ..core.errors import InputError
from ..fe.defaults import DEFAULT_ELEMENT_SIZE, MAX_ELEMENTS
from . import dialect
from .options import MAX_MODES, count, number
from .sizes import add_size_option, every_size


def _common(parser):
    dialect.add_bike(parser, "shipped bicycle name or bicycle YAML file")
    action = parser.add_argument("--material", metavar="M", default=None,
                                 help="steel, titanium, aluminum, carbon or a one-material YAML file "
                                      "(default: the frame's own materials); geometry is unchanged")
    dialect.late_help(action, lambda: f"a material: {dialect.materials_or_note()} (frames/materials.yaml; "
                      "sources in docs/fe.md), or a one-material YAML file (default: the frame's own "
                      "materials); the geometry is unchanged: the bicycle's tube sections take its properties")
    parser.add_argument("--beam", choices=Beam.values(), default=Beam.TIMOSHENKO.value,
                        help="beam theory (default timoshenko: shear deformation + rotary inertia)")
    dialect.add_output(parser)


def register(subparsers):
    p = subparsers.add_parser(
        "stiffness", help="equivalent rear-frame stiffness S (roll, steer) at the head tube",
        description="2x2 stiffness S (N m/rad) on roll and steer rotations at the bottom head-tube "
                    "keypoint with the dropouts clamped (beam finite elements of the frame tubes).")
    _common(p)
    p.add_argument("--procedure", choices=Procedure.values(), default=Procedure.CONDENSED.value,
                   help="condensed: consistent Schur complement (default); thesis: Williams (2015) "
                        "Eq. 3.31-3.34 unit rotations; see docs/thesis.md")
    add_size_option(p, "--bike-size")
    p.set_defaults(run=every_size(run_stiffness))

    p = subparsers.add_parser(
        "modes", help="natural frequencies of the rear frame",
        description="Lowest natural frequencies (Hz) of the rear frame's beam model; free-free "
                    "skips the six rigid-body modes.")
    _common(p)
    p.add_argument("--bc", choices=Support.values(), default=Support.FREE.value,
                   help="free, fix-rear (dropouts clamped), fix-head (head tube clamped), fix-both")
    p.add_argument("-n", type=count(what="a number of modes"), default=10, metavar="N",
                   help=f"number of modes (default 10, at most --max-modes = {MAX_MODES})")
    p.add_argument("--element-size", type=number(0, 10, open_low=True, what="an element length in m"),
                   default=DEFAULT_ELEMENT_SIZE, metavar="M",
                   help=f"beam element length in m (default {DEFAULT_ELEMENT_SIZE}; at most "
                        f"--max-elements = {MAX_ELEMENTS} elements in all)")
    p.add_argument("--max-modes", type=count(), default=MAX_MODES, metavar="N",
                   help=f"raise the limit on -n (default {MAX_MODES})")
    p.add_argument("--max-elements", type=count(), default=MAX_ELEMENTS, metavar="N",
                   help=f"raise the limit on the model's beam elements (default {MAX_ELEMENTS})")
    dialect.add_plot(p, "the mode shapes on the frame")
    add_size_option(p, "--bike-size")
    p.set_defaults(run=every_size(run_modes, many=False))


def run_stiffness(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario.frame import frame_stiffness

    S = frame_stiffness(args.bike, args.material, args.procedure, args.beam)

    def render(fmt):
        if fmt in ("json", "yaml"):
            # lazy: the engine loads numpy, as the frame's model has already; S's unit as a result declares it
            from ..analysis.engine.stability import StabilityResult
            return dialect.document({"procedure": args.procedure, "S": S}, fmt,
                                    {"S": StabilityResult.field_units()["stiffness"]})
        rows = [["roll", *S[0]], ["steer", *S[1]]]
        if fmt == "csv":
            return dialect.csv_text(["S (N m/rad)", "roll", "steer"], rows)
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import table
        return f"S (N m/rad), procedure {args.procedure}\n" + table(["", "roll", "steer"], rows, "{:.1f}")
    dialect.emit(args, render)


def run_modes(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario.catalog import load_bicycle
    from ..fe.model import element_count
    from ..scenario.frame import frame_modes, frame_structure

    options = dialect.figure_checked(args)
    if args.n > args.max_modes:
        raise InputError("-n", args.n, f"at most {args.max_modes} modes (raise with --max-modes)")
    bicycle = load_bicycle(args.bike)
    elements = element_count(frame_structure(bicycle), args.element_size)
    if elements > args.max_elements:
        raise InputError("--element-size", args.element_size, f"a model of at most {args.max_elements} "
                         f"elements, got {elements} (raise with --max-elements)")
    modes = frame_modes(bicycle, args.bc, args.n, args.material, args.element_size, args.beam,
                        max_elements=args.max_elements)
    if args.plot:
        # lazy: plots/ load matplotlib; only the figure needs it
        from ..plots.frame_modes import plot_frame_modes
        dialect.save_plot(args, plot_frame_modes(modes, size=options.size), options)

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.document({"support": args.bc, **modes.to_dict()}, fmt, modes.units())
        rows = [[i + 1, f] for i, f in enumerate(modes.frequencies_hz)]
        if fmt == "csv":
            return dialect.csv_text(["mode", "frequency (Hz)"], rows)
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import table
        return f"natural frequencies, {args.bc}\n" + table(["mode", "frequency (Hz)"], rows, "{:.3f}")
    dialect.emit(args, render)
