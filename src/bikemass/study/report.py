"""``report.md``: the study's results beside the thesis's, readable on its own."""

from .runs import RUNS
from .stability_tables import CHAPTER4, CHAPTER5, TOLERANCE, compare, title
from .handling import handling_findings
from .handling import handling_table
from .flexible import damped_findings, damped_table, flexible_findings, flexible_table, lean_table, quasi_static_speeds
from .reference import wobble_bands

LEGEND = (f"Each cell: our value (m/s, first or last speed of the stable run on the 0..30 m/s grid, or "
          f"its length; `-` = no stable run), the thesis's in brackets where it differs, then "
          f"`ok` (within {TOLERANCE} m/s, one grid step) or **MISS**.")


def _speed(v):
    return "-" if v is None else f"{v:.2f}"


def _cell(entry):
    ours, thesis = _speed(entry.ours), _speed(entry.thesis)
    text = ours if ours == thesis else f"{ours} ({thesis})"
    if entry.several:
        text += " several runs"
    return f"{text} ok" if entry.match else f"**{text} MISS**"


def stability_grid(table, entries):
    """Markdown grid of one thesis table: its rows and columns, every cell ours vs thesis."""
    mine = [e for e in entries if e.table == table]
    columns = list(dict.fromkeys(e.column for e in mine))
    rows = list(dict.fromkeys(e.row for e in mine))
    cells = {(e.row, e.column): _cell(e) for e in mine}
    lines = ["| rider | " + " | ".join(columns) + " |", "|---|" + "---:|" * len(columns)]
    lines += [f"| {r} | " + " | ".join(cells[r, c] for c in columns) + " |" for r in rows]
    return "\n".join(lines) + "\n"


def _table_section(t, level="###"):
    notes = "".join(f"\n{n}\n" for n in t.notes)
    return f"{level} {t.title}\n\n{t.to_markdown()}{notes}\n(CSV: `{t.key}.csv`)\n"


def match_counts(entries):
    """``(matched, total)`` overall and for chapters 4 and 5; ``identical``: equal to the printed 2 decimals."""
    def count(prefix):
        mine = [e for e in entries if e.table.startswith(prefix)]
        return sum(e.match for e in mine), len(mine)
    identical = sum(_speed(e.ours) == _speed(e.thesis) and not e.several for e in entries)
    return {"all": count("T"), "chapter 4": count("T4"), "chapter 5": count("T5"), "identical": identical}


NUMBER_WORDS = ("no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten")


def _count(n, singular, plural=None):
    """``n`` with its noun in the right grammatical number (``one miss``, ``2 misses``)."""
    word = NUMBER_WORDS[n] if 0 <= n < len(NUMBER_WORDS) else str(n)
    return f"{word} {singular if n == 1 else plural or singular + 's'}"


def misses_sentence(misses, explained, why="the rounding of the printed inputs"):
    """One sentence on the misses and how many ``why`` explains, in the right grammatical number:
    "No entry missed.", "The one miss is explained by ...", "Of the 3 misses, 2 are explained by ..."."""
    if misses == 0:
        return "No entry missed."
    if misses == 1:
        return f"The one miss is {'' if explained else 'not '}explained by {why}."
    if explained == misses:
        return f"All {misses} misses are explained by {why}."
    if explained == 0:
        return f"Of the {misses} misses, none is explained by {why}."
    return f"Of the {misses} misses, {_count(explained, 'is', 'are')} explained by {why}."


