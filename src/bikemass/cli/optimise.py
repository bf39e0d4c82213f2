"""``bikemass optimise``: the design in a box that maximises, minimises or hits a metric."""

import argparse
import sys
import warnings

from ..core.errors import BikemassWarning, InputError
from ..core.progress import Progress
from . import dialect
from .figure_options import add_figure_options, figure_options, write_figure

DESCRIPTION = """\
Search the box of SPEC.yaml's design variables (any input a sweep can vary: the 26 parameters,
dotted paths into the bicycle or pose YAML such as chart.head_tube_angle) for the design that
maximises or minimises a metric, or hits a target value of it, with other metrics kept within
bounds. The box is screened, then a gradient search (SLSQP) runs from the best screened designs;
gradients are exact in the model's parameters (eigenvalue derivatives), chained with central
differences through the geometry (a person is re-seated on every design). A kink of the objective
at the end point (a stable range changing its bounding mode) is reported, never a false
convergence. The spec format: docs/optimise.md.

spec example:
  bike: bmc-roadmachine@54
  rider: person.yaml
  variables:
    chart.head_tube_angle: {min: 70 deg, max: 75 deg}
    chart.fork_offset: {min: 35 mm, max: 60 mm}
  maximise: stable-range          # or  minimise: METRIC  or  target: {weave-speed: 5.0}
  constraints:
    trail: {min: 50 mm, max: 70 mm}
"""


def _description():
    """The description with every metric (read from the metrics' table when the help is printed)."""
    # lazy: the metrics' module loads numpy; bikemass --help must not
    from ..design.metrics import NAMES, catalogue
    lines = [f"  {m.name} ({m.unit}): {m.description}" for m in catalogue().values() if m.name not in NAMES]
    return (DESCRIPTION + "\nmetrics (SI units; bounds and targets may carry a unit, e.g. 50 mm):\n"
            + "\n".join(lines) + "\n  and any of the 26 benchmark parameters by name (w, c, lam, rR, mB, ...)\n")


def register(sub):
    p = sub.add_parser("optimise", help="the design (geometry, parameters) that maximises, minimises or hits a "
                       "metric (weave speed, stable range, trail, ...) under constraints",
                       description=_description, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("spec", metavar="SPEC.yaml", help="optimisation specification (docs/optimise.md)")
    p.add_argument("--format", choices=("table", "json", "yaml"), default="table",
                   help="table (default), json or yaml (with a units block) of the result on stdout")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="write the optimal design as a file every command reads: the bicycle YAML with the "
                        "values applied (dotted paths into the bicycle only; its header and a warning name the "
                        "options, such as --rider and --model, that analyse it as the spec did), else the "
                        "parameter set (.yaml) of the design with its rider included and the spec's model")
    p.add_argument("--plot", metavar="FILE", help="draw the convergence and the objective around the design "
                                                  "into FILE (.png, .pdf, .svg, ...)")
    add_figure_options(p)
    dialect.add_quiet(p)
    p.set_defaults(run=run_optimise)


def run_optimise(args):
    # lazy: the library loads numpy and scipy; bikemass --help must not
    from ..design.optimise import optimise
    from ..design.spec import read_spec

    options = figure_options(args, args.plot) if args.plot else None
    if args.output:
        # lazy: the library loads numpy; bikemass --help must not
        from ..core.output import check_output
        check_output(args.output, (".yaml", ".yml"), what="the optimal design", option="-o")
    spec = read_spec(args.spec)
    with Progress(100, "optimise") as bar:
        bar.enabled = bar.enabled and not args.quiet
        result = optimise(spec, progress=lambda: bar.step() if bar.done < bar.total - 1 else None)
    if args.output:
        write_design(spec, result, args.output)
    if not args.quiet:
        sys.stdout.write(render(result, args.format))
    if args.plot:
        # lazy: matplotlib only for a figure
        from ..design.figures import objective_slices, plot_optimisation
        fig = plot_optimisation(result, objective_slices(spec, result), f"{spec.bike}: {result.sense} {result.metric}",
                                options.size)
        write_figure(fig, args.plot, options)
    return 0


def render(result, fmt):
    """The result as text: a table, or JSON/YAML with its units block."""
    if fmt in ("json", "yaml"):
        return dialect.result_document(result.to_dict(), result.units(), fmt)
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import table
    rows = [[k, v, u] for k, v, u in result.display_rows()]
    text = table(["", "value", "unit"], rows)
    lines = [text, f"search: {result.message}; {result.evaluations} designs built in {result.seconds:.1f} s",
             f"gradients: {result.gradient}"]
    lines += [f"note: {n}" for n in result.notes]
    return "\n".join(lines) + "\n"


