"""The thesis's question asked again: with the frame's inertia and the fork's compliance, does frame
stiffness matter?

Williams (2015) put the frame's stiffness into the Whipple bicycle as a quasi-static spring without
inertia (Eq. 3.27-3.30; the study's ``geometry`` run with the condensed S of the beam model).  Here
the same geometry bicycles and Table 3-3 riders (as the geometry run builds them) are analysed with
the ``flexible`` member of the model family (docs/models-flexible.md): the rear frame's twist and the
fork's bending as degrees of freedom, stiffness and inertia from the beam models of the same tubes,
in every material.  For each bicycle, rider and material: the wobble (the steer-dominated
oscillation of the compliances' family) by its frequency at :data:`SPEED` and the speeds at which it
is unstable, and the weave and capsize speeds beside those of the rigid frame and the thesis's
spring.  And the rider: the leaning rider (``rider-lean``, the upper body on a hip spring and
damper) against the rigid rider, rigid frame, by the weave speed.

And once more with the damping and the arms (:data:`DAMPED_MODEL`): the published wobble models'
structure, compliance plus tyres, with every published default (the steering bearings' measured
damping, force-only tyres) and the rider's arms at their published values (none could be read: zero,
so the model without them; docs/models.md, "The rider's arms").

The compliances are computed once per bicycle and material (:func:`compliances_of`).
"""

from dataclasses import dataclass, field

import numpy as np

from ..analysis.engine.critical import critical_speeds
from ..analysis.engine.crossings import OSCILLATORY, REAL
from ..analysis.engine.naming import family
from ..analysis.engine.speeds import speed_grid
from ..analysis.engine.stability import WOBBLE, analyse
from ..fe.flexible import compliances
from ..models.members.arms import MEMBER as ARMS
from ..models.members.arms.parameters import NO_ARMS
from ..models.members.flexible import MEMBER as FLEXIBLE
from ..models.members.tyre import MEMBER as TYRE
from ..models.registry import model_of, parse_model
from ..models.family import build
from ..models.members.rider_lean.parameters import LeanJoint
from ..models.whipple import whipple_model
from ..rider.lean_split import rider_lean_parameters
from .configurations import RIDERS, THESIS_NAMES, Configuration
from .frames import MATERIALS
from .runs import GEOMETRY, METHOD
from .tables import Table

BICYCLES = ("jamis", "cargo")
"""The bicycles the question is asked of (the geometry bicycles: their tubes give the compliances)."""
POSES = RIDERS[1:]
"""The thesis's five rider positions."""
SPEED = 8.0
"""Speed (m/s) at which the wobble's frequency and growth rate are stated (docs/models-flexible.md)."""
STEER = "steer-angle"
FLEXIBLE_MODEL = parse_model(FLEXIBLE.name)
"""The model of the study's wobble: the flexible frame and fork."""
DAMPED_MODEL = parse_model("+".join((TYRE.name, FLEXIBLE.name, ARMS.name)))
"""The model of the study's damped wobble: compliance, tyres and the arms with their defaults."""
NO_HANDS_MODEL = parse_model("+".join((TYRE.name, FLEXIBLE.name)))
"""The damped model of the no-hands rider: without the arms."""


@dataclass(frozen=True)
class Wobble:
    """The flexible model of one bicycle, rider and material, in plain numbers.

    Attributes
    ----------
    frequency : float or None
        The wobble's frequency (Hz) at :data:`SPEED`; ``None``: no steer-dominated oscillation in
        the compliances' family.
    growth : float or None
        Its real part (1/s) at :data:`SPEED` (positive: it grows).
    unstable : tuple
        ``((start, stop), ...)`` (m/s) where the wobble is unstable, on the analysed span.
    weave_speeds, capsize_speeds, wobble_speeds : tuple
        The flexible model's critical speeds (m/s; :class:`~bikemass.analysis.engine.stability.StabilityResult`).
    stable : tuple
        ``((start, stop), ...)`` (m/s) where every mode of the flexible model is stable (exact).
    span : tuple
        ``(lo, hi)`` (m/s): the speeds analysed.
    """

    frequency: float
    growth: float
    unstable: tuple
    weave_speeds: tuple
    capsize_speeds: tuple
    wobble_speeds: tuple
    stable: tuple
    span: tuple


