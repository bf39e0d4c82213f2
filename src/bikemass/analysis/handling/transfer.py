"""Transfer functions of a linear model from one input to one output, as zeros, poles and gain::

    G(s) = gain * prod(s - z) / prod(s - p)

:func:`zeros_poles_gain` works on any single-input single-output state space ``(A, b, c)``:

* States the input never reaches, or that never reach the output (by the pattern of nonzero
  entries of ``A``: the heading and lateral integrators of the Whipple bicycle for a roll or
  steer output), are dropped exactly; numerical pole-zero cancellation is never attempted.
* The poles are the eigenvalues of what is left (LAPACK ``geev``).
* The relative degree ``r`` is the first ``k`` with ``c A^(k-1) b != 0``, and the gain is that
  Markov parameter, ``c A^(r-1) b`` (the high-frequency asymptote ``G(s) ~ gain / s^r``).
* The zeros are the ``n - r`` finite generalized eigenvalues of the Rosenbrock pencil
  ``([[A, b], [c, 0]], diag(I, 0))`` (LAPACK ``ggev``), the invariant zeros.
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike
import scipy.linalg

from ...core.results import Result, quantity, quantity_in
from ...core.frozen import readonly, short_repr
from ...core.tables import Table
from .plant import System, linear_model, signal_unit, siso

ORTHOGONAL = 1e-12
"""``|c x| <= ORTHOGONAL |c| |x|`` counts as zero when finding the relative degree (the Markov
parameters ``c A^k b`` that vanish by the model's structure come out as exact zeros or as
rounding noise of about 1e-16 of the terms they are summed from)."""

ROOTS_UNIT = "1/s (pairs: real, imaginary)"


def coupled_states(A, b, c):
    """Boolean mask (N,) of the states that the input ``b`` reaches and that reach the output ``c``,
    by the pattern of nonzero entries of ``A`` (a state ``j`` drives state ``i`` when ``A[i, j] != 0``)."""
    drives = A != 0
    reached, seen = b != 0, c != 0
    for _ in range(len(A)):
        reached_next = reached | drives[:, reached].any(axis=1)
        seen_next = seen | drives[seen, :].any(axis=0)
        if np.array_equal(reached_next, reached) and np.array_equal(seen_next, seen):
            break
        reached, seen = reached_next, seen_next
    return reached & seen


def zeros_poles_gain(A, b, c):
    """Zeros (complex), poles (complex) and gain (float) of ``c (sI - A)^-1 b``.

    Parameters
    ----------
    A : array_like (N, N)
        State matrix.
    b : array_like (N,)
        The input's column.
    c : array_like (N,)
        The output's row.

    Returns
    -------
    zeros, poles : numpy.ndarray (complex)
        Sorted by real then imaginary part.  Both empty, with gain 0, when the output never
        responds to the input.
    gain : float
        The leading coefficient: ``G(s) = gain * prod(s - z) / prod(s - p)``.
    """
    A, b, c = (np.asarray(x, dtype=float) for x in (A, b, c))
    keep = coupled_states(A, b, c)
    A, b, c = A[np.ix_(keep, keep)], b[keep], c[keep]
    n = len(A)
    x, degree, gain = b, None, 0.0
    for k in range(1, n + 1):
        markov = float(c @ x)
        if abs(markov) > ORTHOGONAL * np.linalg.norm(c) * np.linalg.norm(x):
            degree, gain = k, markov
            break
        x = A @ x
    if degree is None:
        return np.zeros(0, complex), np.zeros(0, complex), 0.0
    poles = np.sort_complex(scipy.linalg.eigvals(A))
    return invariant_zeros(A, b, c, n - degree), poles, gain


def invariant_zeros(A, b, c, count):
    """The ``count`` finite generalized eigenvalues of the pencil ``([[A, b], [c, 0]], diag(I, 0))``
    (sorted), the finite ones told from the infinite ones by the size of ``beta`` in
    ``lambda = alpha / beta``."""
    if count == 0:
        return np.zeros(0, complex)
    n = len(A)
    S = np.zeros((n + 1, n + 1))
    S[:n, :n], S[:n, n], S[n, :n] = A, b, c
    E = np.zeros((n + 1, n + 1))
    E[:n, :n] = np.eye(n)
    alpha, beta = scipy.linalg.eig(S, E, right=False, homogeneous_eigvals=True)
    finiteness = np.abs(beta) / np.hypot(np.abs(alpha), np.abs(beta))
    finite = np.argsort(-finiteness, kind="stable")[:count]
    return np.sort_complex(alpha[finite] / beta[finite])


def gain_unit(output_unit, input_unit, relative_degree):
    """The unit of the gain: ``output / (input s^r)`` (``G(s) ~ gain / s^r``); an output per
    second (``rad/s``) adds one to the power of s (``rad/(N m s^2)``)."""
    power = relative_degree
    while output_unit.endswith("/s"):
        output_unit, power = output_unit[:-2], power + 1
    tail = "" if power == 0 else (" s" if power == 1 else f" s^{power}")
    return f"{output_unit}/({input_unit}{tail})"


@dataclass(frozen=True, eq=False, repr=False)
class TransferFunction(Result):
    """``G(s) = gain * prod(s - z) / prod(s - p)`` from one input to one output at one speed.

    Attributes
    ----------
    input, output : str
        The names of the input and output signals.
    input_unit, output_unit : str
        Their units (``"N m"``, ``"rad"``, ...).
    speed : float
        Forward speed (m/s).
    zeros, poles : numpy.ndarray (complex)
        In 1/s, sorted by real then imaginary part; read-only.
    gain : float
        The leading coefficient, in :attr:`gain_unit`.

    See Also
    --------
    bikemass.transfer_function : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> tf = bm.transfer_function(bm.parameters("benchmark"), 5.0, "steer-torque", "roll-angle")
    >>> tf.relative_degree, tf.units()["gain"]
    (2, 'rad/(N m s^2)')
    >>> print(f"|G(2j)| = {abs(tf(2j)):.4f} {tf.output_unit}/({tf.input_unit})")
    |G(2j)| = 0.2109 rad/(N m)
    """

    input: str
    output: str
    input_unit: str
    output_unit: str
    speed: float = quantity("m/s", "forward speed")
    zeros: np.ndarray = quantity(ROOTS_UNIT, "the invariant zeros")
    poles: np.ndarray = quantity(ROOTS_UNIT, "the poles")
    gain: float = quantity_in("gain_unit", "the leading coefficient, in output_unit/(input_unit s^r)")

    def __post_init__(self):
        object.__setattr__(self, "zeros", readonly(self.zeros, complex))
        object.__setattr__(self, "poles", readonly(self.poles, complex))
        object.__setattr__(self, "speed", float(self.speed))
        object.__setattr__(self, "gain", float(self.gain))

    @property
    def relative_degree(self):
        """Poles minus zeros: ``G(s) ~ gain / s^r`` at high frequency."""
        return len(self.poles) - len(self.zeros)

    @property
    def gain_unit(self):
        """The unit of :attr:`gain`: ``output / (input s^r)``."""
        return gain_unit(self.output_unit, self.input_unit, self.relative_degree)

    def __call__(self, s):
        """``G(s)`` at the complex frequencies ``s`` (1/s; a number or an array)."""
        s = np.asarray(s, dtype=complex)
        num = np.prod(s[..., None] - self.zeros, axis=-1) if len(self.zeros) else np.ones_like(s)
        den = np.prod(s[..., None] - self.poles, axis=-1) if len(self.poles) else np.ones_like(s)
        return self.gain * num / den

    def to_dict(self):
        """Plain data: input, output, speed, zeros and poles as ``[real, imaginary]`` pairs, gain."""
        return {"input": self.input, "output": self.output, "speed": self.speed,
                "zeros": _pairs(self.zeros), "poles": _pairs(self.poles), "gain": self.gain}

    def tables(self):
        """``{"roots": Table}``: one row per zero and pole: ``part`` (``zero``, ``pole``), ``real`` and
        ``imaginary`` (1/s). Input, output, speed, gain and its unit are the frame's ``attrs``."""
        roots = np.concatenate([self.zeros, self.poles])
        columns = {"part": ["zero"] * len(self.zeros) + ["pole"] * len(self.poles), "real": roots.real,
                   "imaginary": roots.imag}
        attrs = {"input": self.input, "output": self.output, "speed": self.speed, "gain": self.gain,
                 "gain_unit": self.gain_unit}
        return {"roots": Table(columns, {"real": "1/s", "imaginary": "1/s"}, attrs)}

    def __repr__(self):
        return short_repr(self, ("input", self.input), ("output", self.output), ("speed", f"{self.speed:g} m/s"),
                          ("zeros", len(self.zeros)), ("poles", len(self.poles)), ("gain", f"{self.gain:.6g}"))


