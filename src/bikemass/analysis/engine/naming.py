"""Naming tracked modes from their physics: weave, capsize, caster, and the modes of richer models.

At standstill (``v = 0``) the Whipple bicycle's four roots are ``+-sqrt(mu)`` for the two static
modes, ``mu`` the eigenvalues of ``-M^-1 g K0``: a slow pair (the whole bicycle falling over) and a
fast one (the front assembly flopping to the side).  The positive (or ``+i``) root of each pair is
a weave root, the two of which merge into the weave oscillation as speed grows; the negative
(``-i``) root of the slow pair is the capsize mode and that of the fast pair the caster mode.
Pairs are found from the values (``l`` and ``-l``), never from a solver's order.

A richer model's further roots belong to its other mode families (a leaning rider, a flexing
frame or fork, tyres): each root at standstill goes to the family whose states take the largest
share of it (participation factors ``|x_k y_k|`` of right and left eigenvectors, Perez-Arriaga,
Verghese & Schweppe 1982: independent of the states' units), the four most bicycle-like roots
keep the rules above, and the others are named ``family`` or ``family 1``, ``family 2``, ...

Wobble is named by what moves (:func:`wobble_columns`): the tracked oscillation that at
:data:`REFERENCE_SPEED` lies in the wobble band (:data:`WOBBLE_MIN_FREQUENCY` to
:data:`WOBBLE_MAX_FREQUENCY`) with its largest share (participation, summed by coordinate) on the
steer coordinate, the test :func:`is_wobble` applies to a crossing, is labelled ``wobble`` (its
conjugate with it: ``wobble 1``, ``wobble 2``) whatever family holds it at standstill (the tyre and
flexible Jamis's 6.5 Hz steer mode belongs to the tyres' family there).  A root the compliances'
family would have named wobble is then named by its coordinate that moves most (``frame-twist``).
Where no oscillation passes the test (the flexible Jamis without tyres: its 7.4 Hz mode is
frame-twist-dominated by participation) the labels by family stand.

When a complex pair splits into two real roots again the tracking cannot tell which root
continues which label (both leave one point).  The convention (the one Williams 2015's tables
follow): of the two labels, the one earlier in the rank (weave 1, weave 2, capsize, caster, then
the other families) takes the root with the larger real part.
"""

import numpy as np

from .tracking import partners

BICYCLE = "bicycle"
"""The family of the Whipple bicycle's own modes (roll and steer)."""
BICYCLE_LABELS = ("weave 1", "weave 2", "capsize", "caster")
WEAVE = ("weave 1", "weave 2")
WEAVE_FAMILY = "weave"
"""The name of the weave pair: the family of ``weave 1`` and ``weave 2``."""
_PAIRINGS = (((0, 1), (2, 3)), ((0, 2), (1, 3)), ((0, 3), (1, 2)))

WOBBLE = "wobble"
"""The name of a steer-dominated high-frequency oscillation (shimmy): what a flexible frame and
fork or tyres that slip add to the Whipple bicycle's modes."""
WOBBLE_MIN_FREQUENCY = 2 * np.pi * 3.0
"""Lowest frequency (rad/s, 3 Hz) of an oscillation named wobble; the weave of a bicycle stays
below it up to about 15 m/s, the wobble of the literature lies at 6-12 Hz (docs/models.md)."""
WOBBLE_MAX_FREQUENCY = 2 * np.pi * 15.0
"""Highest frequency (rad/s, 15 Hz) of an oscillation named wobble: the published wobble band is
about 4-12 Hz (Ploechl et al. 2012: 6-9 Hz; Klinger et al. 2014: 8-12 Hz hands on); a mode of the
compliances far above it (a fork bending at 60-80 Hz, a frame twist at 30 Hz) is named by the
coordinate that moves most in it (``fork-bending``, ``frame-twist``), not wobble."""


