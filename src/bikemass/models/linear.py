"""The linear-model seam: a bicycle model linearised about the upright, straight run at speed v.

Every model of bikemass (the Whipple bicycle of Meijaard et al. 2007, its quasi-static flexible
rear frame, and the richer members of the family) is one :class:`LinearModel`: named states with
units, named inputs, and the state-space matrices as polynomials in the forward speed ``v`` (m/s)::

    x' = A(v) x + B(v) u,     A(v) = sum_k v**k A[k],     B(v) = sum_k v**k B[k]

The first :attr:`LinearModel.n_dynamic` states are the dynamic ones (their block of ``A`` decides
stability); the others (heading, lateral position) are kinematic: integrals of the dynamic states
that never feed back into them, kept for outputs, time responses and the rider in the loop.

A model with mechanical coordinates ``q`` (a second-order model)::

    M q'' + C(v) q' + K(v) q = F u,      C(v) = sum_k v**k C[k],  K(v) = sum_k v**k K[k]

keeps ``M, C, K, F`` as :class:`SecondOrder` beside its state-space form (``x = [q, q']`` first).
Analyses (stability, transfer functions, responses) take a :class:`LinearModel` and nothing else.
"""

import math
import numbers
from dataclasses import dataclass, field

import numpy as np

from ..core.errors import InputError, short
from ..core.frozen import readonly
from ..core.limits import MAX_SPEED


@dataclass(frozen=True)
class Signal:
    """A named quantity: a state, an input or an output (``Signal("roll-angle", "rad")``)."""

    name: str
    unit: str
    description: str = ""


@dataclass(frozen=True, eq=False)
class Output:
    """A named output that is not a state but a fixed combination of them: ``y = row . x``
    (``row`` of length N, read-only; units of ``signal.unit``)."""

    signal: Signal
    row: np.ndarray

    def __post_init__(self):
        object.__setattr__(self, "row", readonly(self.row))        # complex in the complex-step derivatives


def _coefficients(terms, shape, dtype=float):
    """``terms`` (a sequence of arrays, coefficient of ``v**k`` at index ``k``) as one read-only array
    of shape ``(d + 1, *shape)``; ``None`` entries are zero."""
    out = np.zeros((max(len(terms), 1), *shape), dtype=dtype)
    for k, t in enumerate(terms):
        if t is not None:
            out[k] = t
    return readonly(out)


def polynomial(coefficients, speed):
    """``sum_k v**k coefficients[k]`` at ``speed`` (m/s): one speed -> shape ``coefficients.shape[1:]``,
    an array of speeds (n,) -> ``(n, *coefficients.shape[1:])``."""
    v = np.asarray(speed, dtype=float)
    powers = v[..., None] ** np.arange(len(coefficients))
    # tensordot's own reshape and dot, without its checks (a third of its cost on one speed)
    flat = np.reshape(coefficients, (len(coefficients), -1))
    return (powers @ flat).reshape(v.shape + np.shape(coefficients)[1:])


@dataclass(frozen=True, eq=False)
class SecondOrder:
    """``M q'' + C(v) q' + K(v) q = F u`` of a model's mechanical coordinates ``q``.

    ``M`` (n, n); ``C`` and ``K`` (d + 1, n, n), coefficients of ``v**k``; ``F`` (n, m).  Units follow
    the coordinates (kg m^2, N m s/rad, N m/rad for angles driven by torques).
    """

    coordinates: tuple
    M: np.ndarray
    C: np.ndarray
    K: np.ndarray
    F: np.ndarray

    def damping(self, speed):
        """``C(v)`` at ``speed`` (m/s)."""
        return polynomial(self.C, speed)

    def stiffness(self, speed):
        """``K(v)`` at ``speed`` (m/s)."""
        return polynomial(self.K, speed)


