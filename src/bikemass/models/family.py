"""The members' linear models from the generated code: one combination's matrices for any parameters.

:func:`build` takes the typed parameters (a benchmark set, the leaning rider's, tyres) and returns
the :class:`~bikemass.models.linear.LinearModel`; :func:`linear_model` does the same from the flat
``{name: float}`` the generated code takes; :func:`state_coefficients` evaluates thousands of
configurations at once (arrays for parameters) for sweeps.
"""

import importlib
from functools import lru_cache
from types import MappingProxyType

import numpy as np

from ..core.errors import InputError
from ..core.frozen import readonly
from .linear import LinearModel, SecondOrder, polynomial, state_form
from .parameters import NAMES, BenchmarkParameters
from .registry import BASE, SPECS, by_keyword, module_name, parse_model
from .signals import signal


@lru_cache(maxsize=None)
def generated(model):
    """The generated module of ``model`` (a name or :class:`~bikemass.models.registry.ModelChoice`).

    Imported on first use, not with bikemass: each module is a few hundred lines of numpy that
    only a model of that combination needs."""
    return importlib.import_module(f"{__package__}.generated.{module_name(parse_model(model).members)}")


def parameter_names(model):
    """The names of the parameters that the code of ``model`` takes, in order (the generated code's, then
    those of the members without a derivation)."""
    return tuple(name for name, _, _ in parameters_of(model))


def parameters_of(model):
    """``(name, unit, description)`` of every parameter of ``model`` (:func:`parameter_names`)."""
    extra = tuple(p for spec in parse_model(model).specs if not spec.derived for p in spec.runtime().PARAMETERS)
    return (*generated(model).PARAMETERS, *extra)


def member_inputs(model):
    """``{name: (member spec, SI unit)}`` (read-only): the parameters of ``model``'s code that are inputs of a
    scenario (each member's ``INPUTS``, :mod:`bikemass.models.members.spec`), in the order of its members;
    empty for the Whipple bicycle."""
    return _member_inputs(parse_model(model))


@lru_cache(maxsize=None)
def _member_inputs(choice):
    if not choice.members:
        return MappingProxyType({})
    units = {name: unit for name, unit, _ in parameters_of(choice)}
    return MappingProxyType({name: (spec, units[name]) for spec in choice.specs for name in (spec.hook("INPUTS") or {})})


def input_owner(name):
    """The member (:class:`~bikemass.models.members.spec.Member`) whose ``INPUTS`` hold ``name``, or ``None``."""
    return _owners().get(name)


@lru_cache(maxsize=1)
def _owners():
    return MappingProxyType({name: spec for spec in SPECS for name in (spec.hook("INPUTS") or {})})


@lru_cache(maxsize=None)
def member_code_names(choice):
    """The parameters of the code of the model ``choice`` (a :class:`~bikemass.models.registry.ModelChoice`)
    beyond the 26 benchmark names (frozenset): its members' own, inputs or not."""
    return frozenset(parameter_names(choice)) - frozenset(NAMES)


def coefficients(model, values):
    """``(E, A, B)`` of ``model`` in descriptor form (see :mod:`bikemass.models.derive.build`) at
    ``values`` (``{name: float or array}``, every name of :func:`parameter_names`; arrays broadcast,
    their shape leads the results)."""
    code = generated(model)
    missing = [name for name in parameter_names(model) if name not in values]
    if missing:
        raise ValueError(f"model {parse_model(model).name!r}: parameters missing: {', '.join(missing)}")
    choice = parse_model(model)
    for radius in ("rR", "rF"):          # the members' equations divide by the wheel radii (I/r: the spin)
        if choice.members and np.any(np.real(values[radius]) == 0):
            raise InputError(radius, "0 m", f"a wheel radius above 0 for the {choice.name} model (a point wheel, "
                             "the two-mass skate's, is the Whipple model's alone: --model whipple)")
    E, A, B = code.coefficients(*(x if type(x) is float else _number(values[name]) for name, _, _ in code.PARAMETERS
                                  for x in (values[name],)))
    for spec in parse_model(model).specs:                 # the members that change the combination's equations
        if not spec.derived:
            E, A, B = spec.runtime().transform({n: values[n] for n, _, _ in spec.runtime().PARAMETERS}, code, E, A, B)
    return E, A, B


