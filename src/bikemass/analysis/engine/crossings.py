"""Exact critical speeds: every speed where an eigenvalue of a linear model reaches ``Re = 0``.

An eigenvalue of the dynamic state matrix ``A(v)`` (:class:`~bikemass.models.linear.LinearModel`)
is on the imaginary axis at ``v`` exactly when

* a **real** root passes through zero: ``det A(v) = 0``, or
* an **oscillatory** pair sits at ``+-i w``: two eigenvalues sum to zero, so the additive compound
  ``A(v)^[2]`` is singular (:mod:`~bikemass.analysis.engine.compound`).

Both are polynomial eigenvalue problems in ``v`` (:mod:`~bikemass.analysis.engine.polynomial`),
solved once for all speeds: nothing between grid points is missed.  ``A(v)`` is first balanced, one
diagonal similarity for every speed (the states of a richer model differ in scale by many orders:
very stiff tyres put entries of ``1e12`` beside ones of 1, and the compound's speeds would be only
``1e-5`` accurate; balanced, ``1e-8``).  Each candidate is verified on the eigenvalues near its
speed: the root nearest the axis must change the sign of its real part within a small bracket
around the candidate (Brent's method then refines the speed) and sit on the axis there, or lie on
the axis at the candidate itself (a root that touches the axis); a real pair ``l, -l`` also sums to
zero and is dropped (no eigenvalue is on the axis there).  For the marginal criterion the
boundary is also where an eigenvalue with ``Re >= 0`` has modulus ``r``: ``det(A(v) - r I) = 0``
(a real root) or ``C_2(A(v)) - r^2 I`` singular (a pair; the multiplicative compound).
"""

import math
from dataclasses import dataclass

import numpy as np

from ...core.results import Result, quantity
from .compound import additive_coefficients, multiplicative_coefficients
from .eigen import has_quartic_path
from .polynomial import real_roots

OSCILLATORY, REAL = "oscillatory", "real"
KINDS = (OSCILLATORY, REAL)
"""What crosses ``Re = 0``: a complex pair (weave-like) or a real root (capsize-like)."""
STABILISING, DESTABILISING, TOUCHING = "stabilising", "destabilising", "touching"
DIRECTIONS = (STABILISING, DESTABILISING, TOUCHING)
"""As speed grows, the crossing makes the model more stable, less stable, or neither."""

VERIFY_TOL = 1e-6
"""A root is on the axis when its real part is within VERIFY_TOL (1 + |root|) of zero."""
BRACKETS = (1e-9, 1e-7, 1e-5, 1e-4)
"""Half-widths (relative to 1 + v) of the brackets searched, smallest first, for the sign change of
a candidate's root: a candidate speed may be this far from the crossing (the polynomial eigenvalue
problem's error grows with the spread of the model's eigenvalues)."""
XTOL = 1e-13
"""Absolute tolerance (m/s) of a refined critical speed."""
MERGE_TOL = 1e-9
"""Candidates closer than this (m/s) are one crossing, and candidates this close to the span's start
are at its start (outside ``(lo, hi]``)."""


@dataclass(frozen=True, eq=False)
class Crossing(Result):
    """One crossing of ``Re = 0`` by an eigenvalue of a model.

    Attributes
    ----------
    speed : float
        Forward speed (m/s).
    kind : str
        ``"oscillatory"`` (a complex pair crosses) or ``"real"`` (a real root passes through 0).
    direction : str
        ``"stabilising"``, ``"destabilising"`` or ``"touching"`` (the number of unstable roots is
        the same on both sides).
    frequency : float
        ``|Im|`` of the crossing root (rad/s); 0 for a real root.
    mode : str
        The tracked mode that crosses (``"weave 1"``, ``"capsize"``, ...), ``""`` if not tracked.
    """

    speed: float = quantity("m/s")
    kind: str = ""
    direction: str = ""
    frequency: float = quantity("rad/s", default=0.0)
    mode: str = ""