@dataclass(frozen=True)
class Lean:
    """The leaning rider against the rigid rider (rigid frame): critical speeds (m/s) and stable ranges."""

    weave_speeds: tuple
    capsize_speeds: tuple
    stable: tuple
    rigid_weave_speeds: tuple
    rigid_capsize_speeds: tuple
    rigid_stable: tuple


@dataclass(frozen=True)
class FlexibleResults:
    """``wobble[(bike, rider, material)]``: :class:`Wobble`; ``lean[(bike, rider)]``: :class:`Lean`;
    ``damped[(bike, rider, material)]``: :class:`Wobble` of :data:`DAMPED_MODEL` (hands on the bars;
    the no-hands rider without the arms member)."""

    wobble: dict
    lean: dict
    damped: dict = field(default_factory=dict)


def _pairs(ranges):
    return tuple((float(a), float(b)) for a, b in ranges)


def complement(ranges, lo, hi):
    """The parts of ``[lo, hi]`` outside the sorted ``ranges`` ``((start, stop), ...)``."""
    out, at = [], lo
    for a, b in ranges:
        if a > at:
            out.append((at, a))
        at = max(at, b)
    if at < hi:
        out.append((at, hi))
    return tuple(out)


def wobble_mode(result, speed=SPEED):
    """``(label, eigenvalue)`` of the wobble at ``speed`` (on the result's grid): of the tracked
    oscillations of the compliances' family, the slowest whose shape (the coordinates' part of its
    eigenvector) is largest in steer; else (with the tyres, whose states share the shape) the
    oscillation the engine labels ``wobble 1``/``wobble 2``; ``None`` if there is neither."""
    speeds = result.speeds
    k = np.flatnonzero(np.isclose(speeds, speed, rtol=0.0, atol=1e-9))
    if not len(k):
        raise ValueError(f"speed {speed} m/s is not on the analysed grid")
    k = int(k[0])
    names = [s.name for s in result.model.dynamic_states]
    coordinates = [i for i, n in enumerate(names) if not n.endswith("-rate")]
    best = None
    for c, label in enumerate(result.labels):
        value = result.eigenvalues[k, c]
        if family(label) != WOBBLE or value.imag <= 0:
            continue
        shape = np.abs(result.modes.eigenvectors[k, coordinates, c])
        if names[coordinates[int(np.argmax(shape))]] == STEER and (best is None or value.imag < best[1].imag):
            best = (label, complex(value))
    if best is None:
        # with the tyres the wobble is the oscillation the engine labels by what moves at its reference
        # speed (engine.naming.wobble_columns), whose shape the tyres' states share
        for c, label in enumerate(result.labels):
            value = result.eigenvalues[k, c]
            if label in ("wobble 1", "wobble 2") and value.imag > 0:
                best = (label, complex(value))
    return best


def wobble(model, speeds=None, speed=SPEED):
    """:class:`Wobble` of a flexible :class:`~bikemass.models.linear.LinearModel` over ``speeds``
    (m/s; default the thesis's 0..30 m/s grid, which must hold ``speed``)."""
    result = analyse(model, speed_grid() if speeds is None else speeds)
    found = wobble_mode(result, speed)
    lo, hi = float(result.speeds[0]), float(result.speeds[-1])
    if found is None:
        frequency = growth = None
        unstable = ()
    else:
        label, value = found
        frequency, growth = value.imag / (2 * np.pi), value.real
        unstable = complement(_pairs(result.mode_ranges[label]["strict"]["exact"]), lo, hi)
    return Wobble(frequency, growth, unstable, tuple(result.weave_speeds), tuple(result.capsize_speeds),
                  tuple(result.wobble_speeds), _pairs(result.stable_speeds), (lo, hi))


