"""``report.html``: the study for readers, one self-contained file (figures embedded as PNG
data, no external resources): the findings on one page, then the reproduction tables with
their misses explained, then the details.  ``report.md`` keeps the full text for diffs."""

import base64
import html
import re

from .configurations import BICYCLES, RIDERS, THESIS_NAMES
from .report import LEGEND, match_counts, misses_sentence
from .runs import RUNS
from .stability_tables import CHAPTER4, CHAPTER5, TOLERANCE, title
from .handling import handling_findings
from .handling import handling_table
from .flexible import SPEED, flexible_table, lean_table, quasi_static_speeds
from .report import flexible_lines

STYLE = """
body { font-family: Georgia, 'Times New Roman', serif; max-width: 60em; margin: 2em auto; padding: 0 1em;
       line-height: 1.45; color: #222; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: .2em; margin-top: 2em; }
table { border-collapse: collapse; margin: .8em 0; font-size: .85em; font-family: Helvetica, Arial, sans-serif; }
th, td { border: 1px solid #ccc; padding: .2em .5em; } td.num { text-align: right; }
td.miss { background: #fde2e1; font-weight: bold; } td.ok { color: #333; }
figure { margin: 1.2em 0; text-align: center; } figure img { max-width: 100%; }
figcaption { font-size: .9em; color: #444; text-align: left; }
.findings { background: #f6f8fa; border: 1px solid #dde; padding: .5em 1.2em; }
.pair { display: flex; gap: 1em; } .pair figure { flex: 1; }
code { font-size: .9em; }
"""

KEY_BIKE = "jamis"


def _inline(text):
    """Plain text with the report's Markdown marks (``code``, **bold**) as HTML."""
    text = html.escape(str(text))
    text = re.sub(r"`([^`]+)`", r"<code>\1</code>", text)
    return re.sub(r"\*\*([^*]+)\*\*", r"<b>\1</b>", text)


def figure(png, caption):
    """An HTML figure with ``png`` (bytes) embedded as a data URI."""
    data = base64.b64encode(png).decode("ascii")
    return (f'<figure><img alt="{html.escape(caption)}" src="data:image/png;base64,{data}">'
            f"<figcaption>{_inline(caption)}</figcaption></figure>")


def table_html(t):
    """A :class:`~bikemass.study.tables.Table` as an HTML table with its title and notes."""
    head = "".join(f"<th>{_inline(h)}</th>" for h in t.headers)
    body = "".join("<tr>" + "".join(
        f'<td class="{"num" if isinstance(v, (int, float)) and not isinstance(v, bool) else ""}">'
        f"{_inline(t.cell(i, v))}</td>" for i, v in enumerate(row)) + "</tr>" for row in t.rows)
    notes = "".join(f"<p>{_inline(n)}</p>" for n in t.notes)
    return f"<h3>{_inline(t.title)}</h3><table><tr>{head}</tr>{body}</table>{notes}"


def _speed(v):
    return "-" if v is None else f"{v:.2f}"


def stability_grid_html(table, entries):
    """One thesis table: every cell ours (thesis's in brackets where it differs), misses marked."""
    mine = [e for e in entries if e.table == table]
    columns = list(dict.fromkeys(e.column for e in mine))
    rows = list(dict.fromkeys(e.row for e in mine))
    cells = {(e.row, e.column): e for e in mine}
    out = ["<table><tr><th>rider</th>" + "".join(f"<th>{html.escape(c)}</th>" for c in columns) + "</tr>"]
    for r in rows:
        out.append(f"<tr><td>{html.escape(r)}</td>")
        for c in columns:
            e = cells[r, c]
            ours, thesis = _speed(e.ours), _speed(e.thesis)
            text = ours if ours == thesis else f"{ours} ({thesis})"
            out.append(f'<td class="num {"ok" if e.match else "miss"}">{text}</td>')
        out.append("</tr>")
    return "".join(out) + "</table>"


def _ends(thesis, bike, stiffness):
    """(starts, stops) (m/s) of the riders' stable speeds on ``bike`` (thesis run, grid)."""
    ranges = [o.ranges["grid"]["strict"]["overall"] for c, o in thesis.items()
              if c.bike == bike and c.stiffness == stiffness and c.rider in RIDERS[1:]]
    return [r[0][0] for r in ranges if r], [r[-1][1] for r in ranges if r]


