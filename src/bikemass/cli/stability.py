"""``bikemass eig``, ``bikemass stability`` and ``bikemass compare``: eigenvalues over speed,
critical speeds, stable ranges."""

import argparse
import math

from ..core.errors import InputError, short
from . import dialect
from .bicycle import allow_off_contact_option
from .options import MAX_SPEEDS, count, number
from .sizes import add_size_option, every_size

SPEED_LIMIT = "speed, m/s"


def register(sub):
    eig = sub.add_parser(
        "eig", help="eigenvalues of the labelled modes (weave, capsize, caster) against speed",
        description="Eigenvalues of the linearised bicycle at every speed (the Whipple bicycle of Meijaard "
                    "et al. 2007, or the --model you choose), each followed across speed and labelled weave "
                    "1, weave 2, capsize, caster (and the richer models' lean, tyre, wobble, ... modes).")
    _common(eig)
    dialect.add_output(eig, what="the eigenvalues")
    dialect.add_plot(eig, "the eigenvalues against speed (Meijaard et al. 2007, Fig. 3 convention)", SPEED_LIMIT, "real parts, 1/s")
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
    dialect.add_output(stab, what="the critical speeds and ranges")
    dialect.add_plot(stab, "the eigenvalues with the stable speeds shaded", SPEED_LIMIT, "real parts, 1/s")
    add_size_option(stab, "--bike-size")
    stab.set_defaults(run=every_size(run_stability))

    comp = sub.add_parser(
        "compare", help="several riders, stiffnesses and/or models compared by their weave and capsize speeds",
        description="Weave and capsize speeds and the stable speeds of every rider x stiffness (x model with "
                    "--models): a figure with one line per configuration (riders, or riders and models, as "
                    "rows, stiffnesses as colours) and a table.")
    dialect.add_bike(comp)
    comp.add_argument("--riders", metavar="POSES", default="none",
                      help="comma-separated rider poses or pose files, 'none' for no rider "
                           "(e.g. none,relaxed,aero-tuck)")
    _allow(comp)
    dialect.add_stiffness(comp, many=True)
    dialect.add_model(comp)
    comp.add_argument("--models", metavar="MODELS",
                      help="comma-separated models compared side by side, each as for --model (e.g. "
                           "whipple,rider-lean,tyre,rider-lean+tyre); replaces --model; docs/models.md")
    dialect.add_combine(comp)
    dialect.add_speeds(comp)
    _max_speeds(comp)
    dialect.add_output(comp, what="the critical speeds of every configuration")
    dialect.add_plot(comp, "the weave and capsize speeds of every configuration", SPEED_LIMIT)
    add_size_option(comp, "--bike-size")
    comp.set_defaults(run=every_size(run_compare, many=False))


def _allow(p):
    allow_off_contact_option(p)


def _common(p):
    dialect.add_bike(p)
    dialect.add_rider(p)
    _allow(p)
    dialect.add_combine(p)
    dialect.add_stiffness(p)
    dialect.add_model(p)
    dialect.add_control(p)
    dialect.add_speeds(p)
    _max_speeds(p)


def _max_speeds(p):
    p.add_argument("--max-speeds", type=count(), default=MAX_SPEEDS, metavar="N",
                   help=f"raise the limit on the speeds in the grid (default {MAX_SPEEDS})")


def _built(args, rider=None, stiffness=None):
    """The scenario of BIKE with ``rider`` and ``stiffness`` (default: the options'), built."""
    return dialect.scenario(args, rider, stiffness).build()


def _rider_name(rider, args=None):
    return (dialect.riderless_label(args) if args is not None else "no rider") if rider == "none" else rider


def _combine(combine):
    return "rider added as the thesis did" if combine == "thesis" else "rider added with the parallel-axis theorem"


def _title(args):
    thesis = " (rider added as the thesis did)" if args.rider != "none" and args.combine == "thesis" else ""
    model = "" if getattr(args, "model", "whipple") == "whipple" else f", model {args.model}"
    control = f", control {args.control}" if getattr(args, "control", None) else ""
    return f"{dialect.bike_name(args.bike)}, {_rider_name(args.rider, args)}, {dialect.frame_name(args)}{model}{control}{thesis}"


