"""What changes when the thesis's physical errors are corrected: inputs and stable ranges, side by side."""

from .configurations import BENCHMARK, BENCHMARK_RIDER, RIDERS
from .frame_tables import ENTRIES
from .frames import MATERIALS
from .runs import CRITERIA
from .tables import Table

INERTIAS = ("IBxx", "IByy", "IBzz", "IBxz")
CHANGE = 0.05
"""m/s: a range end that moves by more than one grid step counts as changed."""


def inertia_table(thesis, corrected):
    """Rear frame + rider inertia (kg m^2): Eq. 3.6 (thesis) vs parallel-axis theorem (corrected)."""
    rows, seen = [], set()
    for c, o in thesis.items():
        key = (c.bike, c.rider)
        if c.bike == BENCHMARK or c.rider == "none" or key in seen:
            continue
        seen.add(key)
        p, q = o.parameters, corrected[c].parameters
        row = [c.bike, c.rider]
        for name in INERTIAS:
            a, b = getattr(p, name), getattr(q, name)
            row += [a, b, b - a]
        rows.append(row)
    headers = ["bike", "rider"] + [h for n in INERTIAS for h in (f"{n} thesis", f"{n} corrected", "change")]
    return Table("corrections_inertia", "Rear frame + rider inertia (kg m^2): inertias added (Eq. 3.6) vs "
                 "parallel-axis theorem", tuple(headers), rows,
                 formats={i: "{:+.3f}" for i in range(4, len(headers), 3)},
                 notes=("Masses and centres of mass are the same both ways; only the inertias differ, by "
                        "the reduced mass times the squared distance between the rider's and the "
                        "frame's centres of mass.",))


def stiffness_table(thesis, corrected):
    """S (N m/rad): published Table 3-12 (as the ``*-thesis`` bicycles carry it) vs condensed beam model."""
    rows, seen = [], set()
    for c, o in thesis.items():
        key = (c.bike, c.stiffness)
        if c.stiffness not in MATERIALS or key in seen:
            continue
        seen.add(key)
        S, T = o.S, corrected[c].S
        for name, i, j in ENTRIES:
            rows.append([c.bike, c.stiffness, name, float(S[i, j]), float(T[i, j]),
                         100 * (T[i, j] - S[i, j]) / abs(S[i, j])])
    return Table("corrections_stiffness", "Rear-frame stiffness S (N m/rad): published (thesis run) vs "
                 "condensed from the beam model (corrected run)",
                 ("bike", "material", "entry", "thesis run", "corrected run", "change (%)"), rows,
                 formats={3: "{:.1f}", 4: "{:.1f}", 5: "{:+.1f}"})


def _fmt(ranges):
    return ", ".join(f"{a:.2f}..{b:.2f}" for a, b in ranges) or "none"


def _shift(a, b):
    """(start, stop) changes (m/s) between single ranges ``a`` and ``b``, or Nones."""
    if len(a) == 1 and len(b) == 1:
        return b[0][0] - a[0][0], b[0][1] - a[0][1]
    return None, None


def range_table(thesis, corrected, geometry):
    """Overall stable ranges per configuration and criterion: thesis run (grid) vs corrected (exact),
    and the run from geometry (grid)."""
    rows = []
    for c, o in thesis.items():
        for criterion in CRITERIA:
            a = o.ranges["grid"][criterion]["overall"]
            b = corrected[c].ranges["exact"][criterion]["overall"]
            rows.append([c.bike, c.rider, c.stiffness, criterion, _fmt(a), _fmt(b), *_shift(a, b),
                         _fmt(geometry[c].ranges["grid"][criterion]["overall"])])
    headers = ["bike", "rider", "stiffness", "criterion", "thesis run (grid)", "corrected (exact)",
               "start change", "stop change", "from geometry (grid)"]
    return Table("corrections_ranges", "Stable speed ranges (m/s, all modes): thesis run vs corrected run",
                 tuple(headers), rows, formats={6: "{:+.2f}", 7: "{:+.2f}"})


def _changes(thesis, corrected, criterion, configurations):
    """(changed, gained, lost, largest shift) of the overall ranges over ``configurations``."""
    changed, gained, lost, shifts = 0, 0, 0, []
    for c in configurations:
        a = thesis[c].ranges["grid"][criterion]["overall"]
        b = corrected[c].ranges["exact"][criterion]["overall"]
        gained += not a and bool(b)
        lost += bool(a) and not b
        start, stop = _shift(a, b)
        if start is not None:
            shifts.append((max(abs(start), abs(stop)), c, start, stop))
            changed += max(abs(start), abs(stop)) > CHANGE
    return changed, gained, lost, max(shifts, key=lambda s: s[0]) if shifts else None


def summary(thesis, corrected):
    """Plain-language lines: how many ranges move, appear or vanish, and the largest shifts.

    Rigid-frame configurations change only by the parallel-axis theorem (and exact ends);
    the flexible ones also by the condensed, computed S.
    """
    lines = []
    groups = (("rigid frame (parallel axis only)", [c for c in thesis if c.stiffness == "infinite"]),
              ("flexible frame (parallel axis and computed S)", [c for c in thesis if c.stiffness != "infinite"]))
    for criterion in CRITERIA:
        for name, group in groups:
            changed, gained, lost, worst = _changes(thesis, corrected, criterion, group)
            text = (f"{criterion}, {name}: of {len(group)} configurations {changed} keep a stable range whose "
                    f"start or stop moves by more than {CHANGE} m/s, {gained} gain one and {lost} lose it")
            if worst is not None:
                text += f"; largest shift {worst[1].label} (start {worst[2]:+.2f}, stop {worst[3]:+.2f} m/s)"
            lines.append(text + ".")
    ratios = [corrected[c].parameters.IBxx / o.parameters.IBxx
              for c, o in thesis.items() if c.rider not in ("none", BENCHMARK_RIDER)]
    lines.append(f"Parallel-axis theorem: the rear frame + rider roll inertia IBxx grows by "
                 f"{100 * (min(ratios) - 1):.0f} to {100 * (max(ratios) - 1):.0f} % over the "
                 f"{len(RIDERS) - 1} riders on the three bicycles.")
    cargo = [(corrected[c].S[0, 1] - o.S[0, 1]) / o.S[0, 1] for c, o in thesis.items()
             if c.bike == "cargo" and o.S is not None]
    if cargo:
        spread = sorted({f"{100 * x:+.0f} %" for x in cargo})
        lines.append(f"The Cargo's computed S also carries the error of its reconstructed beam model "
                     f"(K_phidelta {' to '.join(spread[::len(spread) - 1 or 1])} against Table 3-12): "
                     "for the Cargo the flexible-frame results are a what-if on that model.")
    return lines
