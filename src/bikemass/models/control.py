"""A linear feedback from named signals to named inputs, each gain scheduled in speed: the closed loop.

A control file (YAML, read through the input gate) maps each input of the model to the signals fed
back into it, each with a gain schedule::

    steer-torque:
      roll-rate: {speeds: [0.0, 1.5, 4.7, 1000.0], gains: [0.0, 12.48, 0.0, 0.0]}   # N m s/rad
      steer-angle: -2.0                                                             # N m/rad, any speed

A signal is a state or a further output of the model, by the names the model uses (``roll-angle``,
``steer-rate``, ``front-lateral``...; ``bikemass tf --help`` lists them); it must not depend on the
kinematic states (heading, lateral position), which would make them dynamic.  A schedule's speeds
(m/s, or with a unit: ``"6 km/h"``) increase strictly; its gain is linear between them and constant
outside them.  A gain is in SI: the input's unit per the signal's unit (N m per rad/s = N m s/rad for
roll-rate -> steer-torque).  A bare number is a gain at every speed.

**Sign convention.** ``u = K(v) y`` is *added* to the inputs: with ``y`` the signals and ``u`` the
input torques, the closed loop is ``x' = (A(v) + B(v) K(v) C) x + B(v) u_ext``.  In the benchmark
frame (x forward, z down) a positive roll is to the right and a positive steer torque steers right,
so a positive roll-rate -> steer-torque gain steers into the fall (the balance-assist law); a
negative steer-rate -> steer-torque gain is a steering damper of that many N m s/rad.

**Why pieces.**  The analyses of bikemass work on ``A(v)`` as a polynomial in ``v`` (the exact
critical speeds are the real roots of polynomial eigenvalue problems in ``v``).  A scheduled gain is
not a polynomial in ``v``, but it is linear on every interval between the schedule's speeds, so on
each interval the closed loop ``A(v) + B(v) (K0 + v K1) C`` is again a polynomial (one degree
higher).  :class:`ScheduledModel` keeps one :class:`~bikemass.models.linear.LinearModel` per interval
(:attr:`ScheduledModel.speed_pieces`); the engine solves each piece's polynomial problem on its own
interval and joins them (the closed loop is continuous in ``v``, so crossings at a joint are found
by one side).  One-speed analyses (transfer functions, responses, mode shapes) take the piece of
their speed: :meth:`ScheduledModel.at`, which keeps ``M, C(v), K(v), F`` (the feedback moved into
``C`` and ``K``) where the feedback reads only the coordinates and their rates.
"""

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, replace

import numpy as np

from ..core.config import Node, load_yaml
from ..core.errors import InputError, short
from ..core.frozen import readonly
from ..core.gate import plain_input
from .linear import LinearModel

MAX_SPEED = 1000.0
"""Highest schedule speed (m/s) taken, as every speed of bikemass (:mod:`bikemass.core.limits`)."""


@dataclass(frozen=True)
class Schedule:
    """A gain against speed: ``gains[i]`` at ``speeds[i]`` (m/s, strictly increasing), linear in
    between, constant outside.  Gains in the input's unit per the signal's unit."""

    speeds: tuple
    gains: tuple

    def __post_init__(self):
        if len(self.speeds) != len(self.gains) or not self.speeds:
            raise ValueError("a schedule needs as many gains as speeds, at least one")
        if any(b <= a for a, b in zip(self.speeds, self.speeds[1:])):
            raise ValueError("a schedule's speeds must increase strictly")

    def __call__(self, speed):
        """The gain at ``speed`` (m/s; an array gives an array)."""
        return np.interp(speed, self.speeds, self.gains)

    @property
    def constant(self):
        """Whether the gain is the same at every speed."""
        return all(g == self.gains[0] for g in self.gains)