def render(results):
    """The Markdown text of ``report.md`` for :class:`~bikemass.study.pipeline.StudyResults`."""
    r = results
    counts = match_counts(r.entries)
    misses = [e for e in r.entries if not e.match]
    explained = sum(r.explanations[e].startswith("explained") for e in misses)
    out = ["# bikemass study: Williams (2015) reproduced, then corrected\n",
           "Produced by `bikemass study` from the shipped bicycles (`frames/`), riders (`bodies/`) and "
           "materials; the thesis's printed tables (`reference/*.yaml`) are read only to compare. "
           "Thesis: R. Williams, *Influence of Frame Stiffness and Rider Position on Bicycle Dynamics: "
           "an Analytical Study*, M.S. thesis, UW-Milwaukee, 2015.\n",
           "## Summary\n",
           f"* Tables 4-2..4-7 and 5-1..5-3 (thesis run): **{counts['all'][0]} of {counts['all'][1]}** "
           f"entries within {TOLERANCE} m/s (Chapter 4: {counts['chapter 4'][0]}/{counts['chapter 4'][1]}, "
           f"Chapter 5: {counts['chapter 5'][0]}/{counts['chapter 5'][1]}; {counts['identical']} identical). "
           + misses_sentence(len(misses), explained, "the rounding of the printed parameters (see Misses)")]
    others = [f"{name} run {m} of {n}" for name in ("corrected", "geometry")
              for m, n in [match_counts(compare(r.runs[name]))["all"]]]
    out.append(f"* For contrast, against the same tables (grid values): {', '.join(others)}: the printed "
               "tables follow the thesis's own inputs and Eq. 3.6, not the corrected physics.")
    out += [f"* {t.title.split(':')[0]}: {t.notes[0]}" for t in r.input_tables if t.notes]
    out += ["* Corrections (parallel-axis theorem, condensed S from the beam model, exact critical speeds; "
            "see the section below):"]
    out += [f"  * {line}" for line in r.correction_summary]
    out += _handling_summary(r) + _flexible_summary(r) + [""]
    out += ["## The runs\n"]
    out += [f"* **{spec.name}**: {spec.title}." for spec in RUNS]
    out += ["", "The 73 configurations: the benchmark bicycle (Meijaard et al. 2007) and the Jamis, the "
            "Cargo and the loaded Cargo, each with no rider and the five poses, each with a rigid "
            "(infinite) rear frame and the frame in steel, titanium and aluminium. Mass properties of "
            "geometry parts come from the closed-form solids. Per-mode columns need the modes followed "
            "across speed: the thesis's \"weave 1\" and \"weave 2\" are the two roots that merge into the "
            "weave oscillation (docs/stability.md).\n"]
    out += ["## Stability tables: thesis run vs thesis\n", LEGEND + "\n"]
    for table in list(CHAPTER4) + list(CHAPTER5):
        out += [f"### {title(table)}\n", stability_grid(table, r.entries), f"(CSV: `table_{table[1:]}.csv`)\n"]
    out += ["### Misses\n"]
    out += [f"* {e.table[1:].replace('_', '-')}, {e.row}, {e.column}: ours {_speed(e.ours)}, thesis "
            f"{_speed(e.thesis)} m/s: {r.explanations[e]}." for e in misses] or ["None."]
    out += ["", "## Inputs: riders, bicycles, stiffness, frame modes\n"]
    out += [_table_section(t) for t in r.input_tables]
    out += _contact_section(r.contacts)
    out += ["## Corrections: what changes and by how much\n"]
    out += [f"* {line}" for line in r.correction_summary] + [""]
    out += [_table_section(t) for t in r.correction_tables]
    out += _handling_section(r)
    out += _flexible_section(r)
    out += ["## Files\n",
            "* `stability_ranges.json` (thesis run, grid ranges) and `stability_ranges_corrected.json` "
            "(corrected run, exact ranges): records `{bike, rider, stiffness, mode, criterion, start, stop, "
            "range}`, speeds in m/s, `null` where there is no stable range; mode `weave` = both weave roots "
            "stable. `stability_ranges_geometry.json`: the run from geometry (grid ranges).",
            "* one CSV per table (named under each table above);",
            "* `figures/` (unless `--no-figures`): `critical_<bike>.png` (every rider and frame by its weave "
            "and capsize speeds, corrected run) and `critical_<bike>_thesis.png` (stable speeds of the thesis "
            "run), `eig_<bike>_<rider>_<stiffness>.png` (eigenvalues against speed, corrected run), "
            "`pose_<pose>.png` (the poses on the Jamis), `handling_<bike>.png` (the rider in the loop: HQM "
            "peak against speed of every position, beside the self-stable speeds), `flexible.png` (the frame and "
            "fork flexing with their inertia: the wobble, the critical speeds beside the thesis's spring's, the "
            "leaning rider's weave speed); `handling.csv`, `flexible_wobble.csv`, `rider_lean_weave.csv`, `damped_wobble.csv`.\n"]
    return "\n".join(out)