def _number(x):
    """A parameter value as the generated code takes it: a Python float, or a float array (complex where
    ``x`` is: a complex step)."""
    if np.iscomplexobj(x):
        return np.asarray(x, dtype=complex)
    return float(x) if np.ndim(x) == 0 else np.asarray(x, dtype=float)


def state_coefficients(model, values):
    """``(A, B)`` of ``x' = sum_k v**k A[k] x + sum_k v**k B[k] u`` at ``values``: shapes
    (..., d + 1, N, N) and (..., d + 1, N, m), the leading dimensions those of the parameters."""
    return _state_form(generated(model), *coefficients(model, values))


def _state_form(code, E, A, B):
    """``E^-1 A``, ``E^-1 B`` of the generated ``(E, A, B)`` (:func:`~bikemass.models.linear.state_form`;
    E's mass rows are those of the coordinates' rates)."""
    return state_form(E, A, B, slice(code.COORDINATES, code.N_DYNAMIC))


class _Layout:
    """What :func:`linear_model` needs of a generated module, with some coordinates held at zero: the
    coordinate, its rate and its equation of motion removed (the constraint's force is what the
    removed equation would have said)."""

    def __init__(self, code, held):
        names = [n for n, _ in code.STATES]
        unknown = [h for h in held if h not in names[:code.COORDINATES]]
        if unknown:
            raise ValueError(f"model {code.NAME!r} has no coordinate {', '.join(unknown)}")
        drop = {names.index(h) for h in held} | {names.index(h) + code.COORDINATES for h in held}
        self.keep = [i for i in range(len(names)) if i not in drop]
        new = {old: k for k, old in enumerate(self.keep)}
        self.NAME, self.INPUTS, self.SECOND_ORDER = code.NAME, code.INPUTS, code.SECOND_ORDER
        self.STATES = tuple(code.STATES[i] for i in self.keep)
        self.COORDINATES = code.COORDINATES - len(held)
        self.N_DYNAMIC = code.N_DYNAMIC - 2 * len(held)
        self.FAMILIES = tuple((f, tuple(new[i] for i in ix if i in new)) for f, ix in code.FAMILIES
                              if any(i in new for i in ix))

    def reduce(self, E, A, B):
        """``E`` (..., N, N), ``A`` (..., d + 1, N, N), ``B`` (..., d + 1, N, m) without the held rows and columns."""
        k = self.keep
        return E[..., k, :][..., k], A[..., k, :][..., k], B[..., k, :]


def linear_model(model, values, held=()):
    """The :class:`~bikemass.models.linear.LinearModel` of ``model`` at ``values`` (``{name: float}``);
    the coordinates named in ``held`` (e.g. ``"frame-twist"``) are held at zero."""
    code, E, A_terms, B_terms = _descriptor(model, values, held)
    if E.ndim != 2:
        raise ValueError(f"model {code.NAME!r}: one value per parameter expected (use state_coefficients "
                         f"for arrays)")
    A, B = _state_form(code, E, A_terms, B_terms)
    states = tuple(signal(n, u) for n, u in code.STATES)
    inputs = tuple(signal(n, u) for n, u in code.INPUTS)
    mechanics = None
    if code.SECOND_ORDER:
        n = code.COORDINATES
        q, dq = slice(0, n), slice(n, 2 * n)
        mechanics = SecondOrder(states[:n], readonly(E[dq, dq]), readonly(-A_terms[:, dq, dq]),
                                readonly(-A_terms[:, dq, q]), readonly(B_terms[0, dq]))
    return LinearModel(parse_model(model).name, states, code.N_DYNAMIC, inputs, readonly(A), readonly(B), mechanics,
                       code.FAMILIES)


def dynamic_derivatives(model, values, names, speed, step, held=()):
    """``{name: dA/dp}``: the derivative of the dynamic block of ``A(speed)`` of ``model`` ((n, n) for one
    speed, (k, n, n) for an array of k speeds; the model as
    :func:`linear_model` builds it at ``values``, ``held`` coordinates held) with respect to each
    parameter of ``names``, by the complex step ``i * step`` through the generated code: exact to
    rounding, no difference step to choose.  The parameters are stepped in one batch."""
    count = len(names)
    batch = {name: np.full(count, float(values[name])) for name in parameter_names(model)}
    for i, name in enumerate(names):
        stepped = batch[name].astype(complex)
        stepped[i] += 1j * step
        batch[name] = stepped
    code, E, A_terms, B_terms = _descriptor(model, batch, held)
    A, _ = _state_form(code, E, A_terms, B_terms)
    n = code.N_DYNAMIC
    # (speeds..., names, n, n) -> (names, speeds..., n, n)
    dynamic = np.moveaxis(polynomial(np.moveaxis(A[:, :, :n, :n], 1, 0), speed), -3, 0)
    return {name: dynamic[i].imag / step for i, name in enumerate(names)}