class Eigenvalues:
    """``model``'s dynamic eigenvalues (1/s) at single speeds, memoised: ``at(v)``.

    ``pieces`` holds ``(lo, hi, coefficients)`` of each polynomial the model is made of
    (:attr:`~bikemass.models.linear.LinearModel.speed_pieces`: one for a model, one per speed
    interval for a closed loop with scheduled gains); ``coefficients`` are the first piece's."""

    def __init__(self, model):
        self.pieces = tuple((lo, hi, np.asarray(m.dynamic_coefficients, dtype=float))
                            for lo, hi, m in model.speed_pieces)
        self._starts = np.array([lo for lo, _, _ in self.pieces[1:]])
        self.coefficients = self.pieces[0][2]
        self._cache = {}
        self._balanced = {}
        # per piece, the largest absolute row sum of each coefficient: sum_k S_k |v|^k bounds A(v)'s, and
        # below SEPARATION no state can be fast (separated_eigenvalues would take LAPACK's roots as they are)
        self._row_sums = [[float(np.abs(Q).sum(axis=-1).max()) if Q.size else 0.0 for Q in P] if np.all(np.isfinite(P))
                          else None for _, _, P in self.pieces]

    def balanced_piece(self, k):
        """:func:`balanced` of piece ``k``'s coefficients, made once."""
        if k not in self._balanced:
            self._balanced[k] = balanced(self.pieces[k][2])
        return self._balanced[k]

    @property
    def balanced(self):
        """:func:`balanced` of the (first piece's) coefficients, made once."""
        return self.balanced_piece(0)

    def __call__(self, v):
        v = float(v)
        out = self._cache.get(v)
        if out is None:
            k = int(np.searchsorted(self._starts, v, side="right")) if self._starts.size else 0
            P = self.pieces[k][2]
            A = P[-1]
            for Q in P[-2::-1]:                             # Horner in v
                A = A * v + Q
            sums = self._row_sums[k]
            if sums is not None and sum(x * abs(v) ** j for j, x in enumerate(sums)) < SEPARATION:
                out = eigenvalues_of(A)                     # what separated_eigenvalues gives: no fast states
            else:
                out = separated_eigenvalues(A)
            self._cache[v] = out
        return out

    def spans(self, lo, hi):
        """``[(a, b, balanced coefficients)]``: each piece's polynomial (:func:`balanced`) and its part
        ``[a, b]`` of ``[lo, hi]``."""
        return [(max(lo, a), min(hi, b), self.balanced_piece(k)) for k, (a, b, _) in enumerate(self.pieces)
                if max(lo, a) <= min(hi, b)]


SEPARATION = 1e8
"""Ratio of the smallest fast eigenvalue's modulus to the largest slow one's from which
:func:`separated_eigenvalues` takes the slow ones from the reduced matrix (its error is of the
order of the inverse ratio, relative)."""
ROW_GAP = 1e3
"""Least ratio between consecutive sorted row-and-column sums of the balanced matrix that splits
its states into slow and fast ones."""


_DGEEV = []
"""LAPACK's ``dgeev`` (scipy's wrapper), found once on first use."""


def eigenvalues_of(A):
    """The eigenvalues (complex) of one real square matrix ``A``: ``numpy.linalg.eigvals`` up to 4 x 4
    (the Whipple bicycle's path runs without scipy), else LAPACK's ``dgeev`` called directly (the same
    algorithm; half of numpy's cost on a 6 x 6, which is mostly the call: a crossing's refinement asks
    for the eigenvalues at a score of single speeds)."""
    A = np.asarray(A, dtype=float)
    if len(A) <= 4 or not np.isfinite(A).all():
        return np.linalg.eigvals(A).astype(complex, copy=False)   # (numpy refuses a matrix that is not finite)
    if not _DGEEV:
        from scipy.linalg import lapack                   # lazy: loaded with scipy, which richer models use
        _DGEEV.append(lapack.dgeev)
    wr, wi, _, _, info = _DGEEV[0](A, compute_vl=0, compute_vr=0)
    if info != 0:
        return np.linalg.eigvals(A).astype(complex, copy=False)
    return wr + 1j * wi


def separated_eigenvalues(A):
    """The eigenvalues of ``A``; where its states split into slow ones and fast ones at least
    :data:`SEPARATION` apart (a tyre of relaxation length 1e-10 m puts roots of -1e11 1/s beside
    the weave's), the slow ones from the reduced matrix ``A11 - A12 A22^-1 A21`` (the fast states
    at their quasi-steady values) and the fast ones from ``A22``.  A QR eigensolver's error on
    every root is about ``1e-16 |A|``: with ``|A|`` of 1e12 the weave's real part is lost in it
    and its crossing could no longer be verified; the reduction's error is of the order of the
    inverse separation instead."""
    plain = eigenvalues_of(A)
    n = len(A)
    if n <= 4 or not np.all(np.isfinite(A)):        # the Whipple bicycle's 4 x 4 has no such fast states
        return plain
    # the fast roots would be eigenvalues of a diagonal block of A (a similarity of it), so of modulus at
    # most its largest absolute row sum: below SEPARATION the test at the end always fails (no balancing)
    if np.abs(A).sum(axis=1).max() < SEPARATION:
        return plain
    D = balance_scale(A)
    B = A * D[None, :] / D[:, None]                  # D^-1 A D
    size = np.abs(B).sum(axis=0) + np.abs(B).sum(axis=1)
    order = np.argsort(size)
    gaps = size[order[1:]] / np.maximum(size[order[:-1]], np.finfo(float).tiny)
    k = int(np.argmax(gaps))
    if gaps[k] < ROW_GAP:
        return plain
    slow, fast = np.sort(order[:k + 1]), np.sort(order[k + 1:])
    A22 = B[np.ix_(fast, fast)]
    try:
        reduced = B[np.ix_(slow, slow)] - B[np.ix_(slow, fast)] @ np.linalg.solve(A22, B[np.ix_(fast, slow)])
    except np.linalg.LinAlgError:
        return plain
    low, high = eigenvalues_of(reduced), eigenvalues_of(A22)
    if not (np.all(np.isfinite(low)) and np.all(np.isfinite(high))) or \
            np.abs(high).min() < SEPARATION * max(np.abs(low).max(), 1.0):
        return plain
    return np.concatenate([low, high])


