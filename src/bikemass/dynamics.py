"""The linear stability of a bicycle as one typed, immutable result (``bm.stability``).

:func:`stability` takes a benchmark parameter set and an optional rear-frame stiffness S,
builds the Whipple model's matrices (rigid, or with S in series with gravity, Williams
2015 Eq. 3.27-3.30), follows the eigenvalues over a speed grid, labels the modes, and
finds critical speeds and stable ranges (:mod:`bikemass.stability` does the work; the
:class:`StabilityResult` carries its answer through unchanged as ``result.analysis``).
"""

from dataclasses import dataclass

import numpy as np

from .frozen import freeze, readonly, short_repr
from .options import MAX_SPEEDS

DEFAULT_MARGINAL = 2.0
"""Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable (the thesis's)."""


def matrices(params, stiffness=None):
    """The canonical matrices M, C1, K0, K2 of a parameter set, with a flexible rear frame.

    Parameters
    ----------
    params : BenchmarkParameters or CanonicalMatrices
        From :func:`bikemass.parameters` (SI); matrices are taken as they are.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) from :func:`bikemass.stiffness`; ``None`` = rigid.

    Returns
    -------
    CanonicalMatrices
        ``M`` (kg m^2), ``C1`` (kg m^2), ``K0`` (kg m), ``K2`` (kg m), ``g`` (m/s^2); with S,
        ``g K0`` is the static stiffness ``gK0 - gK0^T (gK0 + S)^-1 gK0``.
    """
    from .parameters import BenchmarkParameters
    from .stability import CanonicalMatrices, canonical_matrices, with_frame_stiffness

    if isinstance(params, CanonicalMatrices):
        base = params
    elif isinstance(params, BenchmarkParameters):
        from .plausibility import check_parameters
        base = canonical_matrices(check_parameters(params, "params"))
    else:
        from .errors import wrong_type
        raise wrong_type("params", params, "params must be BenchmarkParameters (bm.parameters) or CanonicalMatrices")
    return with_frame_stiffness(base, _stiffness(stiffness))


def _stiffness(S):
    """``S`` checked as a 2x2 symmetric positive definite array (N m/rad), or None for rigid."""
    from .choices import RIGID
    if S is None or (isinstance(S, str) and S in (RIGID, "rigid")):
        return None
    if isinstance(S, str):
        from .errors import InputTypeError
        raise InputTypeError("stiffness", S, f"a 2x2 array in N m/rad; for a material use "
                             f"bm.stiffness(bicycle, {S!r})")
    from .catalog import stiffness_matrix
    return stiffness_matrix(S)


def speeds(start=0.0, stop=30.0, step=0.05, max_speeds=MAX_SPEEDS):
    """The speed grid ``start, start + step, ...`` up to ``stop`` (m/s, never beyond), shape (n,).

    Raises
    ------
    InputError
        Unless ``0 <= start < stop``, ``step > 0`` and at most ``max_speeds`` speeds.
    """
    from .errors import InputError
    from .stability.analysis import speed_count, speed_grid
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (start, stop, step)):
        raise InputError("speeds", f"{start!r}:{stop!r}:{step!r}", "start, stop and step as numbers (m/s)")
    if not (0 <= start < stop < float("inf") and step > 0 and (stop - start) / step < max_speeds
            and speed_count(start, stop, step) <= max_speeds):
        raise InputError("speeds", f"{start}:{stop}:{step}", f"speeds need 0 <= start < stop, step > 0 and at most "
                         f"{max_speeds} points (m/s), got {start}:{stop}:{step}")
    return speed_grid(start, stop, step)


def speed_values(values, max_speeds=MAX_SPEEDS):
    """``values`` checked as speeds (the default grid for ``None``), their number first: at most
    ``max_speeds`` (the command line's ``--max-speeds``), before any array is made of them."""
    if values is None:
        return speeds()
    from .errors import InputError
    from .stability.modes import check_speeds
    try:
        count = len(values)
    except TypeError:
        count = 1
    if isinstance(max_speeds, bool) or not isinstance(max_speeds, int) or max_speeds < 1:
        raise InputError("max_speeds", repr(max_speeds), "a whole number of speeds >= 1")
    if count > max_speeds:
        raise InputError("speeds", f"{count} speeds", f"at most {max_speeds} speeds (raise max_speeds=; each "
                         "speed holds 4 eigenvalues and their eigenvectors)")
    return check_speeds(values)


def eigenvalues(params, stiffness=None, speeds=None, max_speeds=MAX_SPEEDS):
    """Eigenvalues over speed, followed across speed and labelled.

    Parameters
    ----------
    params, stiffness
        As for :func:`matrices`.
    speeds : array_like of shape (n,), optional
        Increasing speeds >= 0 (m/s); default 0..30 m/s in 0.05 m/s steps.
    max_speeds : int
        Most speeds taken (default 100000, as the command line's ``--max-speeds``).

    Returns
    -------
    Modes
        ``.speeds`` (n,) m/s, ``.labels`` (weave 1, weave 2, capsize, caster),
        ``.eigenvalues`` (n, 4) complex 1/s, ``.eigenvectors`` (n, 4, 4); ``modes["capsize"]``
        is one column.  Arrays are read-only.
    """
    from .stability import follow_modes
    modes = follow_modes(matrices(params, stiffness), speed_values(speeds, max_speeds))
    for a in (modes.speeds, modes.eigenvalues, modes.eigenvectors):
        a.setflags(write=False)
    return modes


