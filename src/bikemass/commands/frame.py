"""``bikemass stiffness`` and ``bikemass modes``: the rear frame's beam model (S and natural frequencies)."""

import sys

from ..choices import Beam, Procedure, Support
from ..fe.defaults import DEFAULT_ELEMENT_SIZE
from .figure_options import add_figure_options, figure_options, write_figure
from .sizes import add_size_option, every_size


def _common(parser):
    parser.add_argument("bike", metavar="BIKE", help="shipped bicycle name or bicycle YAML file")
    parser.add_argument("--material", metavar="M", default=None,
                        help="steel, titanium, aluminum or a one-material YAML file "
                             "(default: the frame's own materials); geometry is unchanged")
    parser.add_argument("--beam", choices=Beam.values(), default=Beam.TIMOSHENKO.value,
                        help="beam theory (default timoshenko: shear deformation + rotary inertia)")
    parser.add_argument("--format", choices=("table", "json"), default="table")


def register(subparsers):
    p = subparsers.add_parser(
        "stiffness", help="equivalent rear-frame stiffness S (roll, steer) at the head tube",
        description="2x2 stiffness S (N m/rad) on roll and steer rotations at the bottom head-tube "
                    "keypoint with the dropouts clamped (beam finite elements of the frame tubes).")
    _common(p)
    p.add_argument("--procedure", choices=Procedure.values(), default=Procedure.CONDENSED.value,
                   help="condensed: consistent Schur complement (default); thesis: Williams (2015) "
                        "Eq. 3.31-3.34 unit rotations")
    add_size_option(p, "--bike-size")
    p.set_defaults(run=every_size(run_stiffness))

    p = subparsers.add_parser(
        "modes", help="natural frequencies of the rear frame",
        description="Lowest natural frequencies (Hz) of the rear frame's beam model; free-free "
                    "skips the six rigid-body modes.")
    _common(p)
    p.add_argument("--bc", choices=Support.values(), default=Support.FREE.value,
                   help="free, fix-rear (dropouts clamped), fix-head (head tube clamped), fix-both")
    p.add_argument("-n", type=int, default=10, metavar="N", help="number of modes (default 10)")
    p.add_argument("--element-size", type=float, default=DEFAULT_ELEMENT_SIZE, metavar="M",
                   help=f"beam element length in m (default {DEFAULT_ELEMENT_SIZE})")
    p.add_argument("--plot", metavar="FILE", help="draw the mode shapes on the frame (.png, .pdf, .svg)")
    add_figure_options(p)
    add_size_option(p, "--bike-size")
    p.set_defaults(run=every_size(run_modes, many=False))


def run_stiffness(args):
    from ..frame import frame_stiffness
    from ..output import dumps, table

    S = frame_stiffness(args.bike, args.material, args.procedure, args.beam)
    if args.format == "json":
        sys.stdout.write(dumps({"S": S, "units": "N m/rad"}, "json"))
        return
    sys.stdout.write(f"S (N m/rad), procedure {args.procedure}\n")
    sys.stdout.write(table(["", "roll", "steer"], [["roll", *S[0]], ["steer", *S[1]]], "{:.1f}"))


def run_modes(args):
    from ..errors import InputError
    from ..frame import frame_modes
    from ..output import dumps, table

    options = figure_options(args, args.plot)
    if args.n < 1:
        raise InputError("-n", "(option)", "a positive number of modes")
    if not args.element_size > 0:
        raise InputError("--element-size", "(option)", "a positive element length in m")
    modes = frame_modes(args.bike, args.bc, args.n, args.material, args.element_size, args.beam)
    if args.plot:
        from ..fe.plot import plot_frame_modes
        write_figure(plot_frame_modes(modes, size=options.size), args.plot, options)
    if args.format == "json":
        sys.stdout.write(dumps(modes.to_dict(), "json"))
        return
    sys.stdout.write(f"natural frequencies, {args.bc}\n")
    rows = [[i + 1, f] for i, f in enumerate(modes.frequencies_hz)]
    sys.stdout.write(table(["mode", "frequency (Hz)"], rows, "{:.3f}"))