def _handling_summary(r):
    """The summary's bullets on the thesis's open question (Sec. 6.1), answered with a rider in the loop."""
    if not r.handling:
        return []
    return ["* The thesis's open question (Sec. 6.1: Aerobars and Aero Tuck are self-stable to higher speeds, "
            "against riders' perception), with the Hess, Moore & Hubbard (2012) rider in the loop "
            "(docs/handling.md):"] + [f"  * {line}" for line in handling_findings(r.handling, r.runs["corrected"])]


def _handling_section(r):
    if not r.handling:
        return []
    return ["## Handling: a rider in the loop\n",
            "Self-stability says whether the bicycle rights itself; the rider's effort is another question. "
            "Each rider position on the Jamis and the Cargo (corrected run, rigid frame) is ridden by the Hess, "
            "Moore & Hubbard (2012) rider, tuned by the published procedure at each speed; the handling quality "
            "metric's peak measures the rate feedback the rider must supply (docs/handling.md).\n",
            _table_section(handling_table(r.handling, r.runs["corrected"]))]


def flexible_lines(r):
    """The findings on frame stiffness with the frame's inertia (:mod:`~bikemass.study.flexible`)."""
    if r.flexible is None:
        return []
    return flexible_findings(r.flexible, quasi_static_speeds(r.flexible, r.runs["geometry"]), wobble_bands())


def _flexible_summary(r):
    """The summary's bullets on the thesis's own question asked again, the frame with its inertia."""
    lines = flexible_lines(r)
    if not lines:
        return []
    return ["* The thesis's question asked again, with the frame's inertia and the fork's compliance (the `flexible` "
            "model, docs/models-flexible.md; geometry bicycles and riders):"] + [f"  * {line}" for line in lines]


def _flexible_section(r):
    if r.flexible is None:
        return []
    speeds = quasi_static_speeds(r.flexible, r.runs["geometry"])
    return ["## Frame stiffness with the frame's inertia: wobble, and the leaning rider\n",
            "The thesis's spring has no inertia and stands between gravity and the bicycle's roll and steer. Here the "
            "rear frame twists and the fork bends as degrees of freedom of their own, stiffness and inertia from the "
            "beam models of the same tubes, in every material (the `flexible` model, docs/models-flexible.md); the "
            "geometry run's bicycles and riders. The wobble is the steer-dominated oscillation this brings. Beside it, "
            "the leaning rider (the `rider-lean` model): the upper body on a hip spring and damper.\n",
            *[f"* {line}" for line in flexible_lines(r)], "",
            _table_section(flexible_table(r.flexible, speeds)), _table_section(lean_table(r.flexible)),
            *_damped_section(r)]


def _damped_section(r):
    """The thesis's question again with the damping and the arms (:func:`~bikemass.study.flexible.damped_table`)."""
    if not r.flexible.damped:
        return []
    return ["## The wobble with damping and the arms\n",
            "The question once more, with the published wobble models' structure (compliance plus tyres) and every "
            "published default: the steering bearings' measured damping, force-only tyres, and the rider's arms "
            "(docs/models.md). For every bicycle, rider position and material: the wobble's frequency and its "
            "onset speed.\n",
            *[f"* {line}" for line in damped_findings(r.flexible)], "",
            _table_section(damped_table(r.flexible))]


def _contact_section(contacts):
    """How far the thesis's riders sit from each bicycle's saddle, grips and pedals (kept as placed)."""
    if not contacts:
        return []
    rows = ["| rider | bicycle | hips (mm) | hands (mm) | feet (mm) |", "| --- | --- | --- | --- | --- |"]
    for (pose, bike), found in contacts.items():
        if not found:                     # lumped published riders: no contact points
            continue
        worst = {part: max((gap for name, (gap, _) in found.items() if name.endswith(part)), default=None)
                 for part in ("hips", "hand", "foot")}
        rows.append(f"| {pose} | {bike} | " + " | ".join("-" if g is None else f"{g * 1000:.1f}"
                                                        for g in worst.values()) + " |")
    return ["### Rider contacts as the thesis placed them\n",
            "The geometry run keeps the Table 3-3 riders where the thesis put them "
            "(`--allow-off-contact`, docs/riders.md); their largest distances from each bicycle's "
            "contacts (hands: the nearest grip; \"-\": hands free):\n", *rows, ""]