@dataclass(frozen=True, eq=False, repr=False)
class StabilityResult:
    """Eigenvalues over speed, critical speeds and stable ranges of one bicycle.

    Attributes
    ----------
    analysis : Stability
        What :func:`bikemass.stability.stability` returned (modes, crossings, ranges).
    stiffness : numpy.ndarray of shape (2, 2) or None
        The rear-frame stiffness S used (N m/rad), ``None`` for a rigid frame.
    matrices : CanonicalMatrices
        The model's matrices (S included).

    Speeds are m/s, eigenvalues 1/s (complex), arrays read-only, ranges tuples of
    ``(start, stop)`` pairs.  Criteria: ``strict`` (every real part < 0) and
    ``marginal`` (also counts an eigenvalue with modulus below :attr:`marginal` rad/s).
    """

    analysis: object
    stiffness: np.ndarray
    matrices: object

    def __post_init__(self):
        object.__setattr__(self, "stiffness", readonly(self.stiffness))
        for a in (self.modes.speeds, self.modes.eigenvalues, self.modes.eigenvectors):
            a.setflags(write=False)

    @property
    def modes(self):
        """The labelled modes (:class:`~bikemass.stability.Modes`): ``modes["weave 1"]`` is (n,)."""
        return self.analysis.modes

    @property
    def speeds(self):
        """Speeds (m/s), shape (n,)."""
        return self.modes.speeds

    @property
    def eigenvalues(self):
        """Eigenvalues (1/s), complex, shape (n, 4); columns in :attr:`labels` order."""
        return self.modes.eigenvalues

    @property
    def labels(self):
        """Column labels of :attr:`eigenvalues`: weave 1, weave 2, capsize, caster."""
        return tuple(self.modes.labels)

    @property
    def marginal(self):
        """Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable."""
        return self.analysis.marginal

    @property
    def weave_speeds(self):
        """Speeds (m/s) where an oscillatory pair crosses ``Re = 0`` (weave-like), ascending."""
        return tuple(float(v) for v in self.analysis.weave_speeds)

    @property
    def capsize_speeds(self):
        """Speeds (m/s) where a real root crosses ``Re = 0`` (capsize-like; also a branch of a
        split weave pair), ascending."""
        return tuple(float(v) for v in self.analysis.capsize_speeds)

    @property
    def caster_speeds(self):
        """Speeds (m/s) where the root tracked as the caster mode crosses ``Re = 0``, ascending."""
        return tuple(c.speed for c in self.analysis.mode_crossings("caster"))

    @property
    def crossings(self):
        """Every crossing of ``Re = 0`` by speed: :class:`~bikemass.stability.Crossing` with
        ``speed`` (m/s), ``kind`` (oscillatory|real: the root that crosses), ``direction``
        (stabilising|destabilising) and ``mode`` (the tracked label)."""
        return self.analysis.crossings

    @property
    def ranges(self):
        """``{"strict"|"marginal": {"exact"|"grid": ((start, stop), ...)}}``: all modes stable (m/s).

        ``exact`` ends are roots; ``grid`` ends are the first and last stable grid speeds.
        """
        return freeze(self.analysis.ranges)

    @property
    def mode_ranges(self):
        """``{label: {criterion: {"exact"|"grid": ((start, stop), ...)}}}``: where each mode is stable (m/s)."""
        return freeze(self.analysis.mode_ranges)

    @property
    def weave_ranges(self):
        """``{criterion: {"exact"|"grid": ((start, stop), ...)}}``: where both weave roots are stable (m/s)."""
        return freeze(self.analysis.weave_ranges)

    @property
    def stable_speeds(self):
        """``((start, stop), ...)`` (m/s) where every mode is strictly stable (exact ends)."""
        return self.ranges["strict"]["exact"]

    def to_dict(self):
        """Plain data: the ``bikemass stability --format json`` document (without its units)."""
        return self.analysis.to_dict()

    def __repr__(self):
        v = self.speeds
        fmt = lambda xs: "(" + ", ".join(f"{x:.4f}" for x in xs) + ")"
        return short_repr(self, ("speeds", f"{v[0]:g}..{v[-1]:g} m/s x {len(v)}"),
                          ("weave_speeds", fmt(self.weave_speeds)), ("capsize_speeds", fmt(self.capsize_speeds)),
                          ("stable", "(" + ", ".join(f"{a:.4f}..{b:.4f}" for a, b in self.stable_speeds) + ")"),
                          ("stiffness", "rigid" if self.stiffness is None else "S"))


def stability(params, stiffness=None, speeds=None, marginal=DEFAULT_MARGINAL, max_speeds=MAX_SPEEDS):
    """Eigenvalues, critical speeds and stable speed ranges of a bicycle.

    Parameters
    ----------
    params : BenchmarkParameters or CanonicalMatrices
        From :func:`bikemass.parameters`.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad), e.g. ``bm.stiffness(bike, "steel")``; ``None`` = rigid.
    speeds : array_like of shape (n,), optional
        Increasing speeds >= 0 (m/s); default 0..30 m/s in 0.05 m/s steps (the thesis's).
        Critical speeds are roots (to 1e-13 m/s) between grid speeds.
    marginal : float
        Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable.
    max_speeds : int
        Most speeds taken (default 100000, as the command line's ``--max-speeds``); more is an
        InputError before any work.

    Returns
    -------
    StabilityResult
        ``.speeds`` (n,), ``.eigenvalues`` (n, 4) complex, ``.weave_speeds``,
        ``.capsize_speeds``, ``.ranges``, ``.mode_ranges``, ``.modes``.
    """
    from .stability import stability as analyse
    if isinstance(marginal, bool) or not isinstance(marginal, (int, float)) or not 0 < marginal < float("inf"):
        from .errors import InputError
        raise InputError("marginal", marginal, "a positive finite modulus in rad/s")
    S = _stiffness(stiffness)
    m = matrices(params, S)
    return StabilityResult(analyse(m, speed_values(speeds, max_speeds), marginal=marginal), S, m)
