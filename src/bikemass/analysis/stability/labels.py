"""Naming tracked modes weave 1, weave 2, capsize and caster from their physics.

At standstill (``v = 0``, no damping) the roots are ``+-sqrt(mu)`` for the two
static modes, ``mu`` the eigenvalues of ``-M^-1 g K0``: a slow one (smaller
``|mu|``: the whole bicycle falling over) and a fast one (the front assembly
flopping to the side).  The positive (or ``+i``) root of each pair is a weave
root, the two of which merge into the weave oscillation as speed grows; the
negative (or ``-i``) root of the slow pair is the capsize mode and that of the
fast pair the caster mode.  The pairs are found from the values (``lambda`` and
``-lambda``), never from the order in which a solver returns them.

When a complex pair splits into two real roots again the tracking cannot tell
which root continues which label (both leave the same point).  The convention,
the one the thesis's tables follow: of the two labels, the one earlier in
:data:`SPLIT_RANK` goes to the root with the larger real part (the capsize mode is
the slow root next to zero, the caster mode the fast, strongly damped one; a weave
root is the less damped one).
"""

import numpy as np

from .tracking import partners

LABELS = ("weave 1", "weave 2", "capsize", "caster")
SPLIT_RANK = LABELS
"""After a split the earlier label takes the root with the larger real part."""

_PAIRINGS = (((0, 1), (2, 3)), ((0, 2), (1, 3)), ((0, 3), (1, 2)))


def standstill_labels(values):
    """Labels of the four roots ``values`` at ``v = 0`` (list in the same order)."""
    values = np.asarray(values)
    pairs = min(_PAIRINGS, key=lambda pr: sum(abs(values[a] + values[b]) for a, b in pr))
    slow, fast = sorted(pairs, key=lambda pr: abs(values[pr[0]] ** 2))
    labels = [None] * 4
    for (a, b), (up, down) in ((slow, ("weave 1", "capsize")), (fast, ("weave 2", "caster"))):
        first = (values[a].real, values[a].imag) >= (values[b].real, values[b].imag)
        labels[a], labels[b] = (up, down) if first else (down, up)
    return labels


def _is_pair(values, i, j):
    """Speeds where columns i and j are a complex-conjugate pair (bool array)."""
    a, b = values[:, i], values[:, j]
    return (a.imag != 0) & (np.abs(a - b.conj()) <= 1e-9 * (1 + np.abs(a)))


def settle_splits(values, labels):
    """Column order (n, 4) applying the :data:`SPLIT_RANK` convention after every split.

    ``values`` (n, 4) are tracked roots whose column ``c`` carries ``labels[c]``.
    """
    values = np.array(values)
    n = len(values)
    order = np.tile(np.arange(4), (n, 1))
    rank = [SPLIT_RANK.index(label) for label in labels]
    for i in range(4):
        for j in range(i + 1, 4):
            paired = _is_pair(values, i, j)
            real = (values[:, i].imag == 0) & (values[:, j].imag == 0)
            for k in np.flatnonzero(paired[:-1] & real[1:]) + 1:
                # first speed after the split where the two real roots differ
                ahead = np.flatnonzero(~real[k:])
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


WEAVE = ("weave 1", "weave 2")
"""The two tracked labels whose roots make up the weave oscillation."""


def mode_names(values, labels):
    """What each root is at every speed, for people to read: array (n, 4) of str.

    ``"weave"`` for both members of the weave pair while it is a complex pair; after
    it splits (or before the two roots merge at low speed) ``"weave, real (upper)"``
    and ``"weave, real (lower)"`` by real part; ``"capsize"`` and ``"caster"`` as
    tracked; any other complex pair ``"<label> + <label> oscillation"``.  ``values``
    (n, 4) are tracked roots, column ``c`` carrying ``labels[c]``.
    """
    values = np.asarray(values)
    partner = partners(values)
    names = np.empty(values.shape, dtype=object)
    weave = [labels.index(w) for w in WEAVE]
    for c, label in enumerate(labels):
        p = partner[:, c]
        names[:, c] = label
        paired = p != c
        for k in np.flatnonzero(paired):
            other = labels[p[k]]
            names[k, c] = "weave" if {label, other} == set(WEAVE) else " + ".join(sorted((label, other))) + " oscillation"
    for c in weave:
        other = weave[1] if c == weave[0] else weave[0]
        real = (partner[:, c] == c) & (partner[:, other] == other)
        upper = (values[:, c].real > values[:, other].real) | (
            (values[:, c].real == values[:, other].real) & (c < other))
        names[real & upper, c] = "weave, real (upper)"
        names[real & ~upper, c] = "weave, real (lower)"
    return names.astype(str)