def whipple_speeds(model):
    """``(weave speeds, capsize speeds, stable ranges)`` (m/s) of a roll-and-steer model on 0..30 m/s
    (exact; an oscillatory crossing of the Whipple bicycle is weave, a real one capsize)."""
    found = critical_speeds(model)
    return (tuple(c.speed for c in found.crossings if c.kind == OSCILLATORY),
            tuple(c.speed for c in found.crossings if c.kind == REAL), _pairs(found.stable))


def lean(parameters):
    """:class:`Lean` of :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` (rigid frame)."""
    result = analyse(build(model_of(parameters), parameters))
    weave = tuple(c.speed for c in result.mode_crossings("weave 1") if c.kind == OSCILLATORY)
    capsize = tuple(c.speed for c in result.mode_crossings("capsize") if c.kind == REAL)
    return Lean(weave, capsize, _pairs(result.stable_speeds), *whipple_speeds(build("whipple", parameters)))


def compliances_of(inputs, bicycles=BICYCLES, materials=MATERIALS):
    """``{(bike, material): Compliances}`` of the geometry bicycles' frames and forks (each once)."""
    return {(b, m): compliances(inputs.bicycle(b), inputs.material(m)) for b in bicycles for m in materials}


def damped_model(params, compliances, rider):
    """:data:`DAMPED_MODEL` of a parameter set and compliances, the arms at their default
    (:data:`~bikemass.models.members.arms.parameters.NO_ARMS`: no published value; the table's notes say so); the
    no-hands rider (hands off the bars) without the arms member."""
    if rider == "no-hands":
        return build(NO_HANDS_MODEL, params, compliances=compliances)
    return build(DAMPED_MODEL, params, compliances=compliances, arms=NO_ARMS)


def flexible_results(inputs, bicycles=BICYCLES, riders=POSES, materials=MATERIALS):
    """:class:`FlexibleResults` of every bicycle, rider and material (the geometry run's inputs)."""
    flexible = compliances_of(inputs, bicycles, materials)
    wobbles, leans, damped = {}, {}, {}
    for bike in bicycles:
        for rider in riders:
            params = inputs.parameters(GEOMETRY, Configuration(bike, rider, "infinite"))
            for material in materials:
                wobbles[bike, rider, material] = wobble(build(FLEXIBLE_MODEL, params,
                                                              compliances=flexible[bike, material]))
                damped[bike, rider, material] = wobble(damped_model(params, flexible[bike, material], rider))
            leans[bike, rider] = lean(rider_lean_parameters(inputs.bicycle(bike), inputs.rider(rider, bike),
                                                            METHOD))
    return FlexibleResults(wobbles, leans, damped)


def spring_speeds(geometry, bike, rider, stiffness):
    """``(weave, capsize, stable)`` (m/s, exact) of the geometry run's configuration: the rigid frame
    (``"infinite"``) or the thesis's quasi-static spring of the frame in ``stiffness``."""
    outcome = geometry[Configuration(bike, rider, stiffness)]
    return whipple_speeds(whipple_model(outcome.parameters, outcome.S))


def quasi_static_speeds(results, geometry):
    """``{(bike, rider, stiffness): (weave, capsize, stable)}`` (m/s) of the geometry run's rigid frame
    (``"infinite"``) and thesis's spring in every material of ``results``, the flexible model's peers."""
    keys = {(b, r, s) for b, r, m in results.wobble for s in ("infinite", m)}
    return {k: spring_speeds(geometry, *k) for k in sorted(keys)}


def _first(speeds):
    return speeds[0] if speeds else None


def _ranges(ranges):
    return ", ".join(f"{a:.2f}..{b:.2f}" for a, b in ranges) or "-"


