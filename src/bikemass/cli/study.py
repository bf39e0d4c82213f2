"""``bikemass study``: the thesis reproduced end to end, compared entry by entry, then corrected."""

import argparse
from pathlib import Path

from ..core.progress import Progress
from .dialect import late_help
from .options import jobs

def _description():
    """``study --help``'s description, its numbers counted from the study itself (read only when the
    help is printed)."""
    # lazy: the study loads numpy; bikemass --help must not
    from ..analysis.engine.speeds import DEFAULT_SPEEDS
    # lazy: the study loads numpy; bikemass --help must not
    from ..study.configurations import BICYCLES, RIDERS, STIFFNESSES, configurations
    # lazy: the study loads numpy; bikemass --help must not
    from ..study.stability_tables import TOLERANCE

    grid = f"{DEFAULT_SPEEDS[2]:g} m/s grid"
    return f"""\
Reproduce Williams (2015) from the shipped data and compare every number with the thesis.

What it does, in order:
  1. riders (Table 3-4) and bicycles (Table 3-9) from their geometry;
  2. rear-frame beam models: stiffness S (Table 3-12) and natural frequencies (Tables 5-4, 5-5);
  3. the stability study, {len(configurations())} configurations (benchmark; {", ".join(BICYCLES)}
     x no rider and {len(RIDERS) - 1} poses x rigid, {", ".join(STIFFNESSES[1:])} frame), run three ways:
       thesis     as the thesis did it (published inputs, inertias added, published S,
                  {grid}), every entry of Tables 4-2..4-7 and 5-1..5-3 compared
                  (match: within {TOLERANCE:g} m/s) and every miss explained;
       corrected  the same inputs with the physics fixed (parallel-axis theorem, condensed S
                  from the beam model, exact critical speeds);
       geometry   everything from geometry.
It writes into -o/--out DIR: report.html (start there: findings, figures, tables in one file that
opens offline), report.md (the same text for diffs), stability_ranges.json (thesis run),
stability_ranges_corrected.json, stability_ranges_geometry.json, one CSV per table and,
unless --no-figures, PNG figures in figures/ (most of the time goes to them).  A summary of the
match counts is printed.
"""


def _figures_help():
    # lazy: the study loads numpy; bikemass --help must not
    from ..study.figures import figure_count
    return f"skip the {figure_count()} PNG figures (the slow part)"


def _jobs_help():
    # lazy: the study loads numpy; bikemass --help must not
    from ..study.pipeline import REFERENCE_CORES
    return (f"worker processes (default: up to {REFERENCE_CORES}, the cores of the reference machine; "
            "capped at this machine's CPU count)")


EPILOG = """\
examples:
  bikemass study                       # everything into ./study/
  bikemass study --out /tmp/s --no-figures
"""


def register(sub):
    p = sub.add_parser("study", help="reproduce the thesis end to end and write a report (the main job)",
                       description=_description, epilog=EPILOG,
                       formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("-o", "--output", "--out", metavar="DIR", default="study",
                   help="output folder (default: study/; created if missing, files replaced)")
    p.add_argument("--quiet", action="store_true", help="no progress bar and no summary on stdout")
    late_help(p.add_argument("--no-figures", action="store_true", help="skip the figures"), _figures_help)
    late_help(p.add_argument("--jobs", type=jobs, default=None, metavar="N", help="worker processes"), _jobs_help)
    p.set_defaults(run=run_study, folder_outputs=("output",))


def run_study(args):
    # lazy: the library loads numpy; bikemass --help must not
    from ..core.output import new_folder
    from ..study import pipeline
    from ..study.report import match_counts

    out = Path(args.output)
    workers = args.jobs or pipeline.WORKERS
    figures = not args.no_figures
    with Progress(pipeline.steps(figures), "study", enabled=not args.quiet) as bar, new_folder(out) as folder:
        results = pipeline.compute(workers, bar.step, folder / "figures" if figures else None)
        pipeline.write_files(results, folder)
        pipeline.write_html(results, folder, results.figure_paths)
    if not args.quiet:
        print(summary(results, match_counts(results.entries), out))
    return 0


def summary(results, counts, out):
    """The lines printed at the end: match counts, the other tables' verdicts, where the files are."""
    misses = [e for e in results.entries if not e.match]
    lines = [f"Tables 4-2..4-7, 5-1..5-3 (thesis run): {counts['all'][0]} of {counts['all'][1]} entries "
             f"within 0.05 m/s (chapter 4: {counts['chapter 4'][0]}/{counts['chapter 4'][1]}, "
             f"chapter 5: {counts['chapter 5'][0]}/{counts['chapter 5'][1]}; {counts['identical']} identical)"]
    lines += [f"  miss: {e.table[1:].replace('_', '-')} {e.row} {e.column}: {results.explanations[e]}"
              for e in misses]
    lines += [f"{t.title.split(':')[0]}: {t.notes[0]}" for t in results.input_tables if t.notes]
    lines.append(f"report: {out / 'report.html'} (the same as Markdown: {out / 'report.md'})")
    return "\n".join(lines)
