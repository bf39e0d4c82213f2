"""``bikemass eig`` and ``bikemass stability``: eigenvalues over speed, critical speeds, stable ranges."""

from .figure_options import add_figure_options, figure_options, write_figure
from .sizes import add_size_option, every_size

EIG_FORMATS = ("table", "csv", "json")
SPEED_LIMIT = "speed, m/s"
STABILITY_FORMATS = ("table", "json")


def register(sub):
    from ..options import number

    eig = sub.add_parser(
        "eig", help="eigenvalues of the labelled modes (weave, capsize, caster) against speed",
        description="Eigenvalues of the linearised Whipple bicycle (Meijaard et al. 2007) at every "
                    "speed, each followed across speed and labelled weave 1, weave 2, capsize, caster.")
    _common(eig)
    eig.add_argument("--format", choices=EIG_FORMATS, default=None,
                     help="table (default; not printed when only --plot is given), csv or json")
    add_figure_options(eig, SPEED_LIMIT, "real parts, 1/s")
    add_size_option(eig, "--bike-size")
    eig.set_defaults(run=every_size(run_eig))

    stab = sub.add_parser(
        "stability", help="weave and capsize speeds, stable speed ranges (strict and marginal)",
        description="Critical speeds (roots, to 1e-13 m/s) and stable speed ranges, exact and on the "
                    "speed grid, overall and per mode. Strict: every Re < 0; marginal: every "
                    "eigenvalue has Re < 0 or modulus below --marginal.")
    _common(stab)
    stab.add_argument("--marginal", type=number(0, 1e6, open_low=True, what="a modulus in rad/s"),
                      default=2.0, metavar="RAD_S",
                      help="modulus (rad/s) below which an unstable eigenvalue counts as marginally "
                           "stable (default 2.0, as the thesis)")
    stab.add_argument("--format", choices=STABILITY_FORMATS, default="table", help="table (default) or json")
    add_figure_options(stab, SPEED_LIMIT, "real parts, 1/s")
    add_size_option(stab, "--bike-size")
    stab.set_defaults(run=every_size(run_stability))

    comp = sub.add_parser(
        "compare", help="several riders and/or stiffnesses compared by their weave and capsize speeds",
        description="Weave and capsize speeds and the stable speeds of every rider x stiffness: a "
                    "figure with one line per configuration (riders as rows, stiffnesses as colours) "
                    "and a table.")
    comp.add_argument("bike", metavar="BIKE", help="shipped bicycle name, bicycle YAML or parameter file")
    comp.add_argument("--riders", metavar="POSES", default="none",
                      help="comma-separated rider poses or pose files, 'none' for no rider "
                           "(e.g. none,relaxed,aero-tuck)")
    _allow(comp)
    comp.add_argument("--stiffnesses", metavar="S", default="infinite",
                      help="comma-separated stiffnesses as for --stiffness (e.g. infinite,steel,aluminum)")
    comp.add_argument("--combine", choices=("exact", "thesis"), default="exact",
                      help="rider + frame: parallel-axis theorem (exact, default) or the thesis's Eq. 3.6")
    comp.add_argument("--speeds", metavar="START:STOP:STEP", default="0:30:0.05",
                      help="speed grid in m/s (default 0:30:0.05)")
    _max_speeds(comp)
    comp.add_argument("-o", "--output", metavar="FILE", required=True, help="figure (.png, .pdf, .svg)")
    add_figure_options(comp, SPEED_LIMIT)
    add_size_option(comp, "--bike-size")
    comp.set_defaults(run=every_size(run_compare, many=False))


def _allow(p):
    from .bicycle import allow_off_contact_option
    allow_off_contact_option(p)


