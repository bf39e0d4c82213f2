"""The linear stability of a bicycle as one typed, immutable result (``bm.stability``).

:func:`stability` takes a benchmark parameter set and an optional rear-frame stiffness S, a
:class:`~bikemass.scenario.scenario.Scenario` (any member of the model family: ``model=``), or any
:class:`~bikemass.models.linear.LinearModel`, builds the model (by default the Whipple bicycle,
rigid or with S in series with gravity, Williams 2015 Eq. 3.27-3.30), and hands it to the one engine
(:mod:`bikemass.analysis.engine`): modes followed and named over a speed grid, exact critical
speeds and stable ranges.
"""
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from ..models.parameters import BenchmarkParameters
from ..models.canonical import CanonicalMatrices
from ..models.flexible_static import with_frame_stiffness
from ..models.plausibility import check_parameters
from ..core.errors import wrong_type
from ..core.choices import RIGID
from ..core.errors import InputTypeError
from ..scenario.catalog import stiffness_matrix
from ..core.errors import InputError, short
from ..core.real import finite_real
from ..core.frozen import readonly
from ..core.keywords import renamed_keywords
from ..core.limits import MAX_SPEEDS
from .engine.speeds import speed_range, speed_values
from ..models.control import Control, ScheduledModel, close_loop
from ..models.family import build as build_member
from ..models.members.rider_lean.parameters import RiderLeanParameters
from ..models.linear import LinearModel
from ..models.members.spec import Source
from ..models.registry import BASE, BY_NAME, by_keyword, model_of
from ..models.whipple import whipple_model
from ..models.whipple_generated import whipple_matrices
from ..scenario.scenario import Built, Scenario
from .engine.modes import Modes, follow_modes
from .engine.stability import StabilityResult, analyse

