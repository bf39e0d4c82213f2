"""The nonlinear bicycle's motion as a value: :class:`NonlinearResponse` (what ``bm.simulate(...,
nonlinear=True)`` returns), apart from the simulator so that the linear ``simulate`` can name it
without loading the nonlinear model."""

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ...core.display import Display
from ...core.frozen import FrozenMap, readonly, short_repr

NAMES = ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral", "forward-speed",
         "pitch-angle", "x", "energy")
"""The outputs: the linear model's six states, the rear contact's forward speed, the rear frame's
pitch (from the reference configuration), the rear contact's x and the total energy."""
UNITS = ("rad", "rad", "rad/s", "rad/s", "rad", "m", "m/s", "rad", "m", "J")


@dataclass(frozen=True, eq=False, repr=False)
class NonlinearResponse(Display):
    """The nonlinear bicycle's motion against time.

    Attributes
    ----------
    speed : float
        Initial forward speed of the rear contact (m/s).
    time : numpy.ndarray (n,)
        Samples ``0, dt, ...`` (s): up to the duration, or to the last sample before the run stopped.
    names, units : tuple of str
        :data:`NAMES` and :data:`UNITS`.
    values : numpy.ndarray (n, 10)
        The outputs at the samples (their units); read-only.
    inputs : mapping
        ``{input name: (kind, size)}`` applied (steps in N m, impulses in N m s).
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

    speed: float
    time: np.ndarray
    names: tuple
    units: tuple
    values: np.ndarray
    inputs: Mapping
    stopped: str = ""

    def __post_init__(self):
        object.__setattr__(self, "time", readonly(self.time, float))
        object.__setattr__(self, "values", readonly(self.values, float))
        object.__setattr__(self, "inputs", FrozenMap(self.inputs))

    def __getitem__(self, name):
        """The samples (n,) of the output ``name``."""
        if name not in self.names:
            raise KeyError(f"no state {name!r} (states: {', '.join(self.names)})")
        return self.values[:, self.names.index(name)]

    @property
    def states(self):
        """``{name: samples}`` of every output (read-only arrays)."""
        return FrozenMap({name: self[name] for name in self.names})

    def to_dict(self):
        """Plain data: speed, time (s), states (``{name: samples}``), the model and why it stopped."""
        return {"model": "nonlinear whipple", "speed": self.speed, "time": self.time.tolist(),
                "states": {name: self[name].tolist() for name in self.names}, "stopped": self.stopped}

    def unit_block(self):
        """The unit of each key of :meth:`to_dict` that holds a quantity."""
        return {"speed": "m/s", "time": "s", **dict(zip(self.names, self.units))}

    def __repr__(self):
        t = self.time
        applied = ", ".join(f"{k}={kind}:{size:g}" for k, (kind, size) in self.inputs.items()) or "none"
        fields = [("speed", f"{self.speed:g} m/s"), ("time", f"0..{t[-1]:g} s x {len(t)}"),
                  ("states", len(self.names)), ("inputs", applied)]
        if self.stopped:
            fields.append(("stopped", self.stopped))
        return short_repr(self, *fields)
