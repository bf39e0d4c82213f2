"""What a sampled motion is, linear or nonlinear: :class:`SampledResponse`, the base of
:class:`~bikemass.analysis.handling.time_response.TimeResponse` and
:class:`~bikemass.analysis.nonlinear.response.NonlinearResponse` (named signals sampled in time)."""

from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from ..core.display import Display
from ..core.errors import InputError, short, wrong_type
from ..core.frozen import FrozenMap, readonly

KINDS = ("step", "impulse")
"""The kinds of input a simulation applies: a step (N m) or an impulse (N m s)."""


@dataclass(frozen=True, eq=False, repr=False)
class SampledResponse(Display):
    """Named signals against time: ``values[:, k]`` is signal ``names[k]`` (unit ``units[k]``) at
    ``time`` (s), the bicycle running at ``speed`` (m/s), ``inputs`` applied (``{input name: (kind,
    size)}``). Arrays read-only, ``inputs`` a read-only mapping."""

    speed: float
    time: np.ndarray
    names: tuple
    units: tuple
    values: np.ndarray
    inputs: Mapping

    def __post_init__(self):
        object.__setattr__(self, "time", readonly(self.time, float))
        object.__setattr__(self, "values", readonly(self.values, float))
        object.__setattr__(self, "inputs", FrozenMap(self.inputs))

    def __getitem__(self, name):
        """The samples (n,) of the signal ``name``."""
        if name not in self.names:
            raise KeyError(f"no state {name!r} (states: {', '.join(self.names)})")
        return self.values[:, self.names.index(name)]

    @property
    def states(self):
        """``{name: samples}`` of every signal (read-only arrays)."""
        return FrozenMap({name: self[name] for name in self.names})

    def unit_block(self):
        """The unit of each key of ``to_dict`` that holds a quantity."""
        return {"speed": "m/s", "time": "s", **dict(zip(self.names, self.units))}

    def _repr_fields(self):
        """``(name, text)`` pairs of the short repr: speed, time span, signals, inputs."""
        t = self.time
        applied = ", ".join(f"{k}={kind}:{size:g}" for k, (kind, size) in self.inputs.items()) or "none"
        return [("speed", f"{self.speed:g} m/s"), ("time", f"0..{t[-1]:g} s x {len(t)}"),
                ("states", len(self.names)), ("inputs", applied)]


def checked_inputs(inputs, check_name, number):
    """``{input name: (kind, size)}`` of a simulation's ``inputs``, each ``(kind, size)`` with kind one
    of :data:`KINDS`: ``check_name(name)`` refuses a name the model has no input of, ``number(size,
    name, kind)`` checks the size and returns it (InputError for either, one line)."""
    if inputs is None:
        return {}
    if not isinstance(inputs, Mapping):
        raise wrong_type("inputs", inputs, "inputs are a mapping {input name: (kind, size)}")
    out = {}
    for name, spec in inputs.items():
        check_name(name)
        if not (isinstance(spec, (tuple, list)) and len(spec) == 2 and spec[0] in KINDS):
            raise InputError("inputs", short(name), f"(kind, size) with kind one of {', '.join(KINDS)}, "
                             f"got {short(spec)}")
        out[name] = (spec[0], number(spec[1], name, spec[0]))
    return out
