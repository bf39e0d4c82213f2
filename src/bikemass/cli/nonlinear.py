"""``bikemass turn``: steady turns of the nonlinear Whipple bicycle (docs/nonlinear.md)."""

from . import dialect
from .bicycle import allow_off_contact_option
from .options import number
from .sizes import add_size_option, every_size

SPEED = number(0, 1000, open_low=True, what="a forward speed in m/s")
DEFAULT_STEERS = "0.01:1.2:60"


def register(sub):
    p = sub.add_parser(
        "turn", help="steady turns of the nonlinear bicycle: lean, steer and steer torque on a circle",
        description="The nonlinear Whipple bicycle's steady turn at --speed on a circle of --radius (of the "
                    "rear contact; negative turns left) or at --steer: the lean, steer, pitch and the rider's "
                    "steer torque, beside the linear model's for the same circle.  --hands-free instead lists "
                    "the circles that need no steer torque, one per steer angle (their speed, lean, radius), "
                    "a family that starts at the linear capsize speed.")
    dialect.add_bike(p)
    dialect.add_rider(p)
    allow_off_contact_option(p)
    dialect.add_combine(p)
    add_size_option(p, "--bike-size")
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--radius", type=float, metavar="R", help="radius of the rear contact's circle, m")
    which.add_argument("--steer", type=float, metavar="DELTA", help="steer angle, rad")
    which.add_argument("--hands-free", action="store_true",
                       help="the hands-free circles over steer angle (see --steers) instead of one turn")
    p.add_argument("--speed", type=SPEED, metavar="V", help="forward speed, m/s (with --radius or --steer)")
    p.add_argument("--steers", metavar="START:STOP:N", default=DEFAULT_STEERS,
                   help=f"steer angles of --hands-free: N from START to STOP rad (default {DEFAULT_STEERS})")
    dialect.add_output(p, what="the turn or the family")
    dialect.add_plot(p, "the hands-free family (speed and lean against steer angle)")
    p.set_defaults(run=every_size(run_turn))


def _steers(text):
    # lazy: the library loads numpy; bikemass --help must not
    import numpy as np

    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError
    try:
        start, stop, count = text.split(":")
        start, stop, count = float(start), float(stop), int(count)
    except ValueError:
        raise InputError("--steers", text, "START:STOP:N, e.g. 0.01:1.2:60") from None
    if not 1 <= count <= 10_000:
        raise InputError("--steers", text, "N from 1 to 10000")
    return np.linspace(start, stop, count)


def run_turn(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.nonlinear.turn import hands_free_turns, steady_turn
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.errors import InputError

    options = dialect.figure_checked(args)
    scenario = dialect.scenario(args)
    if scenario.model.members:          # a parameter set of another model (a MooreRiderLean2012 file)
        raise InputError(args.bike, f"model {scenario.model.name}", "a bicycle of the Whipple model: the steady "
                         "turns are the nonlinear Whipple bicycle's")
    built = scenario.build()
    if built.stiffness is not None:     # --stiffness, or the file's own frame_stiffness block
        raise InputError(args.bike, "frame stiffness", "a rigid frame: the steady turns are the nonlinear Whipple "
                         "bicycle's (--stiffness infinite, and no frame_stiffness block in the file)")
    parameters = built.parameters
    if args.hands_free:
        if args.speed is not None:                 # the family's speeds are what it finds: nothing to ignore silently
            raise InputError("--speed", args.speed, "no speed with --hands-free (each circle's speed is its result; "
                             "--speed goes with --radius or --steer)")
        result = hands_free_turns(parameters, _steers(args.steers))
        headers = ["steer (rad)", "speed (m/s)", "roll (rad)", "radius (m)", "pitch (rad)"]
        rows = [list(r) for r in zip(result.steer.tolist(), result.speed.tolist(), result.roll.tolist(),
                                     result.radius.tolist(), result.pitch.tolist())]
        caption = f"hands-free circles; linear capsize speed {result.capsize_speed:.6g} m/s\n"
    else:
        if args.speed is None:
            raise InputError("--speed", "(missing)", "a forward speed in m/s with --radius or --steer")
        if args.plot:
            raise InputError("--plot", args.plot, "--hands-free: a single turn has no figure")
        try:
            result = steady_turn(parameters, args.speed, radius=args.radius, steer=args.steer)
        except InputError as exc:
            raise InputError(f"--{exc.source}" if exc.source in ("radius", "steer") else exc.source, exc.key,
                             exc.expected) from None
        headers = ["quantity", "nonlinear", "linear", "unit"]
        rows = [["speed", result.speed, result.speed, "m/s"], ["radius", result.radius, result.radius, "m"],
                ["roll", result.roll, result.linear_roll, "rad"], ["steer", result.steer, result.linear_steer, "rad"],
                ["steer torque", result.steer_torque, result.linear_steer_torque, "N m"],
                ["pitch", result.pitch, None, "rad"], ["yaw rate", result.yaw_rate, result.yaw_rate, "rad/s"]]
        caption = ""

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document(result.to_dict(), result.unit_block(), fmt)
        if fmt == "csv":
            return dialect.csv_text(headers, rows)
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import table
        return caption + table(headers, rows, floatfmt="{:.6g}")
    dialect.emit(args, render)
    if args.plot:
        # lazy: matplotlib only for a figure
        from ..analysis.nonlinear.figures import plot_hands_free_turns
        dialect.save_plot(args, plot_hands_free_turns(result, f"{args.bike}: hands-free circles", options.size),
                          options)
    return 0