REFERENCE_SPEED = 8.0
"""Speed (m/s) at which the wobble is recognised by what moves (:func:`wobble_columns`): the issue's and
the study's 8 m/s (``bikemass.study.flexible.SPEED``), where the published wobble is well developed (it
lies at 4-12 Hz there) and the weave is damped into a slow oscillation below the wobble band.  The modes
are always followed up to it (:func:`~bikemass.analysis.engine.modes.follow_modes` extends the grid),
so the labels do not depend on the grid asked for."""


def participation(vectors):
    """Participation factors (N, m) of the states in each mode: ``|x_ki (X^-1)_ik|``, columns sum to 1."""
    P = np.abs(vectors * np.linalg.inv(vectors).T)
    return P / P.sum(axis=0)


def family(label):
    """The family of a tracked label: ``"weave 1"`` -> ``"weave"``, ``"lean 2"`` -> ``"lean"``."""
    head, _, tail = label.rpartition(" ")
    return head if tail.isdigit() else label


def _bicycle_labels(values):
    """Labels of four bicycle roots at standstill (list in the order of ``values``)."""
    pairs = min(_PAIRINGS, key=lambda pr: sum(abs(values[a] + values[b]) for a, b in pr))
    slow, fast = sorted(pairs, key=lambda pr: abs(values[pr[0]] ** 2))
    labels = [None] * 4
    for (a, b), (up, down) in ((slow, ("weave 1", "capsize")), (fast, ("weave 2", "caster"))):
        first = (values[a].real, values[a].imag) >= (values[b].real, values[b].imag)
        labels[a], labels[b] = (up, down) if first else (down, up)
    return labels


def standstill_labels(values, vectors, families, states=None, reference=None):
    """Labels of the roots ``values`` (m,) with state eigenvectors ``vectors`` (N, m) at standstill.

    ``families`` maps each family name to the indices of its dynamic states; the Whipple states
    form :data:`BICYCLE`.  ``states``, the dynamic states' names, lets a root of the compliances'
    family (:data:`WOBBLE`) above :data:`WOBBLE_MAX_FREQUENCY` be named by its family's coordinate
    that moves most in it (``fork-bending``, ``frame-twist``).  ``reference``, the same tracked roots
    and eigenvectors ``(values, vectors)`` at :data:`REFERENCE_SPEED`, with ``states`` names the
    wobble by what moves (:func:`wobble_columns`; a root of the compliances' family that is not it
    is then named by its coordinate too).  Returns a list of unique labels in the order of ``values``.
    """
    values = np.asarray(values)
    if len(families) == 1:
        return _bicycle_labels(values)
    share = participation(vectors)
    names = list(families)
    weight = np.array([share[list(families[f])].sum(axis=0) for f in names])     # (families, m)
    bicycle = np.argsort(-weight[names.index(BICYCLE)], kind="stable")[:4]
    labels = [None] * len(values)
    for i, label in zip(bicycle, _bicycle_labels(values[bicycle])):
        labels[i] = label
    others = [f for f in names if f != BICYCLE]
    rest = [i for i in range(len(values)) if labels[i] is None]
    home = {i: others[int(np.argmax([weight[names.index(f), i] for f in others]))] for i in rest}
    wobble = () if reference is None or states is None else wobble_columns(*reference, states, rest)
    if states is not None and WOBBLE in families:
        for i in rest:
            if home[i] == WOBBLE and (abs(values[i].imag) > WOBBLE_MAX_FREQUENCY or (wobble and i not in wobble)):
                by = {}
                for j in families[WOBBLE]:
                    by[coordinate(states[j])] = by.get(coordinate(states[j]), 0.0) + share[j, i]
                home[i] = max(by, key=by.get)
    for i in wobble:
        home[i] = WOBBLE
    for f in dict.fromkeys([*others, *home.values()]):
        mine = sorted((i for i in rest if home[i] == f), key=lambda i: _standstill_order(values[i]))
        for k, i in enumerate(mine):
            labels[i] = f if len(mine) == 1 else f"{f} {k + 1}"
    return labels