def run_eig(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.eigen_table import eig_table
    from ..analysis.results import eigenvalues

    options = dialect.figure_checked(args)
    speeds = dialect.parse_speeds(args.speeds, args.max_speeds, "--max-speeds")
    built = _built(args)
    modes = eigenvalues(built, speeds=speeds, max_speeds=args.max_speeds, control=args.control)

    def render(fmt):
        if fmt in ("json", "yaml"):
            return dialect.result_document(modes.to_dict(), modes.units(), fmt)
        return eig_table(modes, csv=fmt == "csv")
    dialect.emit(args, render)
    if args.plot:
        # lazy: plots/ load matplotlib; only the figure needs it
        from ..analysis.results import stability
        from ..plots.stability import plot_eigenvalues
        result = stability(built, speeds=speeds, max_speeds=args.max_speeds, control=args.control)     # marks v_w, v_c and shades the stable speeds
        dialect.save_plot(args, plot_eigenvalues(result, _title(args), options.size, **options.limits()), options)
    return 0


def run_stability(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.results import stability

    options = dialect.figure_checked(args)
    if not args.marginal > 0:
        raise InputError("--marginal", args.marginal, "a positive modulus in rad/s")
    speeds = dialect.parse_speeds(args.speeds, args.max_speeds, "--max-speeds")
    result = stability(_built(args), speeds=speeds, marginal=args.marginal, max_speeds=args.max_speeds,
                       control=args.control)

    def render(fmt):
        if fmt in ("json", "yaml"):
            # the frame as the title names it: a material is a property on the bicycle's own tube sections
            return dialect.result_document({"frame": dialect.frame_name(args), **result.to_dict()},
                                           result.units(), fmt)
        if fmt == "csv":
            return ranges_csv(result)
        return stability_text(result, _title(args))
    dialect.emit(args, render)
    if args.plot:
        # lazy: plots/ load matplotlib; only the figure needs it
        from ..plots.stability import plot_eigenvalues
        dialect.save_plot(args, plot_eigenvalues(result, _title(args), options.size, **options.limits()), options)
    return 0


def ranges_csv(result):
    """One row per stable speed range: modes (all, weave, or one label), criterion, ends, start, stop."""
    scopes = {"all modes": result.ranges, "weave": result.weave_ranges, **result.mode_ranges}
    rows = [[scope, criterion, ends, a, b] for scope, ranges in scopes.items()
            for criterion, by_ends in ranges.items() for ends, spans in by_ends.items() for a, b in spans]
    return dialect.csv_text(["modes", "criterion", "ends", "start (m/s)", "stop (m/s)"], rows)


def run_compare(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.results import stability

    options = dialect.figure_checked(args)
    speeds = dialect.parse_speeds(args.speeds, args.max_speeds, "--max-speeds")
    riders = [r.strip() for r in args.riders.split(",") if r.strip()]
    stiffnesses = [None] if args.stiffnesses is None else [k.strip() for k in args.stiffnesses.split(",") if k.strip()]
    for option, items in (("--riders", riders), ("--stiffnesses", stiffnesses)):
        if not items:
            raise InputError(option, short(getattr(args, option[2:]), 40), "a comma-separated list of at least one name")
    models = _models(args)
    results, runs = {}, []
    for rider in riders:
        for model in models or (args.model,):
            each = argparse.Namespace(**{**vars(args), "model": model, **_files_of(args, models, model)})
            row = _rider_name(rider) if not models else f"{_rider_name(rider)}, {model}"
            for stiffness in stiffnesses:
                result = stability(_built(each, rider, stiffness), speeds=speeds, max_speeds=args.max_speeds)
                frame = dialect.frame_name(each, stiffness, rider)
                results.setdefault(row, {})[frame] = result
                # no choice given: the bicycle's own, "infinite" unless a parameter file carries its frame's
                shown = stiffness if stiffness is not None else \
                    ("infinite" if frame == dialect.stiffness_label(None) else "parameter file")
                runs.append({"rider": rider, **({"model": model} if models else {}), "stiffness": shown,
                             "weave_speeds": list(result.weave_speeds), "capsize_speeds": list(result.capsize_speeds),
                             "stable_speeds": [list(r) for r in result.stable_speeds]})
    dialect.emit(args, lambda fmt: comparison_text(runs, fmt))
    if args.plot:
        # lazy: plots/ load matplotlib; only the figure needs it
        from ..plots.critical_speeds import plot_critical_speeds
        fig = plot_critical_speeds(results, f"{dialect.bike_name(args.bike)}: weave and capsize speeds ({_combine(args.combine)})",
                                   options.size, options.xlim)
        dialect.save_plot(args, fig, options)
    return 0


def _files_of(args, models, model):
    """``{keyword: None}`` for each member's file option (``--tyres``, ``--arms``) that ``model``, one of
    ``--models``, has no member for: the file applies to the models that have it.  A file no model of
    ``--models`` takes is an InputError."""
    if not models:
        return {}
    dropped = {}
    for spec in dialect.SPECS:
        given = getattr(args, spec.keyword, None) if spec.option else None
        if given is None:
            continue
        if not any(dialect.parse_model(m).has(spec.name) for m in models):
            raise InputError(spec.option, given, f"a model of --models with the {spec.name} member (e.g. "
                             f"{dialect.parse_model(models[0]).with_member(spec.name).name}); none of "
                             f"{', '.join(models)} has one")
        if not dialect.parse_model(model).has(spec.name):
            dropped[spec.keyword] = None
    return dropped


def _models(args):
    """The models of ``--models`` (canonical names, in order, each once), or ``()`` without it."""
    if args.models is None:
        return ()
    if getattr(args, "model_given", True):
        raise InputError("--models", short(args.models, 40), f"--models or --model, not both (--models replaces "
                         f"--model {args.model})")
    names = []
    for text in args.models.split(","):
        try:
            name = dialect.model_choice(text.strip())
        except argparse.ArgumentTypeError as exc:
            raise InputError("--models", short(text.strip(), 40), str(exc)) from None
        if name not in names:
            names.append(name)
    if not names:
        raise InputError("--models", short(args.models, 40), "a comma-separated list of at least one model")
    return tuple(names)


RUN_UNITS = {"weave_speeds": "m/s", "capsize_speeds": "m/s", "stable_speeds": "m/s"}
"""Units of the keys of a comparison run (the critical speeds and stable ranges of a stability result)."""


def comparison_text(runs, fmt):
    """The weave and capsize speeds and strictly stable ranges of every rider x stiffness (x model)."""
    if fmt in ("json", "yaml"):
        return dialect.document({"runs": runs}, fmt, RUN_UNITS)
    model = ["model"] if runs and "model" in runs[0] else []
    rows = [[r["rider"], *(r[k] for k in model), r["stiffness"], _speeds(r["weave_speeds"]),
             _speeds(r["capsize_speeds"]), _ranges(r["stable_speeds"], "{:.4f}")] for r in runs]
    if fmt == "csv":
        return dialect.csv_text(["rider", *model, "stiffness", "weave speeds (m/s)", "capsize speeds (m/s)",
                                 "stable (strict, m/s)"], rows)
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table
    return table(["rider", *model, "stiffness", "weave speeds", "capsize speeds", "stable (strict)"], rows)


def _speeds(speeds, digits=4):
    return ", ".join(f"{v:.{digits}f}" for v in speeds) or "-"


def _ranges(rs, fmt):
    return ", ".join(f"{fmt.format(a)}..{fmt.format(b)}" for a, b in rs) or "-"


def _start_text(unstable):
    """``"weave 1 (real)"``, ``"tyre (5.978 Hz)"``: a mode unstable from the lowest speed."""
    what = "real" if unstable.kind == "real" else f"{unstable.frequency / (2 * math.pi):.3f} Hz"
    return f"{unstable.mode or unstable.kind} ({what})"


KIND_WORDS = {"oscillatory": "an oscillatory pair (weave-like)", "real": "a real root (capsize-like)"}


def _crossing_rows(result):
    """One row per crossing: speed, what crosses, direction, the tracked mode (a pair by its family),
    and what that root is named at the nearest grid speed."""
    # lazy: the library loads numpy; bikemass --help must not
    import numpy as np

    names, labels = result.modes.names(), result.modes.labels
    rows = []
    for c in result.crossings:
        k = min(np.searchsorted(result.modes.speeds, c.speed), len(names) - 1)
        name = names[k, labels.index(c.mode)] if c.mode in labels else c.mode
        rows.append([c.speed, KIND_WORDS[c.kind], c.direction, c.mode, name])
    return rows


def stability_text(result, title):
    """Human-readable report: critical speeds in words, every crossing, then ranges overall and per mode."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    v = result.modes.speeds
    lines = [title, f"speeds {v[0]:g}..{v[-1]:g} m/s ({len(v)} points); marginal: |lambda| < "
             f"{result.marginal:g} rad/s", "",
             f"weave speeds (the weave pair crosses Re = 0):       {_speeds(result.weave_speeds, 12)}",
             f"capsize speeds (a real root crosses Re = 0):        {_speeds(result.capsize_speeds, 12)}"]
    if result.other_crossings:
        lines.append("other oscillations crossing Re = 0:                 "
                     + ", ".join(f"{c.speed:.12f} ({c.mode})" for c in result.other_crossings))
    if result.unstable_at_start:
        lines.append(f"unstable from the lowest speed ({v[0]:g} m/s):".ljust(52)
                     + ", ".join(_start_text(u) for u in result.unstable_at_start))
    if not result.stable_speeds:
        lines.append("no stable speeds: the modes that prevent them, " + result.prevented_by.text())
    lines.append("")
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