def balanced(coefficients):
    """``D^-1 P[k] D`` for every coefficient of ``A(v) = sum_k v**k P[k]``: one diagonal similarity
    (LAPACK's balancing of ``sum_k |P[k]|``, powers of 2, no permutation) that leaves every
    eigenvalue at every speed unchanged and evens out the scales of the states."""
    P = np.asarray(coefficients, dtype=float)
    if P.shape[-1] == 0:
        return P
    scale = balance_scale(np.abs(P).sum(axis=0))
    return P * scale[None, None, :] / scale[None, :, None]


def balance_scale(A):
    """The diagonal ``D`` (n,) (powers of 2) that balances the square matrix ``A``: ``D^-1 A D`` has
    rows and columns of even 2-norms, by the iteration of LAPACK's ``gebal`` (Parlett and Reinsch
    1969; James, Langou and Lowery 2014) without permutations, in numpy (no scipy on the Whipple
    bicycle's path)."""
    A = np.array(A, dtype=float)
    n = len(A)
    if n > 4:          # a richer model (scipy is loaded for it anyway): LAPACK's own, the same scales
        from scipy.linalg import matrix_balance      # lazy: the Whipple bicycle's path runs without scipy
        return matrix_balance(A, permute=False, separate=True)[1][0]
    A = A.tolist()                      # a 4 x 4: Python floats are faster than numpy calls on it
    scale = [1.0] * n
    tiny = float(np.finfo(float).tiny / np.finfo(float).eps)
    small, big = 2 * tiny, 1 / (2 * tiny)
    for _ in range(100 * max(n, 1)):
        again = False
        for i in range(n):
            column, row = [A[k][i] for k in range(n)], A[i]
            c, r = math.sqrt(sum(x * x for x in column)), math.sqrt(sum(x * x for x in row))
            ca, ra = max(map(abs, column)), max(map(abs, row))
            if c == 0 or r == 0:
                continue
            total, f, g = c + r, 1.0, r / 2
            while c < g and max(f, c, ca) < big and min(r, g, ra) > small:
                f, c, ca, r, g, ra = 2 * f, 2 * c, 2 * ca, r / 2, g / 2, ra / 2
            g = c / 2
            while g >= r and max(r, ra) < big and min(f, c, g, ca) > small:
                f, c, g, ca, r, ra = f / 2, c / 2, g / 2, ca / 2, 2 * r, 2 * ra
            if c + r >= 0.95 * total or (f < 1 and scale[i] < 1 and f * scale[i] <= tiny) or \
                    (f > 1 and scale[i] > 1 and scale[i] >= 1 / (tiny * f)):
                continue
            scale[i] *= f
            A[i] = [x / f for x in A[i]]
            for k in range(n):
                A[k][i] *= f
            again = True
        if not again:
            break
    scale = np.array(scale)
    return scale


FAR = 100.0
"""A candidate whose root, at the slope of the smallest bracket, is over FAR times the largest bracket
away from the axis cannot change sign in any bracket: the larger ones are not searched."""


def _refine(f, v, lo, hi):
    """``v`` moved to the root of ``f`` in the smallest bracket of :data:`BRACKETS` around it where
    ``f`` changes sign (``v`` itself where none does: a root that touches zero, or a candidate whose
    root stays far from the axis, :data:`FAR`)."""
    for h in BRACKETS:
        a, b = max(lo, v - h * (1 + v)), min(hi, v + h * (1 + v))
        fa, fb = f(a), f(b)
        if fa == 0:
            return a
        if fb == 0:
            return b
        if np.sign(fa) != np.sign(fb):
            return _bracketed(f, a, b, fa, fb)
        if h == BRACKETS[0] and b > a and \
                min(abs(fa), abs(fb)) > FAR * BRACKETS[-1] * (1 + v) * abs(fb - fa) / (b - a):
            return v
    return v