def _descriptor(model, values, held=()):
    """``(code, E, A, B)``: the generated module of ``model`` (its layout with the ``held`` coordinates
    removed) and its descriptor coefficients at ``values``."""
    code = generated(model)
    E, A_terms, B_terms = coefficients(model, values)
    if held:
        code = _Layout(code, tuple(held))
        E, A_terms, B_terms = code.reduce(E, A_terms, B_terms)
    return code, E, A_terms, B_terms


def typed_members(model, subject, members=None):
    """``(BenchmarkParameters, {member name: typed parameters})`` of ``model``: the rigid set and each member's
    parameters, from ``members`` (``{member name: given}``, each given as its member's ``coerce`` takes it:
    the typed value, a file, a mapping, or ``None`` for its default) and from ``subject``, a parameter set
    (:class:`~bikemass.models.parameters.BenchmarkParameters`, or one of a member's own types, e.g.
    :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters`: that member's parameters,
    held rigid for a model without it)."""
    choice = parse_model(model)
    members = {k: v for k, v in (members or {}).items() if v is not None}
    own = getattr(type(subject), "MODEL", BASE)
    if own != BASE:
        if choice.has(own):
            members.setdefault(own, subject)
        subject = subject.rigid()
    if not isinstance(subject, BenchmarkParameters):
        raise InputError("model", choice.name, f"benchmark parameters or a member's parameter set, not "
                         f"{type(subject).__name__}")
    for name in members:
        if not choice.has(name):
            raise InputError(name, choice.name, f"no {name} parameters for the model {choice.name} (add the "
                             f"{name} member: {choice.with_member(name).name})")
    return subject, {spec.name: spec.runtime().coerce(members.get(spec.name), spec.keyword or spec.name)
                     for spec in choice.specs}


def values(model, subject, *, members=None, **keywords):
    """The ``{name: float}`` of ``model`` from typed parameters (see :func:`build`)."""
    rigid, typed = typed_members(model, subject, {**(members or {}), **by_keyword(keywords)})
    return _values(model, rigid, typed)


def _values(model, rigid, typed):
    out = {name: getattr(rigid, name) for name in NAMES}
    for spec in parse_model(model).specs:
        out.update(spec.runtime().values(typed[spec.name], out))
    return out


def build(model, subject, *, members=None, **keywords):
    """The :class:`~bikemass.models.linear.LinearModel` of ``model`` (``"whipple"``, ``"rider-lean"``,
    ``"tyre"``, ``"flexible"`` or members joined by ``+``, or a
    :class:`~bikemass.models.registry.ModelChoice`).

    ``subject``: :class:`~bikemass.models.parameters.BenchmarkParameters`, or a member's own parameter set
    (:class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters`: needed by ``rider-lean``;
    a model without that member holds the upper body rigid).  ``members``: ``{member name: parameters}``
    (:mod:`bikemass.models.members`: e.g. ``{"tyre": Tyres(...)}``; a member left out takes its default,
    or says what it needs); parameters for a member the model does not have are an error.  ``keywords``: the
    same by a member's keyword or attribute (``tyres=``, ``compliances=``, ``arms=``).
    """
    rigid, typed = typed_members(model, subject, {**(members or {}), **by_keyword(keywords)})
    return linear_model(model, _values(model, rigid, typed), _held(model, typed))


def _held(model, typed):
    return tuple(c for spec in parse_model(model).specs for c in spec.hook("held", lambda t: ())(typed[spec.name]))


def held_coordinates(model, members):
    """The coordinates ``model`` holds at zero with the members' typed parameters ``members``
    (``{member name: typed}``): e.g. the infinitely stiff ones of the flexible member's compliances."""
    return _held(model, {spec.name: members.get(spec.name) for spec in parse_model(model).specs})