def flexible_table(results, speeds):
    """The wobble table: per bicycle, rider and material the flexible model's wobble (frequency and
    growth at :data:`SPEED`, unstable speeds), and the first weave and capsize speeds and the stable
    speeds of the rigid frame, the thesis's spring (``speeds``: :func:`quasi_static_speeds`) and the
    flexible model."""
    rows = []
    for (bike, rider, material), w in results.wobble.items():
        rigid, spring = speeds[bike, rider, "infinite"], speeds[bike, rider, material]
        flexible = (w.weave_speeds, w.capsize_speeds, w.stable)
        rows.append([THESIS_NAMES[bike], THESIS_NAMES[rider], THESIS_NAMES[material], w.frequency, w.growth,
                     _first(w.unstable)[0] if w.unstable else None, _ranges(w.unstable),
                     *(f(s) for s in (rigid, spring, flexible) for f in (lambda s: _first(s[0]),
                                                                        lambda s: _first(s[1]))),
                     *(_ranges(s[2]) for s in (rigid, spring, flexible))])
    headers = ("bicycle", "rider", "material", f"wobble at {SPEED:g} m/s (Hz)", f"wobble growth at {SPEED:g} m/s (1/s)",
               "wobble unstable from (m/s)", "wobble unstable (m/s)",
               "rigid weave (m/s)", "rigid capsize (m/s)", "spring weave (m/s)", "spring capsize (m/s)",
               "flexible weave (m/s)", "flexible capsize (m/s)",
               "rigid stable (m/s)", "spring stable (m/s)", "flexible stable (m/s)")
    formats = {3: "{:.2f}", 4: "{:.2f}", **{i: "{:.2f}" for i in range(5, 13)}}
    return Table("flexible_wobble", "Frame stiffness with the frame's inertia: the wobble and the critical speeds "
                 "of the rigid frame, the thesis's spring and the flexible frame and fork", headers, rows, formats,
                 notes=("Geometry bicycles and Table 3-3 riders as the geometry run builds them. Spring: the "
                        "thesis's quasi-static frame (Eq. 3.27-3.30) with S condensed from the beam model; flexible: "
                        "the rear frame's twist and the fork's bending with their tubes' inertia, stiffness from the "
                        "beam models of the same tubes (docs/models-flexible.md); damped only in the steering "
                        "bearings (0.34 N m s/rad, measured). Wobble: the "
                        "steer-dominated oscillation of the compliances' family. Weave and capsize: the first "
                        "crossing on 0..30 m/s; '-': none.",))


def damped_table(results):
    """The damped wobble's table: per bicycle, rider and material the wobble of :data:`DAMPED_MODEL`
    (frequency and growth at :data:`SPEED`, onset: the lowest speed it is unstable from, the speeds it
    is unstable at) beside the onset without the tyres' (the ``flexible`` table's), and the damped
    model's stable speeds."""
    rows = []
    for (bike, rider, material), w in results.damped.items():
        plain = results.wobble.get((bike, rider, material))
        rows.append([THESIS_NAMES[bike], THESIS_NAMES[rider], THESIS_NAMES[material], w.frequency, w.growth,
                     w.unstable[0][0] if w.unstable else None, _ranges(w.unstable),
                     plain.unstable[0][0] if plain is not None and plain.unstable else None, _ranges(w.stable)])
    headers = ("bicycle", "rider", "material", f"wobble at {SPEED:g} m/s (Hz)",
               f"wobble growth at {SPEED:g} m/s (1/s)", "wobble onset (m/s)", "wobble unstable (m/s)",
               "onset without tyres (m/s)", "stable (m/s)")
    return Table("damped_wobble", "The wobble with the damping and the arms: compliance, tyres and the arms with "
                 "every published default", headers, rows, {i: "{:.2f}" for i in (3, 4, 5, 7)},
                 notes=("The tyre+flexible+arms model (docs/models.md) of the geometry bicycles and riders: the "
                        "rear frame's twist and the fork's bending (beam models of the tubes, in each material), "
                        "tyres that slip (the default force-only tyres, no tyre moments: none has a published "
                        "default), the steering bearings' measured damping (0.34 N m s/rad, Moore 2012) and no "
                        "structural damping (no published loss factor for a bicycle frame). The arms: no "
                        "published stiffness or damping about the steer axis could be read, so both are 0 (the "
                        "model without them) and the forearms' mass stays where the pose puts it (the thesis's "
                        "riders, placed as it placed them, do not hold the grips to 1 mm); the no-hands rider has "
                        "no arms member. Wobble: the oscillation the engine names wobble by what moves at "
                        f"{SPEED:g} m/s. Onset: the lowest speed of 0..30 m/s it is unstable from; '-': none.",))