@dataclass(frozen=True, eq=False)
class LinearModel:
    """One linear bicycle model: states, inputs, and ``A(v)``, ``B(v)`` as polynomials in speed.

    Attributes
    ----------
    name : str
        The model's name (``"whipple"``, ``"whipple+flexible-static"``, ...).
    states : tuple of Signal
        Every state, dynamic ones first.
    n_dynamic : int
        How many leading states are dynamic (the rest are kinematic integrators).
    inputs : tuple of Signal
        The inputs ``u`` (torques in N m).
    A : numpy.ndarray of shape (d + 1, N, N)
        ``A[k]`` multiplies ``v**k``; read-only.
    B : numpy.ndarray of shape (d + 1, N, m)
        ``B[k]`` multiplies ``v**k``; read-only.
    mechanics : SecondOrder or None
        ``M, C(v), K(v), F`` where the model has mechanical coordinates.
    families : tuple of (str, tuple of int)
        Mode families and the dynamic states that belong to them (for naming modes): the
        Whipple bicycle's roll and steer states are ``"bicycle"``; a richer model adds, e.g.,
        ``("lean", (4, 9))``.  Default: every dynamic state in ``"bicycle"``.
    outputs : tuple of Output
        Further named outputs beside the states, each a fixed combination of them (the Whipple
        bicycle's lateral position of the front contact).

    See Also
    --------
    bikemass.linear_model : The Whipple bicycle of a parameter set.
    bikemass.stability : Any model of the family is analysed the same way.

    Examples
    --------
    >>> import bikemass as bm
    >>> model = bm.linear_model(bm.parameters("benchmark"))
    >>> model.n_dynamic, model.state_names
    (4, ('roll-angle', 'steer-angle', 'roll-rate', 'steer-rate', 'heading', 'lateral'))
    >>> A = model.dynamic_matrix([5.0])[0]       # the dynamic 4x4 block at 5 m/s
    >>> import numpy as np
    >>> weave = max(np.linalg.eigvals(A), key=lambda z: z.imag)
    >>> print(f"{weave.real:.6f} +- {weave.imag:.6f}i")   # Meijaard et al. (2007), Table 2
    -0.775342 +- 4.464868i
    """

    name: str
    states: tuple
    n_dynamic: int
    inputs: tuple
    A: np.ndarray
    B: np.ndarray
    mechanics: SecondOrder | None = field(default=None)
    families: tuple = ()
    outputs: tuple = ()

    def __post_init__(self):
        if not self.families:
            object.__setattr__(self, "families", (("bicycle", tuple(range(self.n_dynamic))),))
        n, m = len(self.states), len(self.inputs)
        if self.A.shape[1:] != (n, n) or self.B.shape[1:] != (n, m) or not 0 < self.n_dynamic <= n:
            raise ValueError(f"model {self.name!r}: A {self.A.shape}, B {self.B.shape} do not fit "
                             f"{n} states ({self.n_dynamic} dynamic) and {m} inputs")
        if np.any(self.A[:, :self.n_dynamic, self.n_dynamic:]):
            raise ValueError(f"model {self.name!r}: kinematic states feed back into the dynamic ones")
        if any(o.row.shape != (n,) for o in self.outputs):
            raise ValueError(f"model {self.name!r}: every output's row must have {n} entries")

    @property
    def state_names(self):
        """The states' names, in order."""
        return tuple(s.name for s in self.states)

    @property
    def input_names(self):
        """The inputs' names, in order."""
        return tuple(s.name for s in self.inputs)

    @property
    def dynamic_states(self):
        """The dynamic states (those whose block of ``A`` decides stability)."""
        return self.states[:self.n_dynamic]

    def state_index(self, name):
        """Position of the state ``name``; ValueError naming the states otherwise."""
        try:
            return self.state_names.index(name)
        except ValueError:
            raise ValueError(f"model {self.name!r} has no state {name!r} "
                             f"(states: {', '.join(self.state_names)})") from None

    def input_index(self, name):
        """Position of the input ``name``; ValueError naming the inputs otherwise."""
        try:
            return self.input_names.index(name)
        except ValueError:
            raise ValueError(f"model {self.name!r} has no input {name!r} "
                             f"(inputs: {', '.join(self.input_names)})") from None

    @property
    def speed_pieces(self):
        """``((lo, hi, model), ...)``: the polynomials in speed the model is made of, and the speeds
        (m/s) each holds on; one for a :class:`LinearModel` (a closed loop with scheduled gains,
        :class:`~bikemass.models.control.ScheduledModel`, has one per interval)."""
        return ((-math.inf, math.inf, self),)

    def at(self, speed):
        """The model that holds at ``speed`` (m/s): this one (a scheduled closed loop gives the piece
        of that speed)."""
        return self

    def state_matrix(self, speed):
        """``A(v)``: shape (N, N) for one speed (m/s), (n, N, N) for an array of n speeds."""
        return polynomial(self.A, speed)

    def input_matrix(self, speed):
        """``B(v)``: shape (N, m) for one speed (m/s), (n, N, m) for an array of n speeds."""
        return polynomial(self.B, speed)

    @property
    def dynamic_coefficients(self):
        """The dynamic block of ``A`` as coefficients (d + 1, n, n) of ``v**k``."""
        n = self.n_dynamic
        return self.A[:, :n, :n]

    def speed_derivative(self, speed):
        """``dA/dv`` (N, N) at one speed (m/s)."""
        k = np.arange(1, len(self.A))
        return np.tensordot(k * float(speed) ** (k - 1), self.A[1:], axes=1) if len(k) else np.zeros_like(self.A[0])

    def dynamic_matrix(self, speed):
        """The dynamic block of ``A(v)``: (n, n) for one speed, (k, n, n) for k speeds."""
        return polynomial(self.dynamic_coefficients, speed)

    @property
    def output_names(self):
        """What can be an output: every state, then the further outputs, by name."""
        return self.state_names + tuple(o.signal.name for o in self.outputs)

    def output_signal(self, name):
        """The :class:`Signal` of the output ``name`` (a state or a further output)."""
        signals = self.states + tuple(o.signal for o in self.outputs)
        return signals[self._output_position(name)]

    def _output_position(self, name):
        try:
            return self.output_names.index(name)
        except ValueError:
            raise ValueError(f"model {self.name!r} has no output {name!r} "
                             f"(outputs: {', '.join(self.output_names)})") from None

    def output_matrix(self, names=None):
        """``C`` (p, N) giving the outputs ``names`` (states or further outputs; default: every
        state) from the states."""
        names = self.state_names if names is None else tuple(names)
        C = np.zeros((len(names), len(self.states)))
        for row, name in enumerate(names):
            k = self._output_position(name)
            if k < len(self.states):
                C[row, k] = 1.0
            else:
                C[row] = self.outputs[k - len(self.states)].row
        return C

    def state_space(self, speed, outputs=None):
        """``(A, B, C, D)`` at one speed (m/s); ``C`` gives ``outputs`` (names of states or further
        outputs; default every state)."""
        C = self.output_matrix(outputs)
        return self.state_matrix(speed), self.input_matrix(speed), C, np.zeros((len(C), len(self.inputs)))

    def to_scipy(self, speed, outputs=None):
        """The state space at one speed as a :class:`scipy.signal.StateSpace` (continuous time).

        Parameters
        ----------
        speed : float
            Forward speed (m/s).
        outputs : sequence of str, optional
            Names of the outputs (states or further outputs, :attr:`output_names`); default every
            state and every further output.

        Returns
        -------
        scipy.signal.StateSpace
            ``A`` (N, N), ``B`` (N, m), ``C`` (p, N), ``D`` (p, m) in SI; the rows and columns in the
            order of :attr:`states`, :attr:`inputs` and ``outputs`` (scipy keeps no names).

        Raises
        ------
        InputError
            A speed that is not a finite number in 0..1000 m/s, or an unknown output.

        Examples
        --------
        >>> import bikemass as bm
        >>> sys = bm.linear_model(bm.parameters("benchmark")).to_scipy(5.0)
        >>> sys.A.shape, sys.B.shape, sys.C.shape
        ((6, 6), (6, 2), (7, 6))
        """
        # lazy: scipy.signal is needed only for this export, and loads slowly
        import scipy.signal
        names = self._outputs(outputs)
        return scipy.signal.StateSpace(*self.state_space(_export_speed(speed), names))

    def to_control(self, speed, outputs=None):
        """The state space at one speed as a python-control ``StateSpace`` with the signal names.

        Needs python-control (``pip install 'bikemass[control]'``).

        Parameters
        ----------
        speed : float
            Forward speed (m/s).
        outputs : sequence of str, optional
            Names of the outputs (states or further outputs, :attr:`output_names`); default every
            state and every further output.

        Returns
        -------
        control.StateSpace
            Continuous time, named after the model (``sys.name``), its states, inputs and outputs
            named as here (``roll-angle``, ``steer-torque``, ...); SI units.

        Raises
        ------
        ImportError
            python-control is not installed.
        InputError
            A speed that is not a finite number in 0..1000 m/s, or an unknown output.

        Examples
        --------
        >>> import bikemass as bm
        >>> sys = bm.linear_model(bm.parameters("benchmark")).to_control(5.0)
        >>> sys.input_labels, sys.nstates
        (['roll-torque', 'steer-torque'], 6)
        """
        try:
            # lazy: python-control is an optional extra, needed only for this export
            import control
        except ImportError as exc:
            raise ImportError("LinearModel.to_control needs python-control: pip install 'bikemass[control]'") from exc
        names = self._outputs(outputs)
        A, B, C, D = self.state_space(_export_speed(speed), names)
        return control.ss(A, B, C, D, states=list(self.state_names), inputs=list(self.input_names),
                          outputs=list(names), name=self.name)

    def _outputs(self, outputs):
        """The outputs of an export (default every state and further output); InputError naming an
        unknown one."""
        names = self.output_names if outputs is None else tuple(outputs)
        for name in names:
            if name not in self.output_names:
                raise InputError("outputs", short(name), f"outputs of the {self.name} model: one of "
                                 + ", ".join(self.output_names))
        return names

    def __repr__(self):
        return (f"LinearModel({self.name!r}, states=({', '.join(self.state_names)}), "
                f"inputs=({', '.join(self.input_names)}), degree={len(self.A) - 1})")