def _bracketed(f, a, b, fa, fb):
    """The root of ``f`` in ``[a, b]`` (``fa``, ``fb`` of opposite signs) to :data:`XTOL`: regula falsi
    with the Illinois weighting (on the small brackets of :func:`_refine` ``f`` is a straight line to
    rounding, so two evaluations settle it), Brent's method if that has not settled in a few steps."""
    side = 0
    for _ in range(8):
        x = b - fb * (b - a) / (fb - fa)
        if not a <= x <= b:
            break
        fx = f(x)
        if fx == 0 or min(x - a, b - x) <= XTOL:
            return x
        if np.sign(fx) == np.sign(fb):
            b, fb = x, fx
            if side == 1:
                fa /= 2
            side = 1
        else:
            a, fa = x, fx
            if side == -1:
                fb /= 2
            side = -1
        if b - a <= XTOL:
            return b - fb * (b - a) / (fb - fa)
    from scipy.optimize import brentq      # lazy: only models beyond the closed form refine crossings
    return brentq(f, a, b, xtol=XTOL, rtol=4 * np.finfo(float).eps)


def _near(v, lo):
    """The lower end of :func:`_refine`'s first bracket around ``v``: the roots there (its first
    evaluation, memoised) stand for the candidate's own, a relative 1e-9 away."""
    return max(lo, v - BRACKETS[0] * (1 + v))


def _real_crossing(at, v, lo, hi):
    """``(speed, 0.0)`` if a real root passes through zero at or near ``v`` (refined), else ``None``."""
    roots = at(_near(v, lo))
    scale = np.abs(roots).max()

    def root(x):
        r = at(x)
        return r[np.argmin(np.abs(r))]
    if abs(root(_near(v, lo)).imag) > VERIFY_TOL:
        return None
    speed = _refine(lambda x: float(root(x).real), v, lo, hi)
    hit = root(speed)
    return (speed, 0.0) if abs(hit) <= VERIFY_TOL * (1 + scale) else None


def _oscillatory_crossing(at, v, lo, hi):
    """``(speed, w)`` if a complex pair crosses the imaginary axis at or near ``v`` (refined), else
    ``None``.  The pair is the upper-half-plane root nearest the axis relative to its modulus."""
    roots = at(_near(v, lo))
    upper = roots[roots.imag > VERIFY_TOL * (1 + np.abs(roots))]
    if not len(upper):
        return None
    w0 = upper[np.argmin(np.abs(upper.real) / (1 + np.abs(upper)))].imag

    def root(x):
        r = at(x)
        return r[np.argmin(np.abs(r - 1j * w0))]
    speed = _refine(lambda x: float(root(x).real), v, lo, hi)
    hit = root(speed)
    return (speed, float(abs(hit.imag))) if abs(hit.real) <= VERIFY_TOL * (1 + abs(hit)) else None


def axis_crossings(model, lo, hi, at=None):
    """``[(speed, kind, frequency)]``, ascending: every verified crossing of ``Re = 0`` in ``(lo, hi]``.

    ``at`` may pass a shared :class:`Eigenvalues` of the model.
    """
    at = at or Eigenvalues(model)
    # at standstill every oscillation of an undamped model (the flexible member) is on the axis: the
    # roots found there, a round-off away from lo, are at lo and no crossing of (lo, hi]
    start = lo + MERGE_TOL * (1 + abs(lo))
    small = has_quartic_path(model)
    found = []
    for a, b, P in at.spans(lo, hi):      # each polynomial on its own speeds (one for a model), balanced
        for kind, coefficients, check in ((REAL, P, _real_crossing),
                                          (OSCILLATORY, additive_coefficients(P), _oscillatory_crossing)):
            for v in real_roots(coefficients, a, b, small):
                if v <= start:
                    continue
                hit = check(at, v, lo, hi)
                if hit is not None and start < hit[0] <= hi:
                    found.append((float(hit[0]), kind, hit[1]))
    found.sort()
    out = []
    for c in found:
        if out and c[1] == out[-1][1] and c[0] - out[-1][0] <= MERGE_TOL * (1 + c[0]):
            continue
        out.append(c)
    return out


def circle_speeds(model, radius, lo, hi, at=None):
    """Speeds in ``(lo, hi)`` where an eigenvalue may have modulus ``radius`` (1/s): candidates for the
    ends of marginally stable ranges (unverified: an extra speed only splits an interval)."""
    at = at or Eigenvalues(model)
    small = has_quartic_path(model)
    found = []
    for a, b, P in at.spans(lo, hi):
        n = P.shape[-1]
        shifted = P.copy()
        shifted[0] = shifted[0] - radius * np.eye(n)
        C2 = multiplicative_coefficients(P)
        C2[0] = C2[0] - radius ** 2 * np.eye(len(C2[0]))
        found += [real_roots(shifted, a, b, small), real_roots(C2, a, b, small)]
    v = np.concatenate(found) if found else np.empty(0)
    return np.sort(v[(v > lo) & (v < hi)])