AXIS_TOLERANCE = 1e-9
"""A root whose real part is within this fraction of its modulus (1/s) of zero is on the imaginary
axis: an undamped oscillation at standstill, whose real part is rounding noise."""


def _standstill_order(value):
    """Sort key of a family's roots at standstill: the most unstable first, then the fastest, a
    conjugate pair together (upper first).  A real part within :data:`AXIS_TOLERANCE` of zero counts
    as zero, so that rounding (a last-bit change of an input) cannot reorder the undamped
    oscillations of a model (the flexible frame's 64 Hz and 7 Hz pairs) and renumber their labels."""
    real = 0.0 if abs(value.real) <= AXIS_TOLERANCE * (1 + abs(value)) else value.real
    return (-real, -abs(value.imag), -value.imag)


def split_rank(labels):
    """Labels in split-rank order: the bicycle's first, then the others as given."""
    return [*[b for b in BICYCLE_LABELS if b in labels], *[x for x in labels if x not in BICYCLE_LABELS]]


def _is_pair(values, i, j):
    """Speeds where columns i and j are a complex-conjugate pair (bool array)."""
    a, b = values[:, i], values[:, j]
    return (a.imag != 0) & (np.abs(a - b.conj()) <= 1e-9 * (1 + np.abs(a)))


def settle_splits(values, labels):
    """Column order (n, m) applying the split-rank convention after every split of a pair.

    ``values`` (n, m) are tracked roots whose column ``c`` carries ``labels[c]``.
    """
    values = np.array(values)
    n, m = values.shape
    order = np.tile(np.arange(m), (n, 1))
    ranking = split_rank(labels)
    rank = [ranking.index(label) for label in labels]
    # only columns that turn from complex to real somewhere can split from a pair (a swap below trades
    # two such columns, so the set stays the same)
    turns = np.flatnonzero(((values[:-1].imag != 0) & (values[1:].imag == 0)).any(axis=0))
    for i in turns:
        for j in turns[turns > i]:
            paired = _is_pair(values, i, j)
            real = (values[:, i].imag == 0) & (values[:, j].imag == 0)
            for k in np.flatnonzero(paired[:-1] & real[1:]) + 1:
                ahead = np.flatnonzero(~real[k:])      # first speed after the split where the roots differ
                end = k + (ahead[0] if len(ahead) else n - k)
                differ = np.flatnonzero(values[k:end, i].real != values[k:end, j].real)
                if not len(differ):
                    continue
                d = k + differ[0]
                upper_is_i = values[d, i].real > values[d, j].real
                if upper_is_i != (rank[i] < rank[j]):
                    values[k:, [i, j]] = values[k:, [j, i]]
                    order[k:, [i, j]] = order[k:, [j, i]]
    return order


def mode_names(values, labels):
    """What each root is at every speed, for people to read: array (n, m) of str.

    Two roots of one family (``weave 1`` and ``weave 2``) that are a complex pair are named by the
    family (``"weave"``); split into real roots, ``"weave, real (upper)"`` and ``"..., real (lower)"``
    by real part; a single-root family as tracked (``"capsize"``, ``"caster"``); roots of different
    families paired up ``"<label> + <label> oscillation"``.
    """
    values = np.asarray(values)
    partner = partners(values)
    names = np.empty(values.shape, dtype=object)
    for c, label in enumerate(labels):
        names[:, c] = label
        for k in np.flatnonzero(partner[:, c] != c):
            other = labels[partner[k, c]]
            names[k, c] = (family(label) if family(label) == family(other) and label != other
                           else " + ".join(sorted((label, other))) + " oscillation")
    for c, label in enumerate(labels):
        mates = [o for o, x in enumerate(labels) if o != c and family(x) == family(label) and x != family(x)]
        if len(mates) != 1:
            continue
        other = mates[0]
        real = (partner[:, c] == c) & (partner[:, other] == other)
        upper = (values[:, c].real > values[:, other].real) | ((values[:, c].real == values[:, other].real) & (c < other))
        names[real & upper, c] = f"{family(label)}, real (upper)"
        names[real & ~upper, c] = f"{family(label)}, real (lower)"
    return names.astype(str)


