"""The linear stability of a bicycle as one typed, immutable result (``bm.stability``).

:func:`stability` takes a benchmark parameter set and an optional rear-frame stiffness S, a
:class:`~bikemass.scenario.scenario.Scenario` (any member of the model family: ``model=``), or any
:class:`~bikemass.models.linear.LinearModel`, builds the model (by default the Whipple bicycle,
rigid or with S in series with gravity, Williams 2015 Eq. 3.27-3.30), and hands it to the one engine
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
from ..models.family import build as build_member
from ..models.lean import RiderLeanParameters
from ..models.linear import LinearModel
from ..models.registry import BASE, parse_model
from ..models.tyres import as_tyres
from ..models.whipple import whipple_model
from ..scenario.scenario import Built, Scenario
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


def linear_model(params, stiffness=None, model=None, tyres=None):
    """The linear model of a parameter set or a scenario (a
    :class:`~bikemass.models.linear.LinearModel` is returned as it is).

    Parameters
    ----------
    params : BenchmarkParameters, RiderLeanParameters, Scenario, Built or LinearModel
        From :func:`bikemass.parameters` (SI), the leaning rider's parameters, a
        :class:`~bikemass.scenario.scenario.Scenario` (built with its own model unless ``model``,
        ``tyres`` or ``stiffness`` say otherwise), a scenario built, or a model.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) from :func:`bikemass.stiffness`; ``None`` = rigid.  The
        Whipple model's quasi-static spring; with a scenario any stiffness choice it takes.
    model : str, optional
        ``"whipple"`` (default), ``"rider-lean"``, ``"tyre"``, ``"flexible"`` or members joined by
        ``+`` (:mod:`bikemass.models.registry`).  ``rider-lean`` needs the rider split at the hips
        (a Scenario with a rider, or RiderLeanParameters); ``flexible`` the bicycle's beam models
        (a Scenario).
    tyres : Tyres, str or Mapping, optional
        The ``tyre`` member's tyres (a tyre file or a mapping in its form; default
        :data:`~bikemass.models.tyres.DEFAULT_TYRES`).

    Returns
    -------
    LinearModel
        The Whipple bicycle's states roll-angle, steer-angle, roll-rate, steer-rate, heading,
        lateral and inputs roll-torque, steer-torque (a richer member adds its own);
        ``A(v)``, ``B(v)`` as polynomials in speed.
    """
    return built_model(params, stiffness, model, tyres)[0]


def built_model(params, stiffness=None, model=None, tyres=None):
    """``(LinearModel, S or None)`` of :func:`linear_model`'s arguments: the model and the quasi-static
    rear-frame stiffness (N m/rad) it holds."""
    given = {k: v for k, v in (("stiffness", stiffness), ("model", model), ("tyres", tyres)) if v is not None}
    if isinstance(params, (LinearModel, Built)):
        if given:
            what = "a LinearModel" if isinstance(params, LinearModel) else "a built scenario"
            raise InputError(next(iter(given)), "(argument)", f"none with {what} (it is built in; give it to "
                             "the Scenario)")
        return (params, None) if isinstance(params, LinearModel) else (params.model, params.stiffness)
    if isinstance(params, Scenario):
        built = (params.replace(**given) if given else params).build()
        return built.model, built.stiffness
    choice = parse_model(BASE if model is None else model)
    if isinstance(params, RiderLeanParameters) and not choice.has("rider-lean"):
        params = params.rigid()
    if not isinstance(params, (BenchmarkParameters, RiderLeanParameters)):
        raise wrong_type("params", params, "params must be BenchmarkParameters (bm.parameters), a Scenario or a "
                         "LinearModel")
    if not choice.members:
        S = _stiffness(stiffness)
        return whipple_model(check_parameters(params, "params"), S), S
    if _stiffness(stiffness) is not None:
        raise InputError("stiffness", "(matrix)", f"none with the model {choice.name}: a 2x2 S is the whipple "
                         "model's quasi-static spring (the flexible member takes a material: bm.Scenario(bike, "
                         "rider, stiffness=material, model=...))")
    if choice.has("flexible"):
        raise InputError("model", choice.name, "a Scenario for the flexible member (its compliances come from the "
                         "bicycle's beam models): bm.stability(bm.Scenario(bike, rider, stiffness='steel', "
                         f"model={choice.name!r}))")
    if choice.has("rider-lean") and not isinstance(params, RiderLeanParameters):
        raise InputError("model", choice.name, "the rider split at the hips for rider-lean: a Scenario with a "
                         f"rider (bm.Scenario(bike, rider, model={choice.name!r})) or RiderLeanParameters")
    if isinstance(params, BenchmarkParameters):
        check_parameters(params, "params")
    return build_member(choice, params, as_tyres(tyres) if choice.has("tyre") else tyres), None


def eigenvalues(params, stiffness=None, speeds=None, max_speeds=MAX_SPEEDS, model=None, tyres=None):
    """Eigenvalues over speed, followed across speed and named.

    Parameters
    ----------
    params, stiffness, model, tyres
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
    return follow_modes(linear_model(params, stiffness, model, tyres), speed_values(speeds, max_speeds))


def stability(params, stiffness=None, speeds=None, marginal=DEFAULT_MARGINAL, max_speeds=MAX_SPEEDS, model=None,
              tyres=None):
    """Eigenvalues, critical speeds and stable speed ranges of a bicycle.

    Parameters
    ----------
    params : BenchmarkParameters, RiderLeanParameters, Scenario, Built or LinearModel
        From :func:`bikemass.parameters`, a :class:`~bikemass.scenario.scenario.Scenario`, or any
        model of the family (see :func:`linear_model`).
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
    model, tyres
        The member of the model family and its tyres, as for :func:`linear_model`.

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
    linear, S = built_model(params, stiffness, model, tyres)
    return analyse(linear, speed_values(speeds, max_speeds), marginal, S)