def thesis_findings(thesis):
    """Plain sentences: per bicycle, where the riders' stable speeds start and end on a rigid
    frame and on the softest (aluminium) one (thesis run, grid values)."""
    lines = []
    for bike in BICYCLES:
        (start, stop), (soft_start, soft_stop) = _ends(thesis, bike, "infinite"), _ends(thesis, bike, "aluminum")
        if not stop:
            lines.append(f"{THESIS_NAMES[bike]}: no rider has a stable speed range on a rigid frame.")
            continue
        text = (f"{THESIS_NAMES[bike]}, rigid frame: with a rider the stable speeds start (weave) between "
                f"{min(start):.2f} and {max(start):.2f} m/s and end (capsize) between {min(stop):.2f} and "
                f"{max(stop):.2f} m/s")
        text += (f"; aluminium frame: start {min(soft_start):.2f}..{max(soft_start):.2f}, end "
                 f"{min(soft_stop):.2f}..{max(soft_stop):.2f} m/s ({len(soft_stop)} of {len(RIDERS) - 1} riders "
                 "keep a stable range)" if soft_stop else "; with the aluminium frame no rider keeps one")
        lines.append(text + ".")
    return lines


def _handling_findings(r):
    """The findings' part on the thesis's open question (Sec. 6.1), with its figure."""
    if not r.handling:
        return []
    out = ["<h3>The thesis's open question, with a rider in the loop</h3>",
           "<p>Williams (2015, Sec. 6.1) found the Aerobars and Aero Tuck positions self-stable up to higher "
           "speeds, against riders' perception, and left the cause to control. The rider model of Hess, Moore "
           "&amp; Hubbard (2012), tuned by its published procedure at each speed, measures the rider's effort by "
           "the peak of its handling quality metric (HQM; Level 1 below 5, Level 3 above 8):</p><ul>"]
    out += [f"<li>{_inline(line)}</li>" for line in handling_findings(r.handling, r.runs["corrected"])]
    return out + ["</ul>"]


def _flexible_findings(r):
    """The findings' part on the thesis's question asked again: the frame with its inertia."""
    lines = flexible_lines(r)
    if not lines:
        return []
    return (["<h3>Does frame stiffness matter? The frame with its inertia, the fork with its compliance</h3>",
             "<p>The thesis's spring has no inertia. With the rear frame's twist and the fork's bending as degrees "
             "of freedom, stiffness and inertia from the beam models of the same tubes (docs/models-flexible.md), a "
             "steer-dominated oscillation appears, the wobble:</p><ul>"]
            + [f"<li>{_inline(line)}</li>" for line in lines] + ["</ul>"])


def _figure_or_note(figures, name, caption):
    png = figures.get(name)
    return figure(png, caption) if png is not None else ""


