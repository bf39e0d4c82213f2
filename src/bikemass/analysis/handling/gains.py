"""The five gains of the Hess, Moore & Hubbard (2012) rider, and gain tables in the form the
published tables are written (Moore's HumanControl ``gains/*SteerGains.txt``)::

    speed,kDelta,kPhiDot,kPhi,kPsi,kY
    5.000,46.5457,-0.0522,12.6611,0.1849,0.0959

(further columns after the six, as ``bikemass handling --format csv`` writes, are ignored).

Units follow from the loops (:mod:`~bikemass.analysis.handling.rider`): ``k_delta`` N m/rad
(steer angle error -> neuromuscular command), ``k_phi_dot`` s (roll-rate error, rad/s -> steer
command, rad), ``k_phi`` 1/s (roll error -> roll-rate command), ``k_psi`` rad/rad (heading error
-> roll command) and ``k_y`` rad/m (lateral error -> heading command).
"""

import csv
import io
import math
import os
from dataclasses import astuple, dataclass, fields

from ...core.errors import InputError, short
from ...core.real import finite_real
from ...core.gate import read_text
from ...core.results import declared_units, quantity

HEADER = ("speed", "kDelta", "kPhiDot", "kPhi", "kPsi", "kY")
"""The header of a gains file."""

MAX_ROWS = 100_000
"""Most rows of a gains file."""


@dataclass(frozen=True)
class Gains:
    """The gains of the five loops, inner to outer (units: :data:`UNITS`).

    Attributes
    ----------
    k_delta : float
        Steer angle error -> neuromuscular command (N m/rad).
    k_phi_dot : float
        Roll-rate error (rad/s) -> steer command (rad): in s.
    k_phi : float
        Roll error -> roll-rate command (1/s).
    k_psi : float
        Heading error -> roll command (rad/rad).
    k_y : float
        Lateral error -> heading command (rad/m).

    See Also
    --------
    bikemass.handling : Tunes them at every speed (or takes them).
    bikemass.lane_change : Takes them.

    Examples
    --------
    >>> import bikemass as bm
    >>> g = bm.Gains(46.5457, -0.0522, 12.6611, 0.1849, 0.0959)   # Moore's benchmark at 5 m/s
    >>> r = bm.handling(bm.parameters("benchmark"), [5.0], gains=g)
    >>> bool(r.closed_loop_stable[0]), list(g) == [46.5457, -0.0522, 12.6611, 0.1849, 0.0959]
    (True, True)
    """

    k_delta: float = quantity("N m/rad", "steer angle error -> neuromuscular command")
    k_phi_dot: float = quantity("s", "roll-rate error (rad/s) -> steer command (rad)")
    k_phi: float = quantity("1/s", "roll error -> roll-rate command")
    k_psi: float = quantity("rad/rad", "heading error -> roll command")
    k_y: float = quantity("rad/m", "lateral error -> heading command")

    def __post_init__(self):
        for f in fields(self):
            x = getattr(self, f.name)
            if not finite_real(x):
                raise InputError("gains", f.name, f"a finite number in {UNITS[f.name]}, got {short(x)}")
            object.__setattr__(self, f.name, float(x))

    def __iter__(self):
        return iter(astuple(self))

    def to_dict(self):
        """``{"k_delta": ..., ...}`` as plain floats."""
        return {f.name: float(getattr(self, f.name)) for f in fields(self)}


UNITS = declared_units(Gains)
"""The unit of each gain, as :class:`Gains` declares it: ``{"k_delta": "N m/rad", "k_phi_dot": "s", ...}``."""
NAMES = tuple(f.name for f in fields(Gains))
"""``k_delta, k_phi_dot, k_phi, k_psi, k_y``: the gains in loop order, inner to outer."""


def as_gains(value, source="gains", key="(argument)"):
    """``value`` (a :class:`Gains` or five numbers, inner loop first) as :class:`Gains`; InputError
    unless five finite numbers."""
    if isinstance(value, Gains):
        values = tuple(value)
    else:
        try:
            values = tuple(float(x) for x in value)
        except (TypeError, ValueError, OverflowError):
            raise InputError(source, key, f"five gains k_delta, k_phi_dot, k_phi, k_psi, k_y, got {short(value)}") from None
    if len(values) != 5 or not all(math.isfinite(x) for x in values):
        raise InputError(source, key, f"five finite gains k_delta, k_phi_dot, k_phi, k_psi, k_y, got {short(value)}")
    return Gains(*values)


def parse_gain_table(text, source):
    """``{speed (m/s): Gains}`` from the text of a gains file (:data:`HEADER`, one row per speed,
    speeds increasing); InputError naming the line otherwise."""
    rows = list(csv.reader(io.StringIO(text)))
    rows = [(n, [cell.strip() for cell in row]) for n, row in enumerate(rows, 1) if any(c.strip() for c in row)]
    if not rows or tuple(rows[0][1][:len(HEADER)]) != HEADER:
        raise InputError(source, "line 1", f"the header {','.join(HEADER)}"
                         + (f", got {short(','.join(rows[0][1]))}" if rows else ", got an empty file"))
    if len(rows) > MAX_ROWS + 1:
        raise InputError(source, "(file)", f"at most {MAX_ROWS} rows of gains")
    table = {}
    for n, row in rows[1:]:
        if len(row) != len(rows[0][1]):
            raise InputError(source, f"line {n}", f"{len(rows[0][1])} cells as the header, got {len(row)}")
        try:
            speed, *values = (float(cell) for cell in row[:len(HEADER)])
        except ValueError:
            raise InputError(source, f"line {n}", f"six numbers {','.join(HEADER)}, got "
                             f"{short(','.join(row[:len(HEADER)]))}") from None
        if not (math.isfinite(speed) and speed >= 0):
            raise InputError(source, f"line {n} (speed)", f"a speed in m/s, finite and >= 0, got {short(row[0])}")
        if table and speed <= max(table):
            raise InputError(source, f"line {n} (speed)", f"speeds increasing down the file, got {speed:g} "
                             f"after {max(table):g}")
        table[speed] = as_gains(values, source, f"line {n}")
    if not table:
        raise InputError(source, "(file)", "at least one row of gains under the header")
    return table


def read_gain_table(path):
    """``{speed (m/s): Gains}`` of the gains file ``path``; InputError for a missing or bad file."""
    return parse_gain_table(read_text(os.fspath(path)), os.fspath(path))