DEFAULT_MARGINAL = 2.0
"""Modulus (rad/s) below which an unstable eigenvalue counts as marginally stable (the thesis's)."""
MAX_MARGINAL = 1e6
"""Largest ``marginal`` modulus (rad/s): beyond every eigenvalue of a bicycle (``bikemass stability --marginal``'s bound)."""


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
        base = whipple_matrices(check_parameters(params, "params"))
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
        First speed and last speed at most (m/s), ``0 <= start < stop <= 1000``; ``stop`` is on
        the grid when ``step`` divides the span, and never passed.
    step : float
        Spacing (m/s), at least 1e-6 and at most ``stop - start``.
    max_speeds : int
        Most speeds (default 100000, as the command line's ``--max-speeds``).

    Returns
    -------
    numpy.ndarray of shape (n,)
        Increasing speeds (m/s), read-only.

    Raises
    ------
    InputError
        Unless ``0 <= start < stop <= 1000`` m/s, ``1e-6 <= step <= stop - start`` m/s and at most
        ``max_speeds`` speeds (:mod:`bikemass.core.limits`; the command line's ``--speeds`` alike).

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
    return readonly(speed_range(start, stop, step, max_speeds))


@renamed_keywords(params="system")
def linear_model(system: "BenchmarkParameters | RiderLeanParameters | Scenario | Built | LinearModel",
                 stiffness: "ArrayLike | None" = None, model: "str | None" = None,
                 control: "Control | str | Mapping | None" = None,
                 **members: object) -> "LinearModel | ScheduledModel":
    """The linear model of a parameter set or a scenario (a
    :class:`~bikemass.models.linear.LinearModel` is returned as it is).

    Parameters
    ----------
    system : BenchmarkParameters, RiderLeanParameters, Scenario, Built or LinearModel
        From :func:`bikemass.parameters` (SI), the leaning rider's parameters, a
        :class:`~bikemass.scenario.scenario.Scenario` (built with its own model unless ``model``,
        ``tyres`` or ``stiffness`` say otherwise), a scenario built, or a model.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad) from :func:`bikemass.stiffness`; ``None`` = rigid.  The
        Whipple model's quasi-static spring; with a scenario any stiffness choice it takes.
    model : str, optional
        ``"whipple"``, ``"rider-lean"``, ``"tyre"``, ``"flexible"`` or members joined by ``+``
        (:mod:`bikemass.models.registry`).  Default: the parameter set's own member (``rider-lean``
        for RiderLeanParameters, ``whipple`` for BenchmarkParameters); ``"whipple"`` with
        RiderLeanParameters holds the upper body rigid.  ``rider-lean`` needs the rider split at
        the hips (a Scenario with a rider, or RiderLeanParameters); ``flexible`` the bicycle's beam
        models (a Scenario).
    control : Control, str or Mapping, optional
        A linear feedback added to the inputs, ``u = K(v) y``, each gain scheduled in speed (a
        :class:`~bikemass.models.control.Control`, a control file or a mapping in its form:
        :mod:`bikemass.models.control`); the closed loop is returned.
    **members
        A member's parameters by the keyword it declares (:mod:`bikemass.models.members`), e.g.
        ``tyres=`` for the ``tyre`` member (a :class:`~bikemass.models.members.tyre.parameters.Tyres`,
        a tyre file or a mapping in its form; default
        :data:`~bikemass.models.members.tyre.parameters.DEFAULT_TYRES`), ``arms=`` for the ``arms``
        member; refused for a model without the member.

    Returns
    -------
    LinearModel or ScheduledModel
        States roll-angle, steer-angle (rad), roll-rate, steer-rate (rad/s), heading (rad),
        lateral (m); inputs roll-torque, steer-torque (N m) (a richer member adds its own);
        ``A(v)``, ``B(v)`` as polynomials in speed.  With ``control``: the closed loop, a
        :class:`~bikemass.models.control.ScheduledModel` (one polynomial per speed interval of
        the schedules; ``.at(v)`` is the LinearModel at one speed).

    Raises
    ------
    InputError
        Parameters the model is not defined for, a bad S, an unknown model, or an argument given
        with a LinearModel or a built scenario.
    InputTypeError
        ``system`` of another type.

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
    return built_model(system, stiffness, model, control, members)[0]


def built_model(params, stiffness=None, model=None, control=None, members=None):
    """``(LinearModel, S or None)`` of :func:`linear_model`'s arguments: the model (the closed loop
    with ``control``) and the quasi-static rear-frame stiffness (N m/rad) it holds.  ``members``:
    ``{keyword: parameters}`` of members (``{"tyres": ...}``)."""
    members = {k: v for k, v in (members or {}).items() if v is not None}
    if control is not None:
        linear, S = built_model(params, stiffness, model, None, members)
        return close_loop(linear, control), S
    given = {k: v for k, v in (("stiffness", stiffness), ("model", model), *members.items()) if v is not None}
    if isinstance(params, (ScheduledModel, LinearModel, Built)):
        if given:
            what = {ScheduledModel: "a closed loop", LinearModel: "a LinearModel"}.get(type(params), "a built scenario")
            raise InputError(next(iter(given)), "(argument)", f"none with {what} (it is built in; give it to "
                             "the Scenario)")
        return (params.model, params.stiffness) if isinstance(params, Built) else (params, None)
    if isinstance(params, Scenario):
        built = (params.replace(**given) if given else params).build()
        return built.model, built.stiffness
    choice = model_of(params, model)          # the parameter set's own member unless a model is named
    named = by_keyword(members, "members")
    for name, value in named.items():
        if not choice.has(name):
            key = BY_NAME[name].keyword or name
            raise InputError(key, short(value), f"a model with the {name} member (e.g. "
                             f"{choice.with_member(name).name}) for {key}; the model {choice.name} has none")
    if not isinstance(params, BenchmarkParameters) and getattr(type(params), "MODEL", BASE) == BASE:
        raise wrong_type("params", params, "params must be BenchmarkParameters (bm.parameters), a Scenario or a "
                         "LinearModel")
    if not choice.members:
        S = _stiffness(stiffness)
        subject = params if isinstance(params, BenchmarkParameters) else params.rigid()
        return whipple_model(check_parameters(subject, "params"), S), S
    if _stiffness(stiffness) is not None:
        rigid = " (or model='whipple': the rider held rigid)" if model is None else ""
        raise InputError("stiffness", "(matrix)", f"none with the model {choice.name}{rigid}: a 2x2 S is the "
                         "whipple model's quasi-static spring (the flexible member takes a material: "
                         "bm.Scenario(bike, rider, stiffness=material, model=...))")
    for spec in choice.specs:
        if spec.source is Source.BEAM_MODELS:
            raise InputError("model", choice.name, f"a Scenario for the {spec.name} member (its parameters come "
                             "from the bicycle's beam models): bm.stability(bm.Scenario(bike, rider, "
                             f"stiffness='steel', model={choice.name!r}))")
    if isinstance(params, BenchmarkParameters):
        check_parameters(params, "params")
    return build_member(choice, params, members=named), None


@renamed_keywords(params="system")
def eigenvalues(system: "BenchmarkParameters | RiderLeanParameters | Scenario | Built | LinearModel",
                stiffness: "ArrayLike | None" = None, speeds: "ArrayLike | None" = None,
                max_speeds: int = MAX_SPEEDS, model: "str | None" = None,
                control: "Control | str | Mapping | None" = None, **members: object) -> Modes:
    """Eigenvalues over speed, followed across speed and named.

    Parameters
    ----------
    system : BenchmarkParameters, RiderLeanParameters, Scenario, Built or LinearModel
        As for :func:`linear_model`.
    stiffness : array_like of shape (2, 2), optional
        Rear-frame stiffness S (N m/rad); ``None`` = rigid.
    speeds : array_like of shape (n,), optional
        Increasing speeds >= 0 (m/s); default 0..30 m/s in 0.05 m/s steps.
    max_speeds : int
        Most speeds taken (default 100000, as the command line's ``--max-speeds``); more is an
        InputError before any work.
    model : str, optional
        The model of the family, as for :func:`linear_model`.
    control : Control, str or Mapping, optional
        A feedback scheduled in speed (:mod:`bikemass.models.control`): the closed loop's modes.

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
    return follow_modes(linear_model(system, stiffness, model, control, **members), speed_values(speeds, max_speeds))


@renamed_keywords(params="system")
def stability(system: "BenchmarkParameters | RiderLeanParameters | Scenario | Built | LinearModel",
              stiffness: "ArrayLike | None" = None, speeds: "ArrayLike | None" = None,
              marginal: float = DEFAULT_MARGINAL, max_speeds: int = MAX_SPEEDS, model: "str | None" = None,
              control: "Control | str | Mapping | None" = None, **members: object) -> StabilityResult:
    """Eigenvalues, critical speeds and stable speed ranges of a bicycle.

    Parameters
    ----------
    system : BenchmarkParameters, RiderLeanParameters, Scenario, Built or LinearModel
        From :func:`bikemass.parameters`, a :class:`~bikemass.scenario.scenario.Scenario`, or any
        model of the family (see :func:`linear_model`).
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
    model : str, optional
        The member of the model family, as for :func:`linear_model`.
    control : Control, str or Mapping, optional
        A linear feedback ``u = K(v) y`` added to the inputs, each gain scheduled in speed (a
        :class:`~bikemass.models.control.Control`, a control file or a mapping in its form:
        :mod:`bikemass.models.control`): the closed loop is analysed, its critical speeds exact
        on every interval of the schedules.
    **members
        A member's parameters by its keyword (``tyres=``, ``arms=``), as for :func:`linear_model`.

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

    A steer-into-the-fall law (roll rate to steer torque, N m s/rad, ramped down to 0 at 4.7 m/s)
    stabilises the benchmark bicycle from a lower speed:

    >>> law = {"steer-torque": {"roll-rate": {"speeds": [0, 1.5, 4.7], "gains": [0, 12.48, 0]}}}
    >>> closed = bm.stability(bm.parameters("benchmark"), control=law)
    >>> print(f"stable from {closed.stable_speeds[0][0]:.4f} m/s")
    stable from 3.5122 m/s
    """
    if not finite_real(marginal) or not 0 < marginal <= MAX_MARGINAL:
        raise InputError("marginal", short(marginal), f"a modulus in rad/s above 0 and at most {MAX_MARGINAL:g} "
                         "(as the command line's --marginal)")
    linear, S = built_model(system, stiffness, model, control, members)
    return analyse(linear, speed_values(speeds, max_speeds), marginal, S)