@dataclass(frozen=True)
class Control:
    """A linear feedback ``u = K(v) y`` added to a model's inputs (see the module docstring).

    Attributes
    ----------
    gains : tuple of (str, str, Schedule)
        ``(input, signal, schedule)``: the input that the signal is fed back into, and its gain
        schedule (the input's unit per the signal's unit, against speed in m/s).
    source : str
        Where the control came from (a file), for messages.

    Examples
    --------
    >>> import bikemass as bm
    >>> law = bm.Control.from_mapping({"steer-torque": {"roll-rate": {"speeds": [0, 1.5, 4.7],
    ...                                                               "gains": [0, 12.48, 0]}}})
    >>> law.gain("steer-torque", "roll-rate", 3.1)              # N m s/rad: halfway down the ramp
    6.24
    >>> law.breaks
    (0.0, 1.5, 4.7)
    """

    gains: tuple
    source: str = "control"

    @property
    def breaks(self):
        """Every speed (m/s) where some gain's slope may change, ascending."""
        return tuple(sorted({float(v) for _, _, s in self.gains for v in (s.speeds if not s.constant else ())}))

    def gain(self, input, signal, speed):
        """The gain from ``signal`` to ``input`` at ``speed`` (m/s); 0 where none is given."""
        return float(sum(s(speed) for i, y, s in self.gains if i == input and y == signal))

    def to_dict(self):
        """The control file's mapping (speeds in m/s, gains in SI)."""
        out = {}
        for i, y, s in self.gains:
            out.setdefault(i, {})[y] = {"speeds": list(s.speeds), "gains": list(s.gains)}
        return out

    @classmethod
    def from_mapping(cls, mapping, source="control"):
        """A :class:`Control` of a mapping in the control file's form (errors name ``source``)."""
        node = Node(plain_input(mapping, source), source, "")
        node.mapping()
        return control_from_node(node)


def _schedule(node):
    if not isinstance(node.value, dict):
        return Schedule((0.0,), (_gain(node),))
    node.check_keys(required=("speeds", "gains"), optional=("note",))
    speeds = [e.number("speed", nonnegative=True) for e in node["speeds"].elements()]
    gains = [_gain(e) for e in node["gains"].elements()]
    if not speeds or len(speeds) != len(gains):
        node.fail(f"as many gains as speeds, at least one (got {len(speeds)} speeds, {len(gains)} gains)")
    if any(b <= a for a, b in zip(speeds, speeds[1:])):
        node.fail(f"speeds that increase strictly (m/s), got {short(node.value['speeds'])}", "speeds")
    if speeds[-1] > MAX_SPEED:
        node.fail(f"speeds up to {MAX_SPEED:g} m/s", "speeds")
    return Schedule(tuple(speeds), tuple(gains))


def _gain(node):
    x = node.value
    if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or abs(x) > 1e12:
        node.fail(f"a gain: a finite number in SI (the input's unit per the signal's unit), got {short(x)}")
    return float(x)


def control_from_node(node):
    """:class:`Control` of a config :class:`~bikemass.core.config.Node` (inputs -> signals -> schedules)."""
    gains = []
    for input_name, signals in node.items():
        if input_name in ("name", "source", "description"):
            continue
        for signal_name, schedule in signals.items():
            gains.append((str(input_name), str(signal_name), _schedule(schedule)))
    if not gains:
        node.fail("at least one gain: INPUT: {SIGNAL: {speeds: [...], gains: [...]}}")
    return Control(tuple(gains), str(node.source))


def load_control(source: "Control | str | os.PathLike | Mapping") -> Control:
    """A linear feedback scheduled in speed, from a control file (see the module docstring).

    Parameters
    ----------
    source : Control, str, os.PathLike or Mapping
        A control YAML file, a mapping in its form (``{input: {signal: {"speeds": [...] (m/s),
        "gains": [...] (SI)}}}`` or ``{input: {signal: gain}}``), or a :class:`Control` (returned
        as it is).

    Returns
    -------
    Control
        Each input's signals and gain schedules.

    Raises
    ------
    InputError
        A file that cannot be read, a schedule whose speeds do not increase strictly or whose gains
        do not match them, a gain that is not a finite number (naming the file and the key); a name
        the model does not have is refused when the loop is closed.

    See Also
    --------
    stability, linear_model : Take ``control=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.load_control({"steer-torque": {"steer-rate": -0.5}}).gain("steer-torque", "steer-rate", 7.0)
    -0.5
    """
    if isinstance(source, Control):
        return source
    if isinstance(source, Mapping):
        return Control.from_mapping(source)
    if isinstance(source, (str, os.PathLike)):
        return control_from_node(load_yaml(os.fspath(source)))
    raise InputError("control", "(argument)", f"a Control, a control YAML file or a mapping in its form, "
                     f"not {type(source).__name__}")