def render_html(results, figures):
    """The text of ``report.html``; ``figures`` = ``{file name: PNG bytes}`` of the study's figures
    (empty without figures: the text alone)."""
    r = results
    counts = match_counts(r.entries)
    misses = [e for e in r.entries if not e.match]
    explained = sum(r.explanations[e].startswith("explained") for e in misses)
    name = THESIS_NAMES[KEY_BIKE]
    out = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
           "<title>bikemass study: Williams (2015) reproduced, then corrected</title>",
           f"<style>{STYLE}</style></head><body>",
           "<h1>Frame stiffness, rider position and bicycle stability: Williams (2015) reproduced, "
           "then corrected</h1>",
           "<p>Made by <code>bikemass study</code> from the shipped bicycles, riders and materials. Thesis: "
           "R. Williams, <i>Influence of Frame Stiffness and Rider Position on Bicycle Dynamics: an Analytical "
           "Study</i>, M.S. thesis, University of Wisconsin-Milwaukee, 2015.</p>",
           "<h2>Findings</h2><div class='findings'>",
           "<h3>What the thesis found</h3><ul>"]
    out += [f"<li>{_inline(line)}</li>" for line in thesis_findings(r.runs["thesis"])]
    out += ["</ul>", "<h3>How well it is reproduced</h3>",
            f"<p>Every number of the thesis's stability Tables 4-2..4-7 and 5-1..5-3 was recomputed from the "
            f"thesis's own inputs: <b>{counts['all'][0]} of {counts['all'][1]}</b> agree within "
            f"{TOLERANCE} m/s, one step of its speed grid ({counts['identical']} identical to the printed two "
            f"decimals). " + misses_sentence(len(misses), explained, "the rounding of the printed inputs (see "
                                                     "<a href='#misses'>Misses</a>)") + "</p>",
            "<h3>What the corrections change, and by how much</h3><ul>"]
    out += [f"<li>{_inline(line)}</li>" for line in r.correction_summary]
    out += ["</ul>"] + _handling_findings(r) + _flexible_findings(r)
    out += ["</div>",
            "<div class='pair'>",
            _figure_or_note(figures, f"critical_{KEY_BIKE}_thesis.png",
                            f"{name} as the thesis computed it: stable speeds of every rider and frame "
                            "(bars, 0.05 m/s grid)."),
            _figure_or_note(figures, f"critical_{KEY_BIKE}.png",
                            f"{name} corrected (parallel-axis theorem, stiffness from the beam model, exact "
                            "speeds): circles weave speeds, squares capsize speeds."),
            "</div>",
            _figure_or_note(figures, "eig_benchmark_included_infinite.png",
                            "The benchmark bicycle (Meijaard et al. 2007): eigenvalues against speed, weave "
                            "speed v_w and capsize speed v_c marked, stable speeds shaded; the check every "
                            "result here rests on."),
            _figure_or_note(figures, f"eig_{KEY_BIKE}_relaxed_steel.png",
                            f"{name}, relaxed rider, steel frame (corrected run)."),
            _figure_or_note(figures, f"handling_{KEY_BIKE}.png",
                            f"{name}, rigid frame, every rider position ridden by the Hess, Moore & Hubbard (2012) "
                            "rider: the HQM peak against speed (Level 1 below 5), and the self-stable speeds "
                            "beneath."),
            _figure_or_note(figures, "flexible.png",
                            f"The frame and fork flexing with their inertia: the wobble's frequency at {SPEED:g} m/s "
                            "beside the published bands (filled: growing), the speeds where it is unstable beside "
                            "the weave and capsize speeds of the rigid frame, the thesis's spring and the flexible "
                            "model, and the leaning rider's weave speed beside the rigid rider's."),
            "<h2>The reproduction: thesis run against the thesis's tables</h2>",
            f"<p>{_inline(LEGEND)} Cells that miss are shaded.</p>"]
    for table in list(CHAPTER4) + list(CHAPTER5):
        out += [f"<h3>{html.escape(title(table))}</h3>", stability_grid_html(table, r.entries)]
    out += ["<h3 id='misses'>Misses</h3><ul>"]
    out += [f"<li>{html.escape(e.table[1:].replace('_', '-'))}, {html.escape(e.row)}, {html.escape(e.column)}: "
            f"ours {_speed(e.ours)}, thesis {_speed(e.thesis)} m/s: {_inline(r.explanations[e])}.</li>"
            for e in misses] or ["<li>None.</li>"]
    out += ["</ul>", "<h2>Details</h2>", "<h3>The runs</h3><ul>"]
    out += [f"<li><b>{html.escape(spec.name)}</b>: {_inline(spec.title)}.</li>" for spec in RUNS]
    out += ["</ul>", "<h3>Every bicycle by its critical speeds</h3>"]
    for bike in BICYCLES:
        for suffix, run in (("", "corrected run"), ("_thesis", "thesis run")):
            out.append(_figure_or_note(figures, f"critical_{bike.replace('-', '_')}{suffix}.png",
                                       f"{THESIS_NAMES[bike]}, {run}."))
    out.append("<h3>Eigenvalues of the relaxed rider on each frame</h3>")
    for bike in BICYCLES:
        for stiffness in ("infinite", "aluminum"):
            out.append(_figure_or_note(figures, f"eig_{bike.replace('-', '_')}_relaxed_{stiffness}.png",
                                       f"{THESIS_NAMES[bike]}, relaxed rider, "
                                       f"{'rigid' if stiffness == 'infinite' else 'aluminium'} frame (corrected run)."))
    out.append("<h3>The rider's poses</h3>")
    out += [_figure_or_note(figures, name, name[5:-4].replace("_", " ") + " on the Jamis (geometry).")
            for name in sorted(figures) if name.startswith("pose_")]
    out += ["<h3>Inputs: riders, bicycles, stiffness, frame modes</h3>"]
    out += [table_html(t) for t in r.input_tables]
    out += ["<h3>Corrections, table by table</h3>"]
    out += [table_html(t) for t in r.correction_tables]
    if r.handling:
        out += ["<h3>Handling: a rider in the loop</h3>", table_html(handling_table(r.handling, r.runs["corrected"]))]
        out += [_figure_or_note(figures, f"handling_{bike}.png", f"{THESIS_NAMES[bike]}, rigid frame: the HQM "
                                "peak of every rider position against speed (Level 1 below 5), and its self-stable "
                                "speeds beneath.") for bike in r.handling if bike != KEY_BIKE]
    if r.flexible is not None:
        speeds = quasi_static_speeds(r.flexible, r.runs["geometry"])
        out += ["<h3>Frame stiffness with the frame's inertia, and the leaning rider</h3>",
                table_html(flexible_table(r.flexible, speeds)), table_html(lean_table(r.flexible))]
    if not figures:
        out.append("<p>Drawn without figures (<code>--no-figures</code>).</p>")
    out.append("</body></html>")
    return "\n".join(x for x in out if x)