def damped_findings(results):
    """Sentences on the damped wobble (:func:`damped_table`): how many combinations it is unstable in,
    its onsets per bicycle, and what a stiffer material does to its frequency and onset."""
    damped = results.damped
    if not damped:
        return []
    lines = []
    unstable = [k for k, w in damped.items() if w.unstable]
    lines.append(f"With the damping and the arms at their published defaults the wobble is unstable somewhere on "
                 f"0..30 m/s in {len(unstable)} of {len(damped)} bicycle x rider x material combinations.")
    for bike in dict.fromkeys(k[0] for k in damped):
        onsets = [w.unstable[0][0] for k, w in damped.items() if k[0] == bike and w.unstable]
        frequencies = [w.frequency for k, w in damped.items() if k[0] == bike and w.frequency is not None]
        where = (f"its onset lies at {min(onsets):.2f}..{max(onsets):.2f} m/s"
                 + (" (below 2 m/s in every case)" if max(onsets) < 2.0 else "") if onsets else
                 "it is damped at every speed")
        band = f"{min(frequencies):.2f}..{max(frequencies):.2f} Hz" if frequencies else "no wobble named"
        lines.append(f"{THESIS_NAMES[bike]}: the wobble is {band} at {SPEED:g} m/s; {where}.")
    materials = list(dict.fromkeys(k[2] for k in damped))
    if len(materials) > 1:
        stiff, soft = materials[0], materials[1]
        higher = lower_onset = pairs = 0
        for (bike, rider, material), w in damped.items():
            other = damped.get((bike, rider, soft))
            if material != stiff or other is None or w.frequency is None or other.frequency is None:
                continue
            pairs += 1
            higher += w.frequency > other.frequency
            a = w.unstable[0][0] if w.unstable else np.inf
            b = other.unstable[0][0] if other.unstable else np.inf
            lower_onset += a < b
        lines.append(f"{THESIS_NAMES[stiff]} against {THESIS_NAMES[soft]}: the stiffer frame and fork raises the "
                     f"wobble's frequency in {higher} of {pairs} bicycle x rider pairs and lowers its onset in "
                     f"{lower_onset}.")
    return lines


def lean_table(results):
    """The leaning rider's table: per bicycle and rider the weave and capsize speeds and the stable
    speeds of the rigid rider and the leaning rider (rigid frame)."""
    rows = []
    for (bike, rider), x in results.lean.items():
        rigid, leaning = _first(x.rigid_weave_speeds), _first(x.weave_speeds)
        rows.append([THESIS_NAMES[bike], THESIS_NAMES[rider], rigid, leaning,
                     None if rigid is None or leaning is None else leaning - rigid,
                     _first(x.rigid_capsize_speeds), _first(x.capsize_speeds),
                     _ranges(x.rigid_stable), _ranges(x.stable)])
    headers = ("bicycle", "rider", "rigid rider weave (m/s)", "leaning rider weave (m/s)", "weave change (m/s)",
               "rigid rider capsize (m/s)", "leaning rider capsize (m/s)", "rigid rider stable (m/s)",
               "leaning rider stable (m/s)")
    joint = LeanJoint()
    return Table("rider_lean_weave", "The leaning rider against the rigid rider (rigid frame)", headers, rows,
                 {i: "{:.2f}" for i in range(2, 7)},
                 notes=(f"The upper body leans about the hip axis against {joint.stiffness:g} N m/rad and "
                        f"{joint.damping:g} N m s/rad (de Lorenzo & Hubbard 1996 via Moore 2012; docs/models.md); "
                        "legs and pelvis stay with the rear frame.",))


