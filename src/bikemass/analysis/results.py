"""The linear stability of a bicycle as one typed, immutable result (``bm.stability``).

:func:`stability` takes a benchmark parameter set and an optional rear-frame stiffness S (or
any :class:`~bikemass.models.linear.LinearModel`), builds the model (the Whipple bicycle, rigid
or with S in series with gravity, Williams 2015 Eq. 3.27-3.30), and hands it to the one engine
(:mod:`bikemass.analysis.engine`): modes followed and named over a speed grid, exact critical
speeds and stable ranges.
"""
import numpy as np
from numpy.typing import ArrayLike

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
from .engine.modes import Modes, follow_modes
from .engine.stability import StabilityResult, analyse

DEFAULT_MARGINAL = 2.0
"""Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable (the thesis's)."""


def matrices(params: BenchmarkParameters | CanonicalMatrices,
             stiffness: "ArrayLike | None" = None) -> CanonicalMatrices:
    """The canonical matrices M, C1, K0, K2 of a parameter set, with a flexible rear frame.

    ``M q'' + v C1 q' + (g K0 + v^2 K2) q = f`` with ``q = [roll, steer]`` (rad): Meijaard et al.
    (2007), Appendix A.

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

    Raises
    ------
    InputError
        Parameters the model is not defined for, or an S that is not symmetric positive definite.
    InputTypeError
        ``params`` of another type.

    See Also
    --------
    linear_model : The state-space model built from them.

    Examples
    --------
    >>> import bikemass as bm
    >>> m = bm.matrices(bm.parameters("benchmark"))   # Meijaard et al. (2007), Sec. 4: M, K2
    >>> print(f"M:  {m.M[0, 0]:.5f} {m.M[0, 1]:.11f} {m.M[1, 1]:.11f}")
    M:  80.81722 2.31941332209 0.29784188200
    >>> print(f"K2: {m.K2[0, 1]:.11f} {m.K2[1, 1]:.11f}")
    K2: 76.59734589573 2.65431523795
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


def speeds(start: float = 0.0, stop: float = 30.0, step: float = 0.05, max_speeds: int = MAX_SPEEDS) -> np.ndarray:
    """The speed grid ``start, start + step, ...`` up to ``stop`` (m/s, never beyond).

    Parameters
    ----------
    start, stop : float
        First speed and last speed at most (m/s), ``0 <= start < stop``; ``stop`` is on the grid
        when ``step`` divides the span, and never passed.
    step : float
        Spacing (m/s), > 0.
    max_speeds : int
        Most speeds (default 100000, as the command line's ``--max-speeds``).

    Returns
    -------
    numpy.ndarray of shape (n,)
        Increasing speeds (m/s), read-only.

    Raises
    ------
    InputError
        Unless ``0 <= start < stop``, ``step > 0`` and at most ``max_speeds`` speeds.

    See Also
    --------
    stability, eigenvalues : Take the grid as ``speeds=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.speeds(0, 2, 0.5).tolist()
    [0.0, 0.5, 1.0, 1.5, 2.0]
    >>> len(bm.speeds())                              # the thesis's 0..30 m/s in 0.05 m/s
    601
    """
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (start, stop, step)):
        raise InputError("speeds", f"{start!r}:{stop!r}:{step!r}", "start, stop and step as numbers (m/s)")
    if not (0 <= start < stop < float("inf") and step > 0 and (stop - start) / step < max_speeds
            and speed_count(start, stop, step) <= max_speeds):
        raise InputError("speeds", f"{start}:{stop}:{step}", f"speeds need 0 <= start < stop, step > 0 and at most "
                         f"{max_speeds} points (m/s), got {start}:{stop}:{step}")
    return speed_grid(start, stop, step)


def linear_model(params: BenchmarkParameters | LinearModel, stiffness: "ArrayLike | None" = None) -> LinearModel:
    """The linear model of a parameter set: the Whipple bicycle, rigid or with the quasi-static
    flexible rear frame of stiffness S.

    Parameters
    ----------
    params : BenchmarkParameters or LinearModel
        From :func:`bikemass.parameters` (SI); a :class:`~bikemass.LinearModel` is returned as
        it is.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) from :func:`bikemass.stiffness`; ``None`` = rigid.

    Returns
    -------
    LinearModel
        States roll-angle, steer-angle (rad), roll-rate, steer-rate (rad/s), heading (rad),
        lateral (m); inputs roll-torque, steer-torque (N m); ``A(v)``, ``B(v)`` as polynomials in
        speed.

    Raises
    ------
    InputError
        Parameters the model is not defined for, a bad S, or an S given with a LinearModel.
    InputTypeError
        ``params`` of another type.

    See Also
    --------
    stability : Analyses the model over speed.
    transfer_function, simulate : Its responses at one speed.

    Examples
    --------
    >>> import bikemass as bm
    >>> model = bm.linear_model(bm.parameters("benchmark"))
    >>> print(model.name, model.state_names, model.input_names)
    whipple ('roll-angle', 'steer-angle', 'roll-rate', 'steer-rate', 'heading', 'lateral')
    ('roll-torque', 'steer-torque')
    >>> model.state_matrix([5.0]).shape                 # A(v) at one speed: (speeds, 6, 6)
    (1, 6, 6)
    """
    if isinstance(params, LinearModel):
        if stiffness is not None:
            raise InputError("stiffness", "(matrix)", "no stiffness with a LinearModel (it is built in)")
        return params
    if not isinstance(params, BenchmarkParameters):
        raise wrong_type("params", params, "params must be BenchmarkParameters (bm.parameters) or a LinearModel")
    return whipple_model(check_parameters(params, "params"), _stiffness(stiffness))


def eigenvalues(params: BenchmarkParameters | LinearModel, stiffness: "ArrayLike | None" = None,
                speeds: "ArrayLike | None" = None, max_speeds: int = MAX_SPEEDS) -> Modes:
    """Eigenvalues over speed, followed across speed and named.

    Parameters
    ----------
    params : BenchmarkParameters or LinearModel
        As for :func:`linear_model`.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad); ``None`` = rigid.
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

    Raises
    ------
    InputError
        Bad parameters, S or speeds.

    See Also
    --------
    stability : The same modes with critical speeds and stable ranges.
    plot_eigenvalues : Draw them.

    Examples
    --------
    >>> import bikemass as bm
    >>> modes = bm.eigenvalues(bm.parameters("benchmark"), speeds=[0.0, 5.0])
    >>> print(modes.labels)
    ('weave 1', 'weave 2', 'capsize', 'caster')
    >>> weave = modes["weave 2"][1]           # 5 m/s; Meijaard et al. (2007), Table 2: -0.775341882 +- 4.46486771i
    >>> print(f"{weave.real:.9f} +- {abs(weave.imag):.8f}i 1/s")
    -0.775341882 +- 4.46486771i 1/s
    """
    return follow_modes(linear_model(params, stiffness), speed_values(speeds, max_speeds))


def stability(params: BenchmarkParameters | LinearModel, stiffness: "ArrayLike | None" = None,
              speeds: "ArrayLike | None" = None, marginal: float = DEFAULT_MARGINAL,
              max_speeds: int = MAX_SPEEDS) -> StabilityResult:
    """Eigenvalues, critical speeds and stable speed ranges of a bicycle.

    Parameters
    ----------
    params : BenchmarkParameters or LinearModel
        From :func:`bikemass.parameters`, or any model of the family (:func:`linear_model`,
        :mod:`bikemass.models`).
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad), e.g. ``bm.stiffness(bike, "steel")``; ``None`` = rigid.
    speeds : array_like of shape (n,), optional
        Increasing speeds >= 0 (m/s); default 0..30 m/s in 0.05 m/s steps (the thesis's).
        Critical speeds are exact (found without a grid) on the grid's span.
    marginal : float
        Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable (the
        thesis's 2 rad/s).
    max_speeds : int
        Most speeds taken (default 100000, as the command line's ``--max-speeds``); more is an
        InputError before any work.

    Returns
    -------
    StabilityResult
        ``.speeds`` (n,), ``.eigenvalues`` (n, m) complex, ``.crossings``, ``.weave_speeds``,
        ``.capsize_speeds``, ``.stable_speeds``, ``.ranges``, ``.mode_ranges``, ``.modes``.

    Raises
    ------
    InputError
        Bad parameters, S or speeds (more than ``max_speeds``), or a ``marginal`` that is not a
        positive finite modulus.

    See Also
    --------
    eigenvalues : The modes alone.
    plot_eigenvalues, plot_critical_speeds : Draw results.
    sensitivity : Derivatives of the critical speeds.

    Examples
    --------
    The benchmark bicycle's weave and capsize speeds: Meijaard et al. (2007) print 4.29238253634111
    and 6.02426201538837 m/s; the exact values (50-digit arithmetic) are 4.2923825363411040 and
    6.0242620153883589 m/s.

    >>> import bikemass as bm
    >>> result = bm.stability(bm.parameters("benchmark"))
    >>> print(f"{result.weave_speeds[0]:.9f} {result.capsize_speeds[0]:.9f}")
    4.292382536 6.024262015
    >>> [(round(a, 4), round(b, 4)) for a, b in result.stable_speeds]
    [(4.2924, 6.0243)]

    A steel rear frame in series with gravity:

    >>> bike = bm.load_bicycle("jamis")
    >>> r = bm.stability(bm.parameters(bike, "relaxed"), stiffness=bm.stiffness(bike, "steel"))
    >>> print(f"weave {r.weave_speeds[0]:.4f} m/s, capsize {r.capsize_speeds[0]:.4f} m/s")
    weave 5.7421 m/s, capsize 8.5505 m/s
    """
    if isinstance(marginal, bool) or not isinstance(marginal, (int, float)) or not 0 < marginal < float("inf"):
        raise InputError("marginal", marginal, "a positive finite modulus in rad/s")
    S = _stiffness(stiffness)
    return analyse(linear_model(params, S), speed_values(speeds, max_speeds), marginal, S)