def _feedback(model, control):
    """``[(input index, signal row (N,), schedule)]`` of ``control`` on ``model``; InputError for a name
    the model does not have or a signal that depends on a kinematic state."""
    out = []
    for input_name, signal_name, schedule in control.gains:
        if input_name not in model.input_names:
            raise InputError(control.source, input_name, f"an input of the model {model.name}: "
                             f"{', '.join(model.input_names)}")
        if signal_name not in model.output_names:
            raise InputError(control.source, f"{input_name}.{signal_name}", f"a signal of the model {model.name}: "
                             f"{', '.join(model.output_names)}")
        row = model.output_matrix([signal_name])[0]
        if np.any(row[model.n_dynamic:]):
            raise InputError(control.source, f"{input_name}.{signal_name}", "a signal of the dynamic states only "
                             f"(feeding back {signal_name} would make the kinematic states dynamic): "
                             f"{', '.join(s.name for s in model.dynamic_states)}")
        out.append((model.input_index(input_name), row, schedule))
    return out


def _feedback_matrix(model, feedback, speed):
    """``K(v) C`` (m, N) at one ``speed`` (m/s)."""
    F = np.zeros((len(model.inputs), len(model.states)))
    for i, row, schedule in feedback:
        F[i] += float(schedule(speed)) * row
    return F


def _closed_piece(model, F0, F1, name):
    """``model`` with ``A(v) + B(v) (F0 + v F1)`` (coefficients of ``v**k``), a polynomial again; its
    ``M, C(v), K(v), F`` too where the feedback is on the coordinates and their rates alone."""
    A, B = np.asarray(model.A), np.asarray(model.B)
    linear = bool(np.any(F1))
    degree = max(len(A), len(B) + linear)
    out = np.zeros((degree, *A.shape[1:]), dtype=np.result_type(A, B, float))
    out[:len(A)] = A
    for k, Bk in enumerate(B):
        out[k] += Bk @ F0
        if linear:
            out[k + 1] += Bk @ F1
    return replace(model, name=name, A=readonly(out), mechanics=_closed_mechanics(model, F0, F1))


def _closed_mechanics(model, F0, F1):
    """``M, C(v) - F Kd(v), K(v) - F Kq(v), F`` of the closed loop (``Kq``, ``Kd``: the feedback on the
    coordinates and on their rates), or ``None`` where the model has no mechanics, its input matrix
    depends on speed, or the feedback reads another state (a tyre's force: no ``M, C, K`` form)."""
    mech = model.mechanics
    if mech is None or len(model.B) != 1:
        return None
    n = len(mech.M)
    if np.any(F0[:, 2 * n:]) or np.any(F1[:, 2 * n:]):
        return None

    def closed(terms, columns):
        out = np.zeros((max(len(terms), 2), n, n), dtype=np.result_type(terms, float))
        out[:len(terms)] = terms
        out[0] -= mech.F @ F0[:, columns]
        out[1] -= mech.F @ F1[:, columns]
        return readonly(out if np.any(out[1:]) or len(terms) > 1 else out[:1])
    return replace(mech, C=closed(mech.C, slice(n, 2 * n)), K=closed(mech.K, slice(0, n)))


