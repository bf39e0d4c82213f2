"""What a sampled motion is, linear or nonlinear: :class:`SampledResponse`, the base of
:class:`~bikemass.analysis.handling.time_response.TimeResponse` and
:class:`~bikemass.analysis.nonlinear.response.NonlinearResponse` (named signals sampled in time)."""

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from ..core.choices import Choice
from ..core.errors import InputError, short, wrong_type
from ..core.frozen import FrozenMap, readonly
from ..core.results import Result, quantity, renamed_units
from ..core.tables import Table


class Excitation(Choice):
    """How a simulation applies an input (a member is its string: ``Excitation.STEP == "step"``).

    See Also
    --------
    bikemass.simulate : Takes ``inputs={name: (kind, size)}``.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.Excitation.values()
    ('step', 'impulse')
    >>> r = bm.simulate(bm.parameters("benchmark"), 4.6, inputs={"steer-torque": (bm.Excitation.STEP, 0.5)},
    ...                 duration=0.5)
    >>> print(f"steer {r['steer-angle'][-1]:.5f} rad after a 0.5 N m step")
    steer 0.01203 rad after a 0.5 N m step
    """

    STEP = "step"
    """The input held at its size (N m) from ``t = 0``."""
    IMPULSE = "impulse"
    """An impulse of its size (N m s) at ``t = 0``."""


KINDS = Excitation.values()
"""The kinds of input a simulation applies: a step (N m) or an impulse (N m s)."""


class Applied(NamedTuple):
    """One input a simulation applied: its :class:`Excitation` and size (N m for a step, N m s for an
    impulse); a tuple, so ``kind, size = applied`` reads it as before.

    Examples
    --------
    >>> import bikemass as bm
    >>> r = bm.simulate(bm.parameters("benchmark"), 4.6, inputs={"steer-torque": ("step", 0.5)}, duration=0.5)
    >>> applied = r.inputs["steer-torque"]
    >>> print(applied.kind, applied.size, applied.unit, applied.kind == "step")
    step 0.5 N m True
    """

    kind: Excitation
    size: float

    @property
    def unit(self):
        """The unit of :attr:`size`: ``"N m"`` for a step, ``"N m s"`` for an impulse."""
        return "N m" if self.kind == Excitation.STEP else "N m s"


@dataclass(frozen=True, eq=False, repr=False)
class SampledResponse(Result):
    """Named signals against time: ``values[:, k]`` is signal ``names[k]`` (unit ``signal_units[k]``)
    at ``time`` (s), the bicycle running at ``speed`` (m/s), ``inputs`` applied (``{input name:
    Applied(kind, size)}``). Arrays read-only, ``inputs`` a read-only mapping.

    ``units()`` is the units block of :meth:`to_dict` (every result's); ``units`` read as a tuple,
    the field's name before 0.3, still gives :attr:`signal_units` with a DeprecationWarning."""

    speed: float = quantity("m/s", "forward speed")
    time: np.ndarray = quantity("s", "the samples' times")
    names: tuple = ()
    signal_units: tuple = ()
    values: np.ndarray = quantity("each signal's (signal_units)", "(n, N): the signals at the samples",
                                  default=None)
    inputs: Mapping = field(default_factory=FrozenMap)

    units = renamed_units("signal_units")

    def __post_init__(self):
        object.__setattr__(self, "time", readonly(self.time, float))
        object.__setattr__(self, "values", readonly(self.values, float))
        object.__setattr__(self, "names", tuple(self.names))
        object.__setattr__(self, "signal_units", tuple(self.signal_units))
        object.__setattr__(self, "inputs", FrozenMap({k: Applied(Excitation(kind), float(size))
                                                      for k, (kind, size) in self.inputs.items()}))

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
        """The units block of :meth:`to_dict`: the declared speed's and time's, each signal's."""
        declared = self.field_units()
        return {"speed": declared["speed"], "time": declared["time"], **dict(zip(self.names, self.signal_units))}

    def tables(self):
        """``{"states": Table}``: one row per sample, ``time`` (s) and every signal in its unit. The
        speed and the inputs applied are the frame's ``attrs``."""
        columns = {"time": self.time, **{name: self[name] for name in self.names}}
        attrs = {"speed": self.speed, "inputs": {k: (str(kind), size) for k, (kind, size) in self.inputs.items()}}
        return {"states": Table(columns, {"time": self.field_units()["time"], **dict(zip(self.names, self.signal_units))},
                                attrs)}

    def _repr_fields(self):
        """``(name, text)`` pairs of the short repr: speed, time span, signals, inputs."""
        t = self.time
        applied = ", ".join(f"{k}={kind}:{size:g}" for k, (kind, size) in self.inputs.items()) or "none"
        return [("speed", f"{self.speed:g} m/s"), ("time", f"0..{t[-1]:g} s x {len(t)}"),
                ("states", len(self.names)), ("inputs", applied)]


def checked_inputs(inputs, check_name, number):
    """``{input name: Applied(kind, size)}`` of a simulation's ``inputs``, each ``(kind, size)`` with kind
    one of :data:`KINDS` (an :class:`Excitation`): ``check_name(name)`` refuses a name the model has no input of, ``number(size,
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
        kind = Excitation(spec[0])
        out[name] = Applied(kind, number(spec[1], name, kind))
    return out