def write_design(spec, result, path):
    """Write ``result``'s design to ``path``: the bicycle YAML with the design's values where every
    variable is a dotted path into the bicycle and the file reads back as that bicycle (the rider, the
    model, its members' files, the stiffness and the combination stay apart: the file's header and one
    warning, given before anything is written, name the options that analyse it as the spec did), else
    the parameter file of the design with its rider included: for a model beyond the rigid Whipple
    bicycle, every parameter it uses (``bikemass params --model M --format yaml``'s form, read back as
    the same model)."""
    # lazy: the library loads numpy; bikemass --help must not
    import yaml
    from ..core.output import write_atomic
    from ..design.problem import Problem
    from ..models.parameter_export import format_parameters, member_document, member_units
    from ..scenario.inputs import split_changes

    problem = Problem(spec)
    x = [result.variables[v.key] for v in spec.variables]
    bike, rider, params, _ = split_changes(problem.changes(x))
    included = spec.rider not in (None, "none") or problem.scenario.rider_in_set()
    doc = _bicycle_design(problem, bike) if bike and not rider and not params else None
    if doc is not None:
        options = _spec_options(spec)
        header = (f"# optimal design of {spec.source} (bikemass optimise): {result.sense} {result.metric} = "
                  f"{result.objective:.6g} {result.metric_units[result.metric]}\n"
                  + (f"# analysed as the spec did with: {options}\n" if options else ""))
        if options:
            warnings.warn(f"{path} holds the bicycle alone: read it back with {options} as the spec analyses it",
                          BikemassWarning, stacklevel=2)
        write_atomic(path, header + yaml.safe_dump(doc, sort_keys=False, allow_unicode=True))
        return
    speeds = _speed_option(spec)
    if speeds:
        warnings.warn(f"{path} holds no speed range: read it back with {speeds} as the spec analyses it",
                      BikemassWarning, stacklevel=2)
    built = problem.design(x).built
    if built.choice.members or built.stiffness is not None:
        data = member_document(built.choice, built.parameters, built.members, built.stiffness, included,
                               spec.stiffness or "")
        write_atomic(path, dialect.document(data, "yaml", member_units(built.choice)))
        return
    write_atomic(path, format_parameters(built.parameters, "yaml", rider_included=included))


def _bicycle_design(problem, changes):
    """The bicycle YAML document of the design's bicycle ``changes``, or ``None`` where the bicycle is
    not a YAML document or the changed document would not read back as the changed bicycle (a file is
    checked as written: a changed ``geometry.trail`` contradicts the head-tube keypoints the analysis
    leaves in place; the parameter file is written instead)."""
    # lazy: the library loads numpy; bikemass --help must not
    from ..scenario.loading import load_bicycle

    try:
        doc = problem.scenario.inputs.bicycle_document(changes)
        load_bicycle(doc)
    except InputError:
        return None
    return doc


def _spec_options(spec):
    """The command-line options (quoted for a shell) that analyse a bicycle file as ``spec`` does: its
    rider, combination, model, members' files and stiffness."""
    # lazy: the registry loads numpy; bikemass --help must not
    import shlex
    from ..models.registry import BASE

    options = [("--rider", spec.rider)] if spec.rider not in (None, "none") else []
    if spec.combine != "exact":
        options.append(("--combine", spec.combine))
    if spec.model != BASE:
        options.append(("--model", spec.model))
    options += [(f"--{keyword}", value) for keyword, value in spec.members]
    if spec.stiffness is not None:
        options.append(("--stiffness", spec.stiffness))
    return " ".join([*(f"{option} {shlex.quote(str(value))}" for option, value in options), _speed_option(spec)]).strip()


def _speed_option(spec):
    """``--speeds 0:MAX:0.05`` where the spec's ``max_speed`` is not the default grid's end, else ``""``."""
    # lazy: the grid's module loads numpy; bikemass --help must not
    from ..analysis.engine.speeds import DEFAULT_SPEEDS

    end = DEFAULT_SPEEDS[1]
    return "" if spec.max_speed == end else f"--speeds 0:{spec.max_speed:g}:{DEFAULT_SPEEDS[2]:g}"
