"""Frequency responses ``G(j w) = c (j w I - A)^-1 b`` of a linear model, in dB and degrees.

:func:`response` reduces ``A`` once to its complex Schur form ``A = Z T Z^H`` (``T`` upper
triangular, ``Z`` unitary; LAPACK ``gees``) and then solves ``(j w I - T) x = Z^H b`` for every
frequency at once by back substitution: a backward-stable solve whose cost per frequency is
``N^2`` multiplications, vectorised over the frequencies (element-wise numpy, no BLAS call).
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike
import scipy.linalg

from ...core.results import Result, quantity, quantity_in
from ...core.errors import InputError, short
from ...core.frozen import readonly, short_repr
from ...core.tables import Table
from .plant import System, linear_model, signal_unit, siso

MAX_FREQUENCIES = 1_000_000
"""Most frequencies of one response."""
FREQUENCY_RANGE = (1e-9, 1e9)
"""Angular frequencies (rad/s) a response is computed at (beyond, a bicycle's response is only
its asymptotes, and floating point overflows)."""


def response(A, b, c, frequencies):
    """``c (j w I - A)^-1 b`` (complex) at every angular frequency ``w`` of ``frequencies`` (rad/s).

    Parameters
    ----------
    A : array_like (N, N)
    b, c : array_like (N,)
    frequencies : array_like (n,)
        Angular frequencies (rad/s); where ``j w`` is an eigenvalue of ``A`` the response is
        infinite.

    Returns
    -------
    numpy.ndarray (n,), complex
    """
    A = np.asarray(A, dtype=float)
    T, Z = scipy.linalg.schur(A, output="complex")
    y = Z.conj().T @ np.asarray(b, dtype=complex)
    row = np.asarray(c, dtype=complex) @ Z
    s = 1j * np.asarray(frequencies, dtype=float)
    n = len(A)
    x = np.zeros((n, s.size), dtype=complex)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for i in range(n - 1, -1, -1):        # element-wise sums: no BLAS call (its threads only spin here)
            x[i] = (y[i] + (T[i, i + 1:, None] * x[i + 1:]).sum(axis=0)) / (s - T[i, i])
    return (row[:, None] * x).sum(axis=0)


def magnitude_db(values):
    """``20 log10 |G|`` (dB)."""
    with np.errstate(divide="ignore"):
        return 20 * np.log10(np.abs(values))


def phase_deg(values):
    """The phase of ``G`` in degrees, unwrapped along the frequencies (the first in (-180, 180])."""
    return np.degrees(np.unwrap(np.angle(values)))


def log_frequencies(start, stop, count):
    """``count`` angular frequencies (rad/s) spaced logarithmically from ``start`` to ``stop``;
    InputError unless ``0 < start < stop`` and ``2 <= count <=`` :data:`MAX_FREQUENCIES`."""
    values = (start, stop, count)
    low, high = FREQUENCY_RANGE
    if not all(isinstance(x, (int, float)) and not isinstance(x, bool) and np.isfinite(x) for x in values) \
            or not (low <= start < stop <= high) or int(count) != count or not 2 <= count <= MAX_FREQUENCIES:
        raise InputError("frequencies", short(values), f"START:STOP:N in rad/s with {low:g} <= START < STOP <= "
                         f"{high:g} and N a whole number of points, 2 <= N <= {MAX_FREQUENCIES} (spaced logarithmically)")
    return np.geomspace(start, stop, int(count))


def check_frequencies(frequencies):
    """``frequencies`` as a 1-D float array (rad/s): finite, > 0, increasing, at most
    :data:`MAX_FREQUENCIES`; InputError otherwise."""
    try:
        w = np.atleast_1d(np.asarray(frequencies, dtype=float))
    except (TypeError, ValueError, OverflowError):
        raise InputError("frequencies", short(frequencies), "angular frequencies in rad/s: numbers") from None
    low, high = FREQUENCY_RANGE
    if w.ndim != 1 or not 1 <= w.size <= MAX_FREQUENCIES or not np.all(np.isfinite(w)) or w[0] < low \
            or w[-1] > high or np.any(np.diff(w) <= 0):
        raise InputError("frequencies", short(frequencies), f"angular frequencies in rad/s: in {low:g}..{high:g}, "
                         f"increasing, at most {MAX_FREQUENCIES}")
    return w


MAGNITUDE_UNIT = "dB"
"""The unit of :attr:`FrequencyResponse.magnitude` (of the ratio in its ``ratio_unit``)."""
PHASE_UNIT = "deg"
"""The unit of :attr:`FrequencyResponse.phase`."""

DEFAULT_FREQUENCIES = (0.1, 100.0, 1000)
"""``(start, stop, count)`` of the default frequencies (rad/s, logarithmic)."""


@dataclass(frozen=True, eq=False, repr=False)
class FrequencyResponse(Result):
    """``G(j w)`` from one input to one output at one speed.

    Attributes
    ----------
    input, output : str
        The signals' names; ``input_unit``, ``output_unit`` their units.
    speed : float
        Forward speed (m/s).
    frequencies : numpy.ndarray (n,)
        Angular frequencies (rad/s).
    magnitude : numpy.ndarray (n,)
        ``20 log10 |G|`` in dB of the ratio in ``output_unit`` per ``input_unit``.
    phase : numpy.ndarray (n,)
        Degrees, unwrapped along the frequencies (the first value in (-180, 180]).

    Arrays are read-only; :attr:`values` is ``G(j w)`` itself (complex).

    See Also
    --------
    bikemass.frequency_response : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> fr = bm.frequency_response(bm.parameters("benchmark"), 5.0, "steer-torque", "roll-angle",
    ...                            frequencies=[1.0, 10.0])
    >>> fr.units()["magnitude"], fr.units()["phase"]
    ('dB (of rad/(N m))', 'deg')
    """

    input: str
    output: str
    input_unit: str
    output_unit: str
    speed: float = quantity("m/s", "forward speed")
    frequencies: np.ndarray = quantity("rad/s", "angular frequencies")
    values: np.ndarray = quantity_in("ratio_unit", "G(j w), complex, in output_unit/(input_unit)")

    def __post_init__(self):
        object.__setattr__(self, "frequencies", readonly(self.frequencies, float))
        object.__setattr__(self, "values", readonly(self.values, complex))
        object.__setattr__(self, "speed", float(self.speed))

    @property
    def magnitude(self):
        """``20 log10 |G(j w)|`` (dB), read-only."""
        return readonly(magnitude_db(self.values))

    @property
    def phase(self):
        """Phase of ``G(j w)`` (degrees, unwrapped), read-only."""
        return readonly(phase_deg(self.values))

    @property
    def ratio_unit(self):
        """The unit of ``|G|`` (the ratio the decibels are of)."""
        return f"{self.output_unit}/({self.input_unit})"

    def to_dict(self):
        """Plain data: input, output, speed, frequencies (rad/s), magnitude (dB), phase (deg)."""
        return {"input": self.input, "output": self.output, "speed": self.speed,
                "frequencies": self.frequencies.tolist(), "magnitude": self.magnitude.tolist(),
                "phase": self.phase.tolist()}

    def units(self):
        """The units block of :meth:`to_dict`: speed and frequencies as their fields declare, the
        magnitude in :data:`MAGNITUDE_UNIT` of :attr:`ratio_unit`, the phase in :data:`PHASE_UNIT`."""
        declared = self.field_units()
        return {"speed": declared["speed"], "frequencies": declared["frequencies"],
                "magnitude": f"{MAGNITUDE_UNIT} (of {self.ratio_unit})", "phase": PHASE_UNIT}

    def tables(self):
        """``{"response": Table}``: one row per frequency: ``frequency`` (rad/s), ``frequency_hz``
        (Hz), ``magnitude`` (dB), ``phase`` (deg), ``real`` and ``imaginary`` (of ``G(j w)``, in
        :attr:`ratio_unit`). Input, output and speed are the frame's ``attrs``."""
        columns = {"frequency": self.frequencies, "frequency_hz": self.frequencies / (2 * np.pi),
                   "magnitude": self.magnitude, "phase": self.phase, "real": self.values.real,
                   "imaginary": self.values.imag}
        units = {"frequency": "rad/s", "frequency_hz": "Hz", "magnitude": f"{MAGNITUDE_UNIT} (of {self.ratio_unit})",
                 "phase": PHASE_UNIT, "real": self.ratio_unit, "imaginary": self.ratio_unit}
        return {"response": Table(columns, units, {"input": self.input, "output": self.output, "speed": self.speed})}

    def __repr__(self):
        w = self.frequencies
        return short_repr(self, ("input", self.input), ("output", self.output), ("speed", f"{self.speed:g} m/s"),
                          ("frequencies", f"{w[0]:g}..{w[-1]:g} rad/s x {len(w)}"))