def _span(values, digits=2):
    lo, hi = min(values), max(values)
    return f"{lo:+.{digits}f}" if abs(hi - lo) < 0.5 * 10 ** -digits else f"{lo:+.{digits}f}..{hi:+.{digits}f}"


def _band_words(frequencies, bands):
    """Where ``frequencies`` (Hz) land beside each of the published ``bands``."""
    lo, hi = min(frequencies), max(frequencies)

    def where(band):
        if band["low"] <= lo and hi <= band["high"]:
            return "inside"
        return "below" if hi < band["low"] else "above" if lo > band["high"] else "partly inside"
    return ", ".join(f"{where(b)} the {b['low']:g}-{b['high']:g} Hz of {b['name']}" for b in bands)


def _unstable_words(wobbles):
    """How the wobbles of one bicycle and material are unstable: everywhere, above a speed, or not."""
    everywhere = [r for r, w in wobbles.items() if w.unstable and w.unstable[0][0] <= w.span[0]
                  and w.unstable[-1][1] >= w.span[1]]
    never = [r for r, w in wobbles.items() if not w.unstable]
    above = {r: w.unstable[0][0] for r, w in wobbles.items() if r not in everywhere and r not in never}
    parts = []
    if everywhere:
        parts.append(("every rider" if len(everywhere) == len(wobbles) else
                      ", ".join(THESIS_NAMES[r] for r in everywhere)) + " unstable at every speed")
    parts += [f"{THESIS_NAMES[r]} unstable from {v:.2f} m/s" for r, v in above.items()]
    if never:
        parts.append(("every rider" if len(never) == len(wobbles) else ", ".join(THESIS_NAMES[r] for r in never))
                     + f" stable up to {max(wobbles[r].span[1] for r in never):g} m/s")
    return "; ".join(parts)


def _shifts(results, speeds, which):
    """``(spring, flexible)``: the changes (m/s) of the first weave (``which`` 0) or capsize (1) speed
    from the rigid frame's, over every combination where both have one."""
    spring, flexible = [], []
    for (bike, rider, material), w in results.wobble.items():
        rigid = speeds[bike, rider, "infinite"][which]
        if not rigid:
            continue
        for out, found in ((spring, speeds[bike, rider, material][which]),
                           (flexible, (w.weave_speeds, w.capsize_speeds)[which])):
            if found:
                out.append(found[0] - rigid[0])
    return spring, flexible


def _against(spring, flexible):
    """How the flexible model moves a speed (m/s changes) beside the thesis's spring, in words."""
    if max(spring) < 0 < min(flexible):
        return f"goes up ({_span(flexible)} m/s) where the spring takes it down ({_span(spring)} m/s)"
    if max(flexible) < 0 < min(spring):
        return f"goes down ({_span(flexible)} m/s) where the spring takes it up ({_span(spring)} m/s)"
    return f"moves by {_span(flexible)} m/s (the spring: {_span(spring)} m/s)"


