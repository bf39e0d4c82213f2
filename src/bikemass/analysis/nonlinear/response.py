"""The nonlinear bicycle's motion as a value: :class:`NonlinearResponse` (what ``bm.simulate(...,
nonlinear=True)`` returns), apart from the simulator so that the linear ``simulate`` can name it
without loading the nonlinear model."""

from dataclasses import dataclass

from ...core.frozen import short_repr
from ..sampled import SampledResponse

NAMES = ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral", "forward-speed",
         "pitch-angle", "x", "energy")
"""The outputs: the linear model's six states, the rear contact's forward speed, the rear frame's
pitch (from the reference configuration), the rear contact's x and the total energy."""
UNITS = ("rad", "rad", "rad/s", "rad/s", "rad", "m", "m/s", "rad", "m", "J")


@dataclass(frozen=True, eq=False, repr=False)
class NonlinearResponse(SampledResponse):
    """The nonlinear bicycle's motion against time.

    Attributes
    ----------
    speed : float
        Initial forward speed of the rear contact (m/s).
    time : numpy.ndarray (n,)
        Samples ``0, dt, ...`` (s): up to the duration, or to the last sample before the run stopped.
    names, signal_units : tuple of str
        :data:`NAMES` and :data:`UNITS` (``units``, the name of ``signal_units`` before 0.3, still reads
        it with a DeprecationWarning; ``units()`` is the units block).
    values : numpy.ndarray (n, 10)
        The outputs at the samples (their units); read-only.
    inputs : mapping
        ``{input name: Applied(kind, size)}`` applied (steps in N m, impulses in N m s).
    stopped : str
        Why the run stopped before the duration (one line), or ``""``.

    See Also
    --------
    bikemass.simulate : Makes it (``nonlinear=True``).

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.simulate(bm.parameters("benchmark"), 4.6, initial={"roll-rate": 0.5}, duration=2.0, nonlinear=True)
    >>> print(r)
    NonlinearResponse(speed=4.6 m/s, time=0..2 s x 201, states=10, inputs=none)
    >>> r.names[6:]
    ('forward-speed', 'pitch-angle', 'x', 'energy')
    >>> bool(abs(r["energy"][-1] / r["energy"][0] - 1) < 1e-9)       # the energy is conserved
    True
    """

    stopped: str = ""

    def to_dict(self):
        """Plain data: speed, time (s), states (``{name: samples}``), the model and why it stopped."""
        return {"model": "nonlinear whipple", "speed": self.speed, "time": self.time.tolist(),
                "states": {name: self[name].tolist() for name in self.names}, "stopped": self.stopped}

    def __repr__(self):
        fields = self._repr_fields()
        if self.stopped:
            fields.append(("stopped", self.stopped))
        return short_repr(self, *fields)