def frequency_response(system: System, speed: float, input: str, output: str,
                       frequencies: "ArrayLike | None" = None,
                       stiffness: "ArrayLike | None" = None) -> FrequencyResponse:
    """The frequency response ``G(j w) = c (j w I - A)^-1 b`` from ``input`` to ``output``.

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A linear model, a scenario, or a parameter set (the Whipple bicycle, or the leaning rider's
        model of RiderLeanParameters).
    speed : float
        Forward speed (m/s).
    input, output : str
        As for :func:`~bikemass.analysis.handling.transfer.transfer_function`.
    frequencies : array_like (n,), optional
        Angular frequencies (rad/s), increasing; default 1000 from 0.1 to 100 rad/s, logarithmic.
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set.

    Returns
    -------
    FrequencyResponse
        ``frequencies`` (rad/s), ``magnitude`` (dB), ``phase`` (deg), ``values`` (complex).

    Raises
    ------
    InputError
        A speed that is not a finite number >= 0, an unknown input or output (the closest name
        is suggested), a bad S, or a system of another type, or frequencies that are not
        positive and increasing.

    See Also
    --------
    transfer_function : Zeros, poles and gain of the same input and output.
    plot_bode : Draw it.

    Examples
    --------
    >>> import bikemass as bm
    >>> fr = bm.frequency_response(bm.parameters("benchmark"), 5.0, "steer-torque", "roll-angle",
    ...                            frequencies=[1.0, 10.0])
    >>> print([f"{m:.3f} dB" for m in fr.magnitude], [f"{p:.2f} deg" for p in fr.phase])
    ['-9.150 dB', '-40.855 dB'] ['104.42 deg', '-66.88 deg']
    """
    model = linear_model(system, stiffness)
    A, b, c = siso(model, speed, input, output)
    w = np.geomspace(*DEFAULT_FREQUENCIES) if frequencies is None else check_frequencies(frequencies)
    return FrequencyResponse(input, output, signal_unit(model, input), signal_unit(model, output),
                             float(speed), w, response(A, b, c, w))
