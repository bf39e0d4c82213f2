"""The linear stability of a bicycle as one typed, immutable result (``bm.stability``).

:func:`stability` takes a benchmark parameter set and an optional rear-frame stiffness S (or
any :class:`~bikemass.models.linear.LinearModel`), builds the model (the Whipple bicycle, rigid
or with S in series with gravity, Williams 2015 Eq. 3.27-3.30), and hands it to the one engine
(:mod:`bikemass.analysis.engine`): modes followed and named over a speed grid, exact critical
speeds and stable ranges.
"""
from ..models.parameters import BenchmarkParameters
from ..models.canonical import CanonicalMatrices, canonical_matrices
from ..models.flexible_static import with_frame_stiffness
from ..models.plausibility import check_parameters
from ..core.errors import wrong_type
from ..core.choices import RIGID
from ..core.errors import InputTypeError
from ..scenario.catalog import stiffness_matrix
from ..core.errors import InputError
from ..core.limits import MAX_SPEEDS
from .engine.speeds import speed_count, speed_grid, speed_values
from ..models.linear import LinearModel
from ..models.whipple import whipple_model
from .engine.modes import follow_modes
from .engine.stability import analyse

DEFAULT_MARGINAL = 2.0
"""Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable (the thesis's)."""


def matrices(params, stiffness=None):
    """The canonical matrices M, C1, K0, K2 of a parameter set, with a flexible rear frame.

    Parameters
    ----------
    params : BenchmarkParameters or CanonicalMatrices
        From :func:`bikemass.models.parameters` (SI); matrices are taken as they are.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) from :func:`bikemass.stiffness`; ``None`` = rigid.

    Returns
    -------
    CanonicalMatrices
        ``M`` (kg m^2), ``C1`` (kg m^2), ``K0`` (kg m), ``K2`` (kg m), ``g`` (m/s^2); with S,
        ``g K0`` is the static stiffness ``gK0 - gK0^T (gK0 + S)^-1 gK0``.
    """

    if isinstance(params, CanonicalMatrices):
        base = params
    elif isinstance(params, BenchmarkParameters):
        base = canonical_matrices(check_parameters(params, "params"))
    else:
        raise wrong_type("params", params, "params must be BenchmarkParameters (bm.parameters) or CanonicalMatrices")
    return with_frame_stiffness(base, _stiffness(stiffness))


def _stiffness(S):
    """``S`` checked as a 2x2 symmetric positive definite array (N m/rad), or None for rigid."""
    if S is None or (isinstance(S, str) and S in (RIGID, "rigid")):
        return None
    if isinstance(S, str):
        raise InputTypeError("stiffness", S, f"a 2x2 array in N m/rad; for a material use "
                             f"bm.stiffness(bicycle, {S!r})")
    return stiffness_matrix(S)


def speeds(start=0.0, stop=30.0, step=0.05, max_speeds=MAX_SPEEDS):
    """The speed grid ``start, start + step, ...`` up to ``stop`` (m/s, never beyond), shape (n,).

    Parameters
    ----------
    start, stop, step : float
        First speed, last speed at most, and step (m/s).
    max_speeds : int
        Most speeds (default 100000, as the command line's ``--max-speeds``).

    Returns
    -------
    numpy.ndarray of shape (n,)

    Raises
    ------
    InputError
        Unless ``0 <= start < stop``, ``step > 0`` and at most ``max_speeds`` speeds.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.speeds(0, 10, 2.5).tolist()
    [0.0, 2.5, 5.0, 7.5, 10.0]
    """
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (start, stop, step)):
        raise InputError("speeds", f"{start!r}:{stop!r}:{step!r}", "start, stop and step as numbers (m/s)")
    if not (0 <= start < stop < float("inf") and step > 0 and (stop - start) / step < max_speeds
            and speed_count(start, stop, step) <= max_speeds):
        raise InputError("speeds", f"{start}:{stop}:{step}", f"speeds need 0 <= start < stop, step > 0 and at most "
                         f"{max_speeds} points (m/s), got {start}:{stop}:{step}")
    return speed_grid(start, stop, step)


