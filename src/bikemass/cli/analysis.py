"""``bikemass sensitivity``, ``bikemass uncertainty`` and ``bikemass sweep``."""

import sys
from pathlib import Path

from ..core.errors import InputError
from ..core.limits import MAX_SPEED
from ..core.progress import Progress
from . import dialect
from .figure_options import add_figure_options, figure_options, write_figure
from .options import whole

PLOT_FORMAT = "png"
"""The sweep's figure format unless ``--plot-format`` gives one."""
INPUTS_UNIT = "value: SI (m, kg, rad, ...); weave_speed, capsize_speed: m/s per SI unit of the input"
"""The unit of ``sensitivity``'s ``inputs`` (:func:`~bikemass.analysis.sensitivity.geometry_sensitivity`);
the rest of its units block is what :class:`~bikemass.analysis.sensitivity.Sensitivity` declares,
one entry per top-level key (the parameter names inside the derivative mappings are not
quantities of their own units there)."""


def register(sub):
    sens = sub.add_parser(
        "sensitivity", help="exact derivatives of the weave and capsize speeds w.r.t. the model's parameters",
        description="Derivatives of the weave speed (first oscillatory crossing of Re = 0) and the "
                    "capsize speed (first real-root crossing) with respect to each parameter of the model "
                    "(the 26 benchmark parameters; with --model, the member's own too: the tyres' CaF, "
                    "sigmaF, ..., the upper body's mU, klean, ..., the arms' k_arms, c_arms), from "
                    "eigenvalue derivatives (left/right eigenvectors) and the implicit function "
                    "theorem, exact to rounding; elasticities (p/v) dv/dp; a bar chart with --plot.")
    _bike_options(sens, "the derivatives and elasticities", "a bar chart of the elasticities")
    sens.add_argument("--inputs", metavar="KEYS", default=None,
                      help="also w.r.t. geometry-level inputs: comma-separated dotted paths into the "
                           "bicycle YAML (sections.seat_stay.wall, geometry.trail, chart.head_tube_angle) "
                           "or, after 'rider.', the pose YAML (rider.chain.torso_lean); chained through "
                           "the model with a central difference for the geometry -> parameters step only")
    sens.add_argument("--step", type=float, default=1e-4, metavar="REL",
                      help="relative step of that central difference, 1e-10 to 0.1 (default 1e-4)")
    sens.set_defaults(run=run_sensitivity)


    unc = sub.add_parser(
        "uncertainty", help="propagate parameter/geometry uncertainties to the matrices, eigenvalues and critical speeds",
        description="Standard deviations of M, C1, K0 (without g), K2, of the eigenvalues over speed and of "
                    "the weave and capsize speeds, from the +/- values of a BicycleParameters file and/or a "
                    "YAML file (--std) of standard deviations or distributions per input: any of the 26 "
                    "parameters or a dotted path into the bicycle or pose YAML. linear: first order (as the "
                    "uncertainties package); montecarlo: N seeded samples, reported beside the linear result.")
    _bike_options(unc, "the standard deviations", "the eigenvalues over speed with their bands (and, for "
                  "montecarlo, histograms of the critical speeds)")
    unc.add_argument("--std", metavar="FILE",
                     help="YAML with an 'uncertainty:' mapping, input -> std, or {std: s}, or "
                          "{distribution: uniform, half_width: h} (each in SI: m, kg, rad; or with a unit: '0.1 mm', '3 deg')")
    unc.add_argument("--method", choices=("linear", "montecarlo"), default="linear",
                     help="linear (default) or montecarlo")
    unc.add_argument("--samples", type=whole("a number of samples"), default=None, metavar="N",
                     help="Monte Carlo samples (default 1000; with --method montecarlo)")
    unc.add_argument("--seed", type=whole("a whole-number seed"), default=None,
                     help="random seed of the Monte Carlo draws (default 0; with --method montecarlo)")
    unc.add_argument("--speeds", metavar="START:STOP:STEP", default="0:10:0.1",
                     help="speeds of the eigenvalue bands in m/s (default 0:10:0.1)")
    unc.set_defaults(run=run_uncertainty)


    sw = sub.add_parser(
        "sweep", help="design sweep: critical speeds over a grid or sample of inputs, locally or on a Dask cluster",
        description="Evaluate every configuration of SPEC.yaml (a bicycle, rider and stiffness, and the inputs "
                    "to vary: any of the 26 parameters, 'stiffness', or dotted paths into the bicycle or pose "
                    "YAML; a full grid or a Latin hypercube / Sobol sample) and write OUT/results.csv (and "
                    "results.parquet), one row per configuration: the varied values, weave_speed, "
                    "capsize_speed (first crossing of each kind, empty if none), stable_from, stable_to "
                    "(first strictly stable range), total_mass, error; figures; sobol.json if the spec "
                    "asks for a global sensitivity analysis. Finished chunks are kept in OUT/chunks: "
                    "run the same command again to resume. The spec format is in docs/analysis.md.")
    sw.add_argument("spec", metavar="SPEC.yaml", help="sweep specification")
    sw.add_argument("--out", metavar="DIR", required=True, help="output folder (created; reused to resume)")
    engine = sw.add_mutually_exclusive_group()
    engine.add_argument("--workers", type=whole("a number of workers"), metavar="N",
                        help="run on a local Dask cluster of N single-threaded worker processes")
    engine.add_argument("--scheduler", metavar="ADDRESS",
                        help="run on an existing Dask distributed cluster (e.g. tcp://10.0.0.5:8786)")
    sw.add_argument("--plot-format", metavar="EXT", help=f"figure format (default {PLOT_FORMAT})")
    sw.add_argument("--no-figures", action="store_true",
                    help="write no figures (matplotlib is then not imported; a sweep of millions of rows "
                         "reads no columns back)")
    sw.add_argument("--quiet", action="store_true", help="no progress bar or summary")
    sw.add_argument("--restart", action="store_true",
                    help="start over in an --out folder holding a sweep (its chunks and tables removed) instead "
                         "of resuming it; a resume needs the same spec, input files and bikemass")
    add_figure_options(sw)
    # --out: a new or empty folder, or a sweep's own (holding bikemass.sweep.run.STAMP) to resume
    sw.set_defaults(run=run_sweep_command, folder_outputs=("out",), folder_mark="sweep.json")