def coordinate(state):
    """The coordinate a state belongs to: ``"steer-angle"``, ``"steer-rate"`` -> ``"steer"``."""
    head, _, tail = state.rpartition("-")
    return head if tail in ("angle", "rate") else state


def _shares(share, states):
    """``{coordinate: participation}`` of one root's participation factors ``share`` (N,)."""
    by = {}
    for state, x in zip(states, share):
        by[coordinate(state)] = by.get(coordinate(state), 0.0) + x
    return by


def wobble_columns(values, vectors, states, candidates):
    """The columns of the wobble among ``candidates`` (indices into ``values``): a tuple of the root and
    its conjugate's column (empty if none).

    ``values`` (m,) and ``vectors`` (N, m) are the tracked roots and eigenvectors at
    :data:`REFERENCE_SPEED`, ``states`` the dynamic states' names.  Of the candidates that oscillate in
    the wobble band (:data:`WOBBLE_MIN_FREQUENCY` to :data:`WOBBLE_MAX_FREQUENCY`) with their largest
    share, summed by coordinate, on the steer coordinate (:func:`is_wobble`'s test), the one with the
    largest steer share is the wobble (on a tie the slower).  Its conjugate is the candidate nearest
    its conjugate value.
    """
    values = np.asarray(values)
    share = participation(vectors)
    found = []
    for i in candidates:
        if values[i].imag <= 0 or not WOBBLE_MIN_FREQUENCY <= values[i].imag <= WOBBLE_MAX_FREQUENCY:
            continue
        by = _shares(share[:, i], states)
        if max(by, key=by.get) == "steer":
            found.append((-by["steer"], values[i].imag, i))
    if not found:
        return ()
    i = min(found)[2]
    others = [j for j in candidates if j != i]
    if not others:
        return (i,)
    j = min(others, key=lambda j: abs(values[j] - np.conj(values[i])))
    return (i, j) if abs(values[j] - np.conj(values[i])) <= 1e-6 * abs(values[i]) else (i,)


def is_wobble(model, speed, root):
    """Whether the oscillation ``root`` (1/s) of ``model`` at ``speed`` (m/s) is wobble: 3 to 15 Hz
    (:data:`WOBBLE_MIN_FREQUENCY`, :data:`WOBBLE_MAX_FREQUENCY`) and its largest share (participation
    factors, summed by coordinate) on the steer coordinate."""
    if not WOBBLE_MIN_FREQUENCY <= abs(root.imag) <= WOBBLE_MAX_FREQUENCY:
        return False
    values, vectors = np.linalg.eig(model.dynamic_matrix(speed))
    k = int(np.argmin(np.abs(values - root)))
    by = _shares(participation(vectors)[:, k], [s.name for s in model.dynamic_states])
    return max(by, key=by.get) == "steer"


def is_weave(name):
    """Whether a root's name (:func:`~bikemass.analysis.engine.tracked.root_name`) is the weave's: it
    continues a Whipple weave root (``"weave"``: the pair of ``weave 1`` and ``weave 2``; or one of
    them paired with another mode of the bicycle, ``"capsize + weave 1"``: the slow static pair
    oscillating, which the thesis calls the first weave mode and capsize combined) and no mode of
    another family (a tyre, a compliance, the leaning rider)."""
    parts = name.split(" + ")
    return (any(family(x) == WEAVE_FAMILY for x in parts)
            and all(x in BICYCLE_LABELS or x == WEAVE_FAMILY for x in parts))
