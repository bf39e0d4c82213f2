"""The members' linear models from the generated code: one combination's matrices for any parameters.

:func:`build` takes the typed parameters (a benchmark set, the leaning rider's, tyres) and returns
the :class:`~bikemass.models.linear.LinearModel`; :func:`linear_model` does the same from the flat
``{name: float}`` the generated code takes; :func:`state_coefficients` evaluates thousands of
configurations at once (arrays for parameters) for sweeps.
"""

import importlib
from functools import lru_cache

import numpy as np

from ..core.errors import InputError
from ..core.frozen import readonly
from .members.arms.parameters import Arms
from .members.flexible.parameters import Compliances
from .parameters import NAMES, BenchmarkParameters
from .members.rider_lean.parameters import RiderLeanParameters
from .linear import LinearModel, SecondOrder, polynomial, state_form
from .registry import module_name, parse_model
from .signals import signal
from .members.tyre.parameters import DEFAULT_TYRES, Tyres


@lru_cache(maxsize=None)
def generated(model):
    """The generated module of ``model`` (a name or :class:`~bikemass.models.registry.ModelChoice`).

    Imported on first use, not with bikemass: each module is a few hundred lines of numpy that
    only a model of that combination needs."""
    return importlib.import_module(f"{__package__}.generated.{module_name(parse_model(model).members)}")


def parameter_names(model):
    """The names of the parameters that the code of ``model`` takes, in order."""
    return tuple(name for name, _, _ in generated(model).PARAMETERS)


def coefficients(model, values):
    """``(E, A, B)`` of ``model`` in descriptor form (see :mod:`bikemass.models.derive.build`) at
    ``values`` (``{name: float or array}``, every name of :func:`parameter_names`; arrays broadcast,
    their shape leads the results)."""
    code = generated(model)
    try:
        args = [values[name] for name, _, _ in code.PARAMETERS]
    except KeyError:
        missing = [name for name, _, _ in code.PARAMETERS if name not in values]
        raise ValueError(f"model {code.NAME!r}: parameters missing: {', '.join(missing)}") from None
    return code.coefficients(*(x if type(x) is float else _number(x) for x in args))


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
    return LinearModel(code.NAME, states, code.N_DYNAMIC, inputs, readonly(A), readonly(B), mechanics,
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


def values(model, bicycle, tyres=None, compliances=None, arms=None):
    """The ``{name: float}`` of ``model`` from typed parameters (see :func:`build`)."""
    choice = parse_model(model)
    if choice.has("rider-lean"):
        if not isinstance(bicycle, RiderLeanParameters):
            raise InputError("model", choice.name, "the rider-lean model needs the rider split at the hips "
                             "(RiderLeanParameters: rider_lean_parameters(bicycle, rider) or from_moore_values)")
        out = bicycle.values()
    elif isinstance(bicycle, RiderLeanParameters):
        out = bicycle.rigid().to_dict()
    elif isinstance(bicycle, BenchmarkParameters):
        out = {name: getattr(bicycle, name) for name in NAMES}
    else:
        raise InputError("model", choice.name, f"benchmark or rider-lean parameters, not {type(bicycle).__name__}")
    if choice.has("tyre"):
        tyres = DEFAULT_TYRES if tyres is None else tyres
        if not isinstance(tyres, Tyres):
            raise InputError("tyres", choice.name, f"Tyres (front, rear), not {type(tyres).__name__}")
        out.update(tyres.values())
    elif tyres is not None:
        raise InputError("tyres", choice.name, f"no tyres for the model {choice.name} (add the tyre member: "
                         f"{_with(choice, 'tyre')})")
    if choice.has("flexible"):
        if not isinstance(compliances, Compliances):
            raise InputError("compliances", choice.name, "the flexible model needs the frame's and the fork's "
                             "compliances (Compliances: bikemass.fe.flexible.compliances(bicycle, material))")
        out.update(compliances.values(out))
    elif compliances is not None:
        raise InputError("compliances", choice.name, f"no compliances for the model {choice.name} (add the "
                         f"flexible member: {_with(choice, 'flexible')})")
    if choice.has("arms"):
        if not isinstance(arms, Arms):
            raise InputError("arms", choice.name, "the arms member needs the arms' stiffness and damping (Arms: "
                             "bikemass.models.members.arms.parameters.as_arms)")
        out.update(arms.values())
    elif arms is not None:
        raise InputError("arms", choice.name, f"no arms for the model {choice.name} (add the arms member: "
                         f"{_with(choice, 'arms')})")
    return out


def _with(choice, member):
    """The name of ``choice`` with ``member`` added."""
    return parse_model("+".join((*choice.members, member))).name


def build(model, bicycle, tyres=None, compliances=None, arms=None):
    """The :class:`~bikemass.models.linear.LinearModel` of ``model`` (``"whipple"``, ``"rider-lean"``,
    ``"tyre"``, ``"flexible"`` or members joined by ``+``, or a
    :class:`~bikemass.models.registry.ModelChoice`).

    ``bicycle``: :class:`~bikemass.models.parameters.BenchmarkParameters`, or
    :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` (needed by ``rider-lean``; a model without
    it holds the upper body rigid: :meth:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters.rigid`).
    ``tyres``: :class:`~bikemass.models.members.tyre.parameters.Tyres` for the ``tyre`` member (default
    :data:`~bikemass.models.members.tyre.parameters.DEFAULT_TYRES`); an error for a model without tyres.
    ``compliances``: :class:`~bikemass.models.members.flexible.parameters.Compliances` for the ``flexible`` member
    (:func:`bikemass.fe.flexible.compliances`; required); an infinitely stiff one (``None``)
    holds its coordinate at zero; an error for a model without the member.
    ``arms``: :class:`~bikemass.models.members.arms.parameters.Arms` for the ``arms`` member (required; an error for a
    model without it).
    """
    return linear_model(model, values(model, bicycle, tyres, compliances, arms), held_coordinates(model, compliances))


def held_coordinates(model, compliances):
    """The coordinates ``model`` holds at zero: the infinitely stiff ones of its ``compliances``."""
    return compliances.held if parse_model(model).has("flexible") and isinstance(compliances, Compliances) else ()