def _bike_options(p, data, figure):
    dialect.add_bike(p)
    dialect.add_rider(p)
    dialect.add_combine(p)
    dialect.add_stiffness(p)
    dialect.add_model(p)
    p.add_argument("--max-speed", type=float, default=30.0, metavar="M_S",
                   help="look for critical speeds on (0, M_S] m/s (default 30)")
    dialect.add_output(p, what=data)
    dialect.add_plot(p, figure)


def _options(args):
    """Checked figure options (or None) of ``--plot``, and ``--max-speed`` checked."""
    options = dialect.figure_checked(args)
    if not 0 < args.max_speed <= MAX_SPEED:                # the limit of every speed grid and spec
        raise InputError("--max-speed", args.max_speed, f"a speed in m/s above 0 and at most {MAX_SPEED:g}")
    return options


def _title(args):
    model = "" if args.model == "whipple" else f", model {args.model}"
    rider = dialect.riderless_label(args) if args.rider == "none" else f"rider {args.rider}"
    return f"{dialect.bike_name(args.bike)}, {rider}, {dialect.frame_name(args)}{model}"


def run_sensitivity(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.sensitivity import MIN_STEP, geometry_sensitivity, sensitivity, sensitivity_figure

    options = _options(args)
    keys = [k.strip() for k in (args.inputs or "").split(",") if k.strip()]
    if args.inputs is not None and not keys:
        raise InputError("--inputs", repr(args.inputs), "a comma-separated list of at least one dotted path")
    if not MIN_STEP <= args.step <= 0.1:             # given without --inputs too: no option is ignored
        raise InputError("--step", args.step, f"a relative step from {MIN_STEP:g} to 0.1 (below it the difference is "
                         "rounding)")
    scenario = dialect.scenario(args, origin="--inputs")
    result = sensitivity(scenario, max_speed=args.max_speed)
    geometry = geometry_sensitivity(scenario, keys, result, args.step) if keys else {}

    def render(fmt):
        if fmt == "table":
            return sensitivity_table(result, _title(args), geometry)
        if fmt == "csv":
            return sensitivity_csv(result, geometry)
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import dumps
        doc = result.to_dict()
        if geometry:
            doc["inputs"] = geometry
        declared = {**result.units(), "inputs": INPUTS_UNIT}
        return dumps({**doc, "units": {k: u for k, u in declared.items() if k in doc}}, fmt)
    dialect.emit(args, render)
    if args.plot:
        dialect.save_plot(args, sensitivity_figure(result, _title(args), options.size), options)
    return 0


def sensitivity_csv(result, geometry=None):
    """One row per input: the two critical speeds first (kind ``speed``), then the model's
    parameters (the 26 and a member's own), the rear-frame S entries and any geometry-level inputs,
    each with its value, unit and the derivatives (and, for parameters, elasticities) of both speeds."""
    ew, ec = result.elasticities("weave_speed"), result.elasticities("capsize_speed")
    rows = [[k, "speed", getattr(result, k), "m/s", None, None, None, None] for k in ("weave_speed", "capsize_speed")]
    rows += [[n, "parameter", result.params[n], result.unit_of(n), result.d_weave_speed[n], ew[n],
              result.d_capsize_speed[n], ec[n]] for n in result.d_weave_speed]
    if result.d_stiffness:
        rows += [[k, "stiffness", None, "N m/rad", result.d_stiffness["weave_speed"][k], None,
                  result.d_stiffness["capsize_speed"][k], None] for k in result.d_stiffness["weave_speed"]]
    rows += [[k, "geometry", g["value"], "SI", g["weave_speed"], None, g["capsize_speed"], None]
             for k, g in (geometry or {}).items()]
    return dialect.csv_text(["input", "kind", "value", "unit", "d_weave_speed (m/s per unit)", "elasticity_weave_speed",
                             "d_capsize_speed (m/s per unit)", "elasticity_capsize_speed"], rows)


def sensitivity_table(result, title, geometry=None):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    ew, ec = result.elasticities("weave_speed"), result.elasticities("capsize_speed")
    rows = [[n, result.params[n], result.d_weave_speed[n], ew[n], result.d_capsize_speed[n], ec[n]]
            for n in result.d_weave_speed]
    head = (f"{title}\nweave speed {_speed(result.weave_speed)}, capsize speed "
            f"{_speed(result.capsize_speed)} (first crossing of each kind)\n\n")
    text = head + table(["parameter", "value", "d weave/dp", "elasticity", "d capsize/dp", "elasticity"],
                        rows, floatfmt="{:.6g}")
    if result.d_stiffness:
        text += "\nrear-frame stiffness S (N m/rad)\n" + table(
            ["entry", "d weave/dS", "d capsize/dS"],
            [[k, result.d_stiffness["weave_speed"][k], result.d_stiffness["capsize_speed"][k]]
             for k in result.d_stiffness["weave_speed"]], floatfmt="{:.6g}")
    if geometry:
        text += ("\ngeometry-level inputs (dv/dp exact, dp/dx by central difference; check = change "
                 "with twice the step)\n") + table(
            ["input", "value", "d weave/dx", "d capsize/dx", "check"],
            [[k, g["value"], g["weave_speed"], g["capsize_speed"], g["difference_check"]]
             for k, g in geometry.items()], floatfmt="{:.6g}")
    return text


def _speed(v):
    return "none" if v is None else f"{v:.9f} m/s"


def read_std_file(path, scenario=None):
    """``{key: Spread}`` from the ``uncertainty:`` mapping of a YAML file; with ``scenario``, a spread in a
    unit its input cannot carry (:meth:`~bikemass.scenario.scenario.Scenario.unit_problem`) is refused."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.uncertainty import read_spreads
    from ..core.config import load_yaml
    node = load_yaml(path)
    node.check_keys(required=("uncertainty",), optional=("name", "description", "source"))
    return read_spreads(node["uncertainty"], None if scenario is None else scenario.unit_problem)


def run_uncertainty(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.uncertainty import Spread, propagate, uncertainty_figure

    options = _options(args)
    for option, value in (("--samples", args.samples), ("--seed", args.seed)):
        if value is not None and args.method != "montecarlo":     # an option given is never ignored silently
            raise InputError(option, value, "--method montecarlo with it (the linear method draws no samples)")
    samples = 1000 if args.samples is None else args.samples
    seed = 0 if args.seed is None else args.seed
    if not 2 <= samples <= 10 ** 6:
        raise InputError("--samples", samples, "a number of samples from 2 to 1000000")
    speeds = dialect.parse_speeds(args.speeds)
    scenario = dialect.scenario(args, origin=args.std or args.bike)
    # a bicycle computed from measurements: its measurements are the independent inputs (the 26
    # parameters share them); a parameter file: its parameters' standard deviations
    spreads = {k: Spread("normal", s) for k, s in (scenario.measurement_std or scenario.file_std).items()}
    if args.std:
        spreads.update(read_std_file(args.std, scenario))
    if not spreads:
        raise InputError(args.bike, "(uncertainties)", "standard deviations: a BicycleParameters file with "
                         "+/- values (<Name>Benchmark.txt or <Name>Measured.txt), a parameter file with an "
                         "uncertainty: block, or --std FILE")
    result = propagate(scenario, spreads, args.method, samples, seed, speeds)

    def render(fmt):
        if fmt == "table":
            return uncertainty_table(result, _title(args))
        if fmt == "csv":
            return uncertainty_csv(result)
        return dialect.result_document(result.to_dict(), uncertainty_units(), fmt)
    dialect.emit(args, render)
    if args.plot:
        dialect.save_plot(args, uncertainty_figure(result, _title(args), options.size), options)
    return 0


def uncertainty_units():
    """The units block of ``uncertainty``'s JSON/YAML: what a
    :class:`~bikemass.analysis.uncertainty.Propagation` declares (:func:`~bikemass.analysis.uncertainty.propagation_units`)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..analysis.uncertainty import propagation_units
    return propagation_units()


def _entries(matrix):
    """``(i, j)`` of every entry of a matrix, row by row (2 x 2 for the Whipple bicycle, a member's more)."""
    rows, columns = matrix.shape
    return [(i, j) for i in range(rows) for j in range(columns)]


def uncertainty_table(result, title):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table

    lines = [title, f"method {result.method}; inputs: " + ", ".join(
        f"{k} ({v['distribution']} std {v['std']:.4g})" for k, v in result.inputs.items()), ""]
    mc = result.method == "montecarlo"
    rows = []
    for name, m in result.matrices.items():
        for i, j in _entries(m["nominal"]):
            if m["nominal"].shape != (2, 2) and m["nominal"][i, j] == 0 and m["std"][i, j] == 0:
                continue                  # a member's state matrix: its structural zeros are left out here
            rows.append([f"{name}[{i},{j}]", m["nominal"][i, j], m["std"][i, j]]
                        + ([m["linear_std"][i, j]] if mc else []))
    lines.append(table(["matrix entry", "nominal", "std" + (" (MC)" if mc else ""), *(["std (linear)"] if mc else [])],
                       rows, floatfmt="{:.6g}"))
    rows = []
    for name, s in result.speeds.items():
        rows.append([name.replace("_", " "), s.nominal, s.std]
                    + ([s.linear_std, s.mean, s.q025, s.q975, s.fraction_without] if mc else []))
    heads = ["critical speed (m/s)", "nominal", "std" + (" (MC)" if mc else "")]
    if mc:
        heads += ["std (linear)", "MC mean", "MC 2.5 %", "MC 97.5 %", "none found"]
    lines.append(table(heads, rows, floatfmt="{:.6g}"))
    return "\n".join(lines)


def uncertainty_csv(result):
    """One row per matrix entry and critical speed: quantity, unit, nominal, std (and, for
    montecarlo, the linear std, mean, 2.5 % and 97.5 % quantiles and the fraction without)."""
    mc = result.method == "montecarlo"
    extra = ["linear_std", "mean", "q025", "q975", "fraction_without"] if mc else []
    units = uncertainty_units()
    rows = [[f"{name}[{i},{j}]", units[name], m["nominal"][i, j], m["std"][i, j]]
            + ([m["linear_std"][i, j], None, None, None, None] if mc else [])
            for name, m in result.matrices.items() for i, j in _entries(m["nominal"])]
    rows += [[name, "m/s", s.nominal, s.std] + [getattr(s, k) for k in extra] for name, s in result.speeds.items()]
    return dialect.csv_text(["quantity", "unit", "nominal", "std", *extra], rows)


MAX_FIGURE_ROWS = 5_000_000
"""Most rows a sweep's figures are drawn from (about 230 bytes a row in memory: 1.2 GB); a larger
sweep writes its tables and a note instead."""


def run_sweep_command(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import dumps, write_atomic
    from ..sweep import read_spec, run_sweep
    from ..sweep.spec import count_of

    spec = read_spec(args.spec)
    require_for_sweep(args)
    plot_format = args.plot_format or PLOT_FORMAT
    # a format given is checked even with --no-figures; the default is not (no matplotlib without figures)
    options = figure_options(args, None if args.no_figures and args.plot_format is None else f"x.{plot_format}")
    total = count_of(spec)
    with Progress(total, "sweep") as bar:
        if args.quiet:
            bar.enabled = False
        rows = run_sweep(spec, args.out, args.workers, args.scheduler, progress=lambda n: bar.step(n=n),
                         restart=args.restart)
    out = Path(args.out)
    notes = list(rows.notes)
    if not args.no_figures and len(rows) > MAX_FIGURE_ROWS:
        notes.append(f"no figures: {len(rows)} rows are more than the {MAX_FIGURE_ROWS} figures are drawn "
                     f"from (they hold every drawn column in memory, about 230 bytes a row); "
                     f"results.csv has them all")
    elif not args.no_figures:
        # lazy: matplotlib is slow to import; only figures need it
        from ..sweep.figures import sweep_figures
        for stem, fig in sweep_figures(rows, spec, options.size).items():
            write_figure(fig, out / f"{stem}.{plot_format}", options)
    if spec.global_sensitivity:
        # lazy: the library loads numpy; bikemass --help must not
        from ..sweep.sobol import sobol_indices
        write_atomic(out / "sobol.json", dumps(sobol_indices(rows, spec), "json"))
    if not args.quiet:
        for note in notes:
            print(f"bikemass: note: {note}", file=sys.stderr)
        errors = rows.refused
        print(f"{len(rows)} configurations -> {out / 'results.csv'}"
              + (f" ({errors} refused by the model: see the error column)" if errors else ""))
    return 0


def require_for_sweep(args):
    """The packages the chosen engine needs (one clear line if missing)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..sweep.run import require_installed
    if args.workers is not None or args.scheduler is not None:
        require_installed("distributed")