def _pairs(values):
    return [[float(z.real), float(z.imag)] for z in values]


def transfer_function(system: System, speed: float, input: str, output: str,
                      stiffness: "ArrayLike | None" = None) -> TransferFunction:
    """The transfer function from ``input`` to ``output`` at ``speed``, as zeros, poles and gain.

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A linear model, a scenario, or a parameter set (the Whipple bicycle, or the leaning rider's
        model of RiderLeanParameters).
    speed : float
        Forward speed (m/s).
    input : str
        An input of the model: ``"steer-torque"`` or ``"roll-torque"`` (N m).
    output : str
        A state or further output: ``"roll-angle"``, ``"steer-angle"`` (rad), ``"roll-rate"``,
        ``"steer-rate"`` (rad/s), ``"heading"`` (rad), ``"lateral"`` (rear contact, m),
        ``"front-lateral"`` (front contact, m), or a richer model's own.
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set.

    Returns
    -------
    TransferFunction
        ``G(s) = gain * prod(s - z) / prod(s - p)``; zeros and poles in 1/s.

    Raises
    ------
    InputError
        A speed that is not a finite number >= 0, an unknown input or output (the closest name
        is suggested), a bad S, or a system of another type.

    See Also
    --------
    frequency_response : The same transfer function on the imaginary axis.
    plot_bode : Draw frequency responses.

    Examples
    --------
    >>> import bikemass as bm
    >>> tf = bm.transfer_function(bm.parameters("benchmark"), 5.0, "steer-torque", "steer-angle")
    >>> print(f"{tf.gain:.5f}", [f"{z.real:+.4f}" for z in tf.zeros])
    4.32384 ['-3.1347', '+3.1347']
    """
    model = linear_model(system, stiffness)
    A, b, c = siso(model, speed, input, output)
    zeros, poles, gain = zeros_poles_gain(A, b, c)
    return TransferFunction(input, output, signal_unit(model, input), signal_unit(model, output),
                            float(speed), zeros, poles, gain)