def _export_speed(speed):
    """``speed`` (m/s) of an exported state space as a float; InputError unless a finite number in
    0..:data:`~bikemass.core.limits.MAX_SPEED` (as every analysis takes)."""
    if isinstance(speed, bool) or not isinstance(speed, numbers.Real) or not math.isfinite(speed) \
            or not 0 <= speed <= MAX_SPEED:
        raise InputError("speed", short(speed), f"a forward speed in m/s, a finite number in 0..{MAX_SPEED:g}")
    return float(speed)


def state_form(E, A, B, mass):
    """The state-space coefficients ``E^-1 A[k]``, ``E^-1 B[k]`` of a descriptor form
    ``E x' = sum_k v**k A[k] x + sum_k v**k B[k] u``: the one place a state matrix is assembled.

    Parameters
    ----------
    E : numpy.ndarray (..., N, N)
        The descriptor matrix: a row of the identity outside the ``mass`` rows, the mass matrix
        (invertible) in the ``mass`` rows and columns.
    A : numpy.ndarray (..., d + 1, N, N)
        Coefficients of ``v**k``.
    B : numpy.ndarray (..., d + 1, N, m)
        Coefficients of ``v**k``.
    mass : slice
        The rows (and columns) of ``E`` holding the mass matrix.

    Returns
    -------
    (numpy.ndarray, numpy.ndarray)
        ``A`` and ``B`` of ``x' = A(v) x + B(v) u``, same shapes (new arrays).  Only the mass rows
        are solved, so the exact zeros and ones of the other rows stay exact.
    """
    inverse = np.linalg.inv(E[..., None, mass, mass])
    A, B = np.array(A), np.array(B)
    A[..., mass, :] = inverse @ A[..., mass, :]
    B[..., mass, :] = inverse @ B[..., mass, :]
    return A, B