@dataclass(frozen=True, eq=False)
class ScheduledModel:
    """A closed loop whose gains are scheduled in speed: one polynomial
    :class:`~bikemass.models.linear.LinearModel` per speed interval (see the module docstring).

    It has the states, inputs, outputs and mode families of its open loop and the same
    ``state_matrix(v)``, ``dynamic_matrix(v)``, ``input_matrix(v)``, ``state_space(v)`` as a
    :class:`~bikemass.models.linear.LinearModel`, evaluated on the piece of each speed; the analyses
    of bikemass (``bm.stability``, ``bm.eigenvalues``) take it as they take a model.

    Attributes
    ----------
    open_loop : LinearModel
        The model without the feedback.
    control : Control
        The feedback.
    breaks : tuple of float
        The speeds (m/s) between the pieces, ascending.
    pieces : tuple of LinearModel
        ``pieces[k]`` holds on ``[breaks[k - 1], breaks[k]]`` (the first from 0 m/s, the last to
        any speed): the closed loop as a polynomial in speed there.

    Examples
    --------
    >>> import bikemass as bm
    >>> law = {"steer-torque": {"roll-rate": {"speeds": [0, 1.5, 4.7], "gains": [0, 12.48, 0]}}}
    >>> closed = bm.linear_model(bm.parameters("benchmark"), control=law)
    >>> closed.breaks, len(closed.pieces)
    ((0.0, 1.5, 4.7), 4)
    >>> closed.at(3.1).name                 # one speed: a LinearModel, exact on its interval
    'whipple, closed loop'
    """

    open_loop: LinearModel
    control: Control
    breaks: tuple
    pieces: tuple

    @property
    def name(self):
        """The open loop's name with ``, closed loop``."""
        return self.pieces[0].name

    def __getattr__(self, attribute):
        # what does not depend on speed is the open loop's: states, inputs, outputs, families, names
        if attribute in _SHARED:
            return getattr(self.pieces[0], attribute)
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {attribute!r}")

    @property
    def mechanics(self):
        """``None``: the closed loop's ``M, C(v), K(v)`` differ from piece to piece (each piece has its
        own where the feedback is on coordinates and rates: ``at(v).mechanics``)."""
        return None

    def _index(self, speed):
        return int(np.searchsorted(self.breaks, float(speed), side="right"))

    def at(self, speed):
        """The :class:`~bikemass.models.linear.LinearModel` of the piece holding ``speed`` (m/s): the
        closed loop exactly at that speed (and on its interval)."""
        return self.pieces[self._index(speed)]

    @property
    def speed_pieces(self):
        """``((lo, hi, LinearModel), ...)``: each piece and the speeds (m/s) it holds on."""
        edges = (-math.inf, *self.breaks, math.inf)
        return tuple((edges[k], edges[k + 1], piece) for k, piece in enumerate(self.pieces))

    def _each(self, method, speed):
        v = np.asarray(speed, dtype=float)
        if v.ndim == 0:
            return getattr(self.at(v), method)(float(v))
        return np.stack([getattr(self.at(x), method)(float(x)) for x in v]) if v.size else \
            getattr(self.pieces[0], method)(v)

    def state_matrix(self, speed):
        """``A(v) + B(v) K(v) C``: (N, N) for one speed (m/s), (n, N, N) for n speeds."""
        return self._each("state_matrix", speed)

    def dynamic_matrix(self, speed):
        """The dynamic block of :meth:`state_matrix`."""
        return self._each("dynamic_matrix", speed)

    def input_matrix(self, speed):
        """``B(v)`` (the open loop's)."""
        return self.open_loop.input_matrix(speed)

    def speed_derivative(self, speed):
        """``dA/dv`` (N, N) at one speed (m/s), on the piece holding it."""
        return self.at(speed).speed_derivative(speed)

    def state_space(self, speed, outputs=None):
        """``(A, B, C, D)`` of the closed loop at one speed (m/s)."""
        return self.at(speed).state_space(speed, outputs)

    def __repr__(self):
        return (f"ScheduledModel({self.name!r}, inputs fed back: "
                f"{', '.join(sorted({f'{y} -> {i}' for i, y, _ in self.control.gains}))}, "
                f"breaks={tuple(round(b, 6) for b in self.breaks)})")


_SHARED = frozenset(("states", "n_dynamic", "inputs", "families", "outputs", "state_names", "input_names",
                     "dynamic_states", "state_index", "input_index", "output_names", "output_signal",
                     "output_matrix", "B"))


def close_loop(model, control):
    """The :class:`ScheduledModel` of ``model`` (a :class:`~bikemass.models.linear.LinearModel`) with
    ``control`` (a :class:`Control`, a control file or a mapping in its form) added to its inputs."""
    control = load_control(control)
    if isinstance(model, ScheduledModel):
        raise InputError("control", control.source, "one control per model (this model has one already)")
    feedback = _feedback(model, control)
    breaks = control.breaks
    name = f"{model.name}, closed loop"
    edges = (*breaks[:1], *breaks, *breaks[-1:]) if breaks else (0.0, 0.0)
    pieces = []
    for a, b in zip(edges, edges[1:]):
        Fa = _feedback_matrix(model, feedback, a)
        if b > a:
            F1 = (_feedback_matrix(model, feedback, b) - Fa) / (b - a)
            F0 = Fa - a * F1
        else:                                   # before the first speed or after the last: constant
            F0, F1 = Fa, np.zeros_like(Fa)
        pieces.append(_closed_piece(model, F0, F1, name))
    return ScheduledModel(model, control, breaks, tuple(pieces))
