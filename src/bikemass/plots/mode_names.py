"""What each tracked root is, for people to read: the weave as one mode while it is a complex
pair, its two real branches after a split named as such (not by the tracking's labels)."""

import numpy as np

WEAVE = ("weave 1", "weave 2")
"""The tracked labels whose roots make up the weave oscillation."""


def _paired(a, b):
    """Speeds where roots ``a`` and ``b`` (n,) are a complex-conjugate pair (bool)."""
    return (a.imag != 0) & (np.abs(a - b.conj()) <= 1e-9 * (1 + np.abs(a)))


def curve_names(modes):
    """Array (n, 4) of str, columns as ``modes.labels``: ``weave`` while the weave roots are a
    pair, ``weave, real (upper)`` / ``weave, real (lower)`` (by real part) while both are real,
    ``weave, real root`` for one that is real while the other has paired with another root,
    ``<label> + <label> oscillation`` for any other pair, else the tracked label."""
    values, labels = modes.eigenvalues, list(modes.labels)
    names = np.array([labels] * len(values), dtype=object)
    for i in range(len(labels)):
        for j in range(i + 1, len(labels)):
            pair = _paired(values[:, i], values[:, j])
            both = {labels[i], labels[j]}
            names[pair, i] = names[pair, j] = ("weave" if both == set(WEAVE)
                                               else " + ".join(sorted(both)) + " oscillation")
    a, b = (labels.index(w) for w in WEAVE)
    for c in (a, b):
        names[values[:, c].imag == 0, c] = "weave, real root"
    real = (values[:, a].imag == 0) & (values[:, b].imag == 0)
    upper = values[:, a].real >= values[:, b].real
    names[real & upper, a] = names[real & ~upper, b] = "weave, real (upper)"
    names[real & ~upper, a] = names[real & upper, b] = "weave, real (lower)"
    return names.astype(str)