def second_order_model(name, coordinates, rates, M, C, K, F, inputs, kinematics=(), families=None, outputs=()):
    """A :class:`LinearModel` from ``M q'' + C(v) q' + K(v) q = F u`` and kinematic states.

    Parameters
    ----------
    name : str
        The model's name.
    coordinates, rates : sequence of Signal
        The states ``q`` and ``q'`` (same length n).
    M : array_like (n, n)
        Mass matrix; must be invertible.
    C, K : sequence of array_like (n, n) or None
        Coefficients of ``v**k`` of the damping and stiffness matrices (``None`` = zero).
    F : array_like (n, m)
        How the inputs enter the equations of motion.
    inputs : sequence of Signal
        The m inputs.
    kinematics : sequence of (Signal, sequence of array_like)
        Kinematic states ``z_j' = sum_k v**k r_jk . [q, q', z]``, each given by its Signal and the
        coefficients ``r_jk`` (rows of length ``2 n + len(kinematics)``, zero on the dynamic block's
        feedback: kinematic states must not feed back).
    families : mapping of str to sequence of int, optional
        Mode families by coordinate index (each takes the coordinate and its rate); default:
        every coordinate in ``"bicycle"``.
    outputs : sequence of (Signal, array_like)
        Further outputs, each a fixed combination (a row of length ``2 n + len(kinematics)``)
        of the states.

    Returns
    -------
    LinearModel
    """
    dtype = np.result_type(float, M, *(x for x in (*C, *K) if x is not None))   # complex for the complex step
    M = np.asarray(M, dtype=dtype)
    n = len(M)
    F = np.asarray(F, dtype=float).reshape(n, len(inputs))
    N = 2 * n + len(kinematics)
    degree = max(len(C), len(K), 1, *(len(rows) for _, rows in kinematics)) - 1
    mech = SecondOrder(tuple(coordinates), readonly(M), _coefficients(C, (n, n), dtype),
                       _coefficients(K, (n, n), dtype), readonly(F))
    E = np.eye(N, dtype=dtype)
    E[n:2 * n, n:2 * n] = M
    A = np.zeros((degree + 1, N, N), dtype=dtype)
    A[0, :n, n:2 * n] = np.eye(n)
    A[:len(mech.K), n:2 * n, :n] = -mech.K
    A[:len(mech.C), n:2 * n, n:2 * n] = -mech.C
    for j, (_, rows) in enumerate(kinematics):
        for k, row in enumerate(rows):
            if row is not None:
                A[k, 2 * n + j] = row
    B = np.zeros((1, N, len(inputs)), dtype=dtype)
    B[0, n:2 * n] = F
    A, B = state_form(E, A, B, slice(n, 2 * n))
    states = (*coordinates, *rates, *(s for s, _ in kinematics))
    groups = tuple((f, tuple(sorted((*idx, *(n + i for i in idx))))) for f, idx in (families or {}).items())
    return LinearModel(name, tuple(states), 2 * n, tuple(inputs), readonly(A), readonly(B), mech, groups,
                       tuple(Output(signal, row) for signal, row in outputs))
