"""What every handling analysis starts from: a :class:`~bikemass.models.linear.LinearModel` at one
speed, its input column and its output row, with the arguments checked.

A *system* is a :class:`~bikemass.models.linear.LinearModel` (any member of the family: the
Whipple bicycle, a flexible frame, a leaning rider, ...), a
:class:`~bikemass.scenario.scenario.Scenario` (built with its own ``model``) or a
:class:`~bikemass.models.parameters.BenchmarkParameters` set, which is the Whipple bicycle of
:func:`~bikemass.models.whipple.whipple_model` (with the rear-frame stiffness S, N m/rad, when
one is given), or a :class:`~bikemass.models.members.rider_lean.parameters.RiderLeanParameters` set, which is the leaning
rider's model (both through :func:`bikemass.analysis.results.built_model`, as ``bm.stability``).  Bad arguments raise :class:`~bikemass.core.errors.InputError` naming the argument and
the choices.
"""



from ...core.choices import closest
from ...core.real import finite_real
from ...core.errors import InputError, short, wrong_type
from ...core.limits import MAX_SPEED
from ..results import built_model
from ...models.linear import LinearModel
from ...models.members.rider_lean.parameters import RiderLeanParameters
from ...models.parameters import BenchmarkParameters
from ...scenario.scenario import Built, Scenario

System = LinearModel | Scenario | Built | BenchmarkParameters | RiderLeanParameters
"""What a handling analysis takes as its ``system`` (:func:`linear_model`)."""


def linear_model(system, stiffness=None):
    """``system`` as a :class:`~bikemass.models.linear.LinearModel`.

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A model, a scenario (built: any member of the family, ``Scenario(..., model="rider-lean")``),
        the 26 Meijaard et al. (2007) parameters (SI) of a Whipple bicycle, or a leaning rider's.
    stiffness : array_like (2, 2) or None
        Rear-frame stiffness S (N m/rad) of a parameter set; ``None`` for a rigid frame.  Not
        allowed with a model (a model carries its own frame).

    Returns
    -------
    LinearModel
    """
    if isinstance(system, LinearModel):
        if stiffness is not None:
            raise InputError("stiffness", "(argument)", "a LinearModel carries its own frame: give the "
                             "stiffness to the model's builder (whipple_model(params, stiffness))")
        return system
    if isinstance(system, (BenchmarkParameters, RiderLeanParameters)):
        return built_model(system, stiffness)[0]          # the one coercion of a parameter set (its own member)
    if isinstance(system, (Scenario, Built)):
        if stiffness is not None:
            raise InputError("stiffness", "(argument)", "a scenario carries its own frame: give the stiffness "
                             "to the Scenario")
        return (system.build() if isinstance(system, Scenario) else system).model
    raise wrong_type("system", system, "a system is a LinearModel, a Scenario, BenchmarkParameters "
                     "(bm.parameters) or RiderLeanParameters")


def check_speed(speed, what="speed"):
    """``speed`` as a float (m/s); InputError unless a finite number in [0, :data:`~bikemass.core.limits.MAX_SPEED`]."""
    if not finite_real(speed) or not 0 <= speed <= MAX_SPEED:
        raise InputError(what, short(speed), f"a forward speed in m/s, a finite number in 0..{MAX_SPEED:g}")
    return float(speed)


def input_index(model, name):
    """Position of the input ``name`` of ``model``; InputError naming the inputs otherwise."""
    if not isinstance(name, str) or name not in model.input_names:
        raise InputError("input", short(name), f"one of {', '.join(model.input_names)}"
                         f"{closest(name, model.input_names)}")
    return model.input_names.index(name)


def output_row(model, name):
    """The row (N,) giving the output ``name`` (a state or a further output) from the states;
    InputError naming the outputs otherwise."""
    if not isinstance(name, str) or name not in model.output_names:
        raise InputError("output", short(name), f"one of {', '.join(model.output_names)}"
                         f"{closest(name, model.output_names)}")
    return model.output_matrix([name])[0]


def siso(model, speed, input, output):
    """``(A, b, c)`` of ``model`` at ``speed`` (m/s) from ``input`` to ``output`` (names): the
    state matrix (N, N), the input's column (N,) and the output's row (N,)."""
    v = check_speed(speed)
    j = input_index(model, input)
    c = output_row(model, output)
    return model.state_matrix(v), model.input_matrix(v)[:, j], c


def signal_unit(model, name):
    """The unit of the input or output ``name`` of ``model``."""
    for s in model.inputs:
        if s.name == name:
            return s.unit
    return model.output_signal(name).unit