def linear_model(params, stiffness=None):
    """The linear model of a parameter set: the Whipple bicycle, rigid or with the quasi-static
    flexible rear frame of stiffness S (a :class:`~bikemass.models.linear.LinearModel` is
    returned as it is).

    Parameters
    ----------
    params : BenchmarkParameters or LinearModel
        From :func:`bikemass.models.parameters` (SI).
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) from :func:`bikemass.stiffness`; ``None`` = rigid.

    Returns
    -------
    LinearModel
        States roll-angle, steer-angle, roll-rate, steer-rate, heading, lateral; inputs
        roll-torque, steer-torque; ``A(v)``, ``B(v)`` as polynomials in speed.
    """
    if isinstance(params, LinearModel):
        if stiffness is not None:
            raise InputError("stiffness", "(matrix)", "no stiffness with a LinearModel (it is built in)")
        return params
    if not isinstance(params, BenchmarkParameters):
        raise wrong_type("params", params, "params must be BenchmarkParameters (bm.parameters) or a LinearModel")
    return whipple_model(check_parameters(params, "params"), _stiffness(stiffness))


def eigenvalues(params, stiffness=None, speeds=None, max_speeds=MAX_SPEEDS):
    """Eigenvalues over speed, followed across speed and named.

    Parameters
    ----------
    params, stiffness
        As for :func:`linear_model`.
    speeds : array_like of shape (n,), optional
        Increasing speeds >= 0 (m/s); default 0..30 m/s in 0.05 m/s steps.
    max_speeds : int
        Most speeds taken (default 100000, as the command line's ``--max-speeds``); more is an
        InputError before any work.

    Returns
    -------
    Modes
        ``.speeds`` (n,) m/s, ``.labels`` (weave 1, weave 2, capsize, caster, ...),
        ``.eigenvalues`` (n, m) complex 1/s, ``.eigenvectors`` (n, N, m); ``modes["capsize"]``
        is one column.  Arrays are read-only.
    """
    return follow_modes(linear_model(params, stiffness), speed_values(speeds, max_speeds))


def stability(params, stiffness=None, speeds=None, marginal=DEFAULT_MARGINAL, max_speeds=MAX_SPEEDS):
    """Eigenvalues, critical speeds and stable speed ranges of a bicycle.

    Parameters
    ----------
    params : BenchmarkParameters or LinearModel
        From :func:`bikemass.models.parameters`, or any model of the family.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad), e.g. ``bm.stiffness(bike, "steel")``; ``None`` = rigid.
    speeds : array_like of shape (n,), optional
        Increasing speeds >= 0 (m/s); default 0..30 m/s in 0.05 m/s steps (the thesis's).
        Critical speeds are exact (found without a grid) on the grid's span.
    marginal : float
        Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable.
    max_speeds : int
        Most speeds taken (default 100000, as the command line's ``--max-speeds``); more is an
        InputError before any work.

    Returns
    -------
    StabilityResult
        ``.speeds`` (n,), ``.eigenvalues`` (n, m) complex, ``.crossings``, ``.weave_speeds``,
        ``.capsize_speeds``, ``.ranges``, ``.mode_ranges``, ``.modes``.

    Examples
    --------
    >>> import bikemass as bm
    >>> result = bm.stability(bm.parameters("benchmark"))
    >>> [round(c.speed, 6) for c in result.crossings]
    [4.292383, 6.024262]
    """
    if isinstance(marginal, bool) or not isinstance(marginal, (int, float)) or not 0 < marginal < float("inf"):
        raise InputError("marginal", marginal, "a positive finite modulus in rad/s")
    S = _stiffness(stiffness)
    return analyse(linear_model(params, S), speed_values(speeds, max_speeds), marginal, S)