def _common(p):
    p.add_argument("bike", metavar="BIKE", help="shipped bicycle name, bicycle YAML or parameter file")
    p.add_argument("--rider", metavar="POSE", default="none",
                   help="rider pose name or pose YAML file, or 'none' (default none)")
    _allow(p)
    p.add_argument("--combine", choices=("exact", "thesis"), default="exact",
                   help="rider + frame: parallel-axis theorem (exact, default) or the thesis's Eq. 3.6")
    p.add_argument("--stiffness", metavar="S", default="infinite",
                   help="rear-frame stiffness: infinite (rigid, default), steel, titanium, aluminum "
                        "(the bicycle's published S if it carries one, else the beam model of its rear "
                        "frame, condensed) or a YAML file with S: [[..], [..]] in N m/rad")
    p.add_argument("--speeds", metavar="START:STOP:STEP", default="0:30:0.05",
                   help="speed grid in m/s (default 0:30:0.05, the thesis's)")
    _max_speeds(p)
    p.add_argument("--plot", metavar="FILE", help="also draw the eigenvalue figure (.png, .pdf, .svg)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def _max_speeds(p):
    from ..options import MAX_SPEEDS, count
    p.add_argument("--max-speeds", type=count(), default=MAX_SPEEDS, metavar="N",
                   help=f"raise the limit on the speeds in the grid (default {MAX_SPEEDS})")


def parse_speeds(text, max_speeds=None):
    """``"start:stop:step"`` -> speed grid (m/s); InputError if malformed or over ``max_speeds``."""
    from ..errors import InputError, short
    from ..options import MAX_SPEED, MAX_SPEEDS, MIN_SPEED_STEP
    from ..stability import speed_grid

    limit = max_speeds or MAX_SPEEDS
    expected = (f"START:STOP:STEP in m/s with 0 <= START < STOP <= {MAX_SPEED:g}, "
                f"{MIN_SPEED_STEP:g} <= STEP <= STOP - START")
    try:
        start, stop, step = (float(x) for x in text.split(":"))
    except ValueError:
        raise InputError("--speeds", text, expected) from None
    if not (0 <= start < stop <= MAX_SPEED and MIN_SPEED_STEP <= step <= stop - start):
        raise InputError("--speeds", text, expected)
    count = int(round((stop - start) / step)) + 1
    if count > limit:
        raise InputError("--speeds", text, f"at most {limit} speeds, got {count} "
                                                      "(raise with --max-speeds)")
    return speed_grid(start, stop, step)


def _inputs(args, rider=None, stiffness=None):
    """(parameter set, S or None) of BIKE with ``rider`` and ``stiffness`` (default: the options')."""
    from ..catalog import load_bicycle, parameters, stiffness as frame_stiffness

    bike = load_bicycle(args.bike)
    return (parameters(bike, rider or args.rider, args.combine, allow_off_contact=args.allow_off_contact),
            frame_stiffness(bike, stiffness or args.stiffness))


def _rider_name(rider):
    return "no rider" if rider == "none" else rider


def _stiffness_name(stiffness):
    return "rigid frame" if stiffness == "infinite" else f"{stiffness} frame"


def _combine(combine):
    return "rider added as the thesis did" if combine == "thesis" else "rider added with the parallel-axis theorem"


def _title(args):
    thesis = " (rider added as the thesis did)" if args.rider != "none" and args.combine == "thesis" else ""
    return f"{args.bike}, {_rider_name(args.rider)}, {_stiffness_name(args.stiffness)}{thesis}"


def _emit(args, text):
    from ..output import write_atomic
    if args.output:
        write_atomic(args.output, text)
    else:
        print(text, end="")


def run_eig(args):
    from ..dynamics import eigenvalues
    from ..output import dumps

    options = figure_options(args, args.plot)
    speeds = parse_speeds(args.speeds, args.max_speeds)
    modes = eigenvalues(*_inputs(args), speeds)
    if args.format or args.output or not args.plot:      # only a figure asked for: no table
        if args.format == "json":
            text = dumps(modes.to_dict(), "json")
        else:
            text = eig_table(modes, csv=args.format == "csv")
        _emit(args, text)
    if args.plot:
        from ..dynamics import stability
        from ..plots.stability import plot_eigenvalues
        result = stability(*_inputs(args), speeds)          # marks v_w, v_c and shades the stable speeds
        write_figure(plot_eigenvalues(result, _title(args), options.size, **options.limits()), args.plot, options)
    return 0


def eig_table(modes, csv=False):
    """Eigenvalues at every speed: CSV (every tracked mode's real and imaginary part, full
    precision) or a text table with the weave as one mode (see :func:`weave_cells`)."""
    from ..output import table

    if csv:
        headers = ["speed"] + [f"{label}_{part}".replace(" ", "_") for label in modes.labels for part in ("re", "im")]
        rows = [[v] + [x for z in row for x in (z.real, z.imag)] for v, row in zip(modes.speeds, modes.eigenvalues)]
        return "\n".join([",".join(headers)] + [",".join(repr(float(x)) for x in r) for r in rows]) + "\n"
    others = [label for label in modes.labels if label not in WEAVE]
    headers = ["speed", "weave re", "weave im"] + [f"{label} {part}" for label in others for part in ("re", "im")]
    w = [modes.labels.index(label) for label in WEAVE]
    rows = [[v, *weave_cells(row[w[0]], row[w[1]], name[w[0]] == "weave"),
             *(x for label in others for x in (row[modes.labels.index(label)].real,
                                               row[modes.labels.index(label)].imag))]
            for v, row, name in zip(modes.speeds, modes.eigenvalues, modes.names())]
    return table(headers, rows, floatfmt="{:.6f}")


WEAVE = ("weave 1", "weave 2")


def weave_cells(a, b, paired):
    """The two weave roots as one mode: ``re``, ``+-im`` while they are a pair; both real
    parts (larger first) and ``real`` while they are two real roots."""
    if paired:
        return a.real, f"+-{abs(a.imag):.6f}"
    hi, lo = sorted((a.real, b.real), reverse=True)
    return f"{hi:.6f}, {lo:.6f}", "real"


def run_stability(args):
    from ..dynamics import stability
    from ..errors import InputError
    from ..output import dumps

    options = figure_options(args, args.plot)
    speeds = parse_speeds(args.speeds, args.max_speeds)
    result = stability(*_inputs(args), speeds, marginal=args.marginal)
    text = dumps(result.to_dict(), "json") if args.format == "json" else stability_text(result, _title(args))
    _emit(args, text)
    if args.plot:
        from ..plots.stability import plot_eigenvalues
        write_figure(plot_eigenvalues(result, _title(args), options.size, **options.limits()), args.plot, options)
    return 0


def run_compare(args):
    from ..dynamics import stability
    from ..errors import InputError, short
    from ..output import table
    from ..plots.critical_speeds import plot_critical_speeds

    options = figure_options(args, args.output)
    speeds = parse_speeds(args.speeds, args.max_speeds)
    riders = [r.strip() for r in args.riders.split(",") if r.strip()]
    stiffnesses = [k.strip() for k in args.stiffnesses.split(",") if k.strip()]
    for option, items in (("--riders", riders), ("--stiffnesses", stiffnesses)):
        if not items:
            raise InputError(option, short(getattr(args, option[2:]), 40), "a comma-separated list of at least one name")
    results, rows = {}, []
    for rider in riders:
        for stiffness in stiffnesses:
            result = stability(*_inputs(args, rider, stiffness), speeds)
            results.setdefault(_rider_name(rider), {})[_stiffness_name(stiffness)] = result
            rows.append([rider, stiffness, _speeds(result.weave_speeds), _speeds(result.capsize_speeds),
                         _ranges(result.ranges["strict"]["exact"], "{:.4f}")])
    fig = plot_critical_speeds(results, f"{args.bike}: weave and capsize speeds ({_combine(args.combine)})",
                               options.size, options.xlim)
    write_figure(fig, args.output, options)
    text = table(["rider", "stiffness", "weave speeds", "capsize speeds", "stable (strict)"], rows)
    print(text + f"wrote {args.output}")
    return 0


def _speeds(speeds, digits=4):
    return ", ".join(f"{v:.{digits}f}" for v in speeds) or "-"


def _ranges(rs, fmt):
    return ", ".join(f"{fmt.format(a)}..{fmt.format(b)}" for a, b in rs) or "-"


KIND_WORDS = {"oscillatory": "an oscillatory pair (weave-like)", "real": "a real root (capsize-like)"}


def _crossing_rows(result):
    """One row per crossing speed: a pair's two members on one row, named by what the root is."""
    import numpy as np

    names = result.modes.names()
    rows = []
    for c in result.crossings:
        if rows and abs(rows[-1][0] - c.speed) < 1e-8 and rows[-1][2] == c.direction:
            rows[-1][3] += f", {c.mode}"
            continue
        k = min(np.searchsorted(result.modes.speeds, c.speed), len(names) - 1)
        name = names[k, result.modes.labels.index(c.mode)]
        rows.append([c.speed, KIND_WORDS[c.kind], c.direction, c.mode, name])
    return rows


def stability_text(result, title):
    """Human-readable report: critical speeds in words, every crossing, then ranges overall and per mode."""
    from ..output import table

    v = result.modes.speeds
    lines = [title, f"speeds {v[0]:g}..{v[-1]:g} m/s ({len(v)} points); marginal: |lambda| < "
             f"{result.marginal:g} rad/s", "",
             f"weave speeds (an oscillatory pair crosses Re = 0):  {_speeds(result.weave_speeds, 12)}",
             f"capsize speeds (a real root crosses Re = 0):        {_speeds(result.capsize_speeds, 12)}", ""]
    rows = [[f"{s:.12f}", kind, d, modes, name] for s, kind, d, modes, name in _crossing_rows(result)]
    lines += ["crossings of Re = 0",
              table(["speed (m/s)", "the root that crosses", "direction", "tracked mode", "named"], rows).rstrip("\n")
              if rows else "  none", ""]
    rows = [["all modes"] + [_ranges(result.ranges[c][k], f) for c in ("strict", "marginal")
                             for k, f in (("exact", "{:.6f}"), ("grid", "{:.2f}"))]]
    for label, r in result.mode_ranges.items():
        rows.append([label] + [_ranges(r[c][k], f) for c in ("strict", "marginal")
                               for k, f in (("exact", "{:.6f}"), ("grid", "{:.2f}"))])
    lines += ["stable speed ranges (m/s; per tracked mode)",
              table(["", "strict exact", "strict grid", "marginal exact", "marginal grid"], rows)]
    return "\n".join(lines)