def flexible_findings(results, speeds, bands):
    """Plain sentences answering "does frame stiffness matter?" from the numbers: per bicycle the
    wobble by material, the leaning rider's effect on weave, and the answer.  ``speeds``:
    :func:`quasi_static_speeds`; ``bands`` the published wobble bands (``[{"name", "low", "high"}]``,
    Hz; :func:`bikemass.study.reference.wobble_bands`), read only to say where the wobble lands."""
    lines = []
    bikes = list(dict.fromkeys(b for b, _, _ in results.wobble))
    materials = list(dict.fromkeys(m for _, _, m in results.wobble))
    for bike in bikes:
        parts = []
        for material in materials:
            mine = {r: w for (b, r, m), w in results.wobble.items() if b == bike and m == material}
            freqs = [w.frequency for w in mine.values() if w.frequency is not None]
            if freqs:
                parts.append(f"{THESIS_NAMES[material].lower()} {min(freqs):.1f}-{max(freqs):.1f} Hz "
                             f"({_band_words(freqs, bands)}), {_unstable_words(mine)}")
            else:
                parts.append(f"{THESIS_NAMES[material].lower()}: no steer-dominated oscillation")
        lines.append(f"{THESIS_NAMES[bike]}, frame and fork flexing with their inertia, the wobble at {SPEED:g} m/s: "
                     + "; ".join(parts) + ".")
    lean_parts = []
    for bike in dict.fromkeys(b for b, _ in results.lean):
        moved = [x.weave_speeds[0] - x.rigid_weave_speeds[0] for (b, _), x in results.lean.items()
                 if b == bike and x.weave_speeds and x.rigid_weave_speeds]
        if moved:
            lean_parts.append(f"{THESIS_NAMES[bike]} {_span(moved)} m/s")
    if lean_parts:
        lines.append("The leaning rider (upper body on a hip spring and damper, rigid frame) moves the weave speed "
                     "from the rigid rider's by " + ", ".join(lean_parts) + ".")
    (spring_w, flexible_w), (spring_c, flexible_c) = _shifts(results, speeds, 0), _shifts(results, speeds, 1)
    if not (spring_c and flexible_c and spring_w and flexible_w):
        return lines
    unstable = sum(bool(w.unstable) for w in results.wobble.values())
    hi = max(w.span[1] for w in results.wobble.values())
    self_stable = [k for k in results.wobble if speeds[k[0], k[1], "infinite"][2]]
    kept = sum(bool(results.wobble[k].stable) for k in self_stable)
    decided = sorted({(b, r) for (b, r, m), w in results.wobble.items() if not w.unstable}
                     & {(b, r) for (b, r, m), w in results.wobble.items() if w.unstable})
    ratio = [results.wobble[b, r, materials[-1]].frequency / results.wobble[b, r, materials[0]].frequency
             for b, r, m in results.wobble if m == materials[0]
             and results.wobble[b, r, m].frequency and results.wobble[b, r, materials[-1]].frequency]
    text = ("Does frame stiffness matter? " + ("Yes, but not as the thesis's spring says" if unstable else
                                                 "Not as the thesis's spring says")
            + f": with the frame's inertia the capsize speed {_against(spring_c, flexible_c)}, the weave speed "
            f"{_against(spring_w, flexible_w)}; the wobble, which the spring cannot show, "
            f"{'is unstable somewhere up to ' + format(hi, 'g') + ' m/s in ' if unstable else 'is stable in '}"
            f"{unstable if unstable else len(results.wobble)} of {len(results.wobble)} combinations of bicycle, rider "
            f"and material, and from {THESIS_NAMES[materials[0]].lower()} to {THESIS_NAMES[materials[-1]].lower()} "
            f"its frequency falls to {min(ratio):.2f}-{max(ratio):.2f} of its value")
    if decided:
        text += ("; the material decides whether it is unstable at all for " + ", ".join(
            f"{THESIS_NAMES[b]} {THESIS_NAMES[r]}" for b, r in decided))
    text += (f"; of the {len(self_stable)} combinations self-stable somewhere on a rigid frame, {kept} keep a "
             "self-stable speed (the model's only damping is the steering bearings': tyres, the rider's arms and the "
             "structure damp a real wobble).")
    return lines + [text]
