"""Units with dimensions for numbers read from YAML.

Every value is read for a *dimension* (``"length"``, ``"mass"``, ``"angle"``, ...).
A string ``"<number> <unit>"`` is converted to SI if the unit has that dimension,
so thesis values can be written as printed (``"1.25 in"``, ``"0.474 lb"``,
``"205 GPa"``, ``"7.85 g/cm^3"``, ``"72 deg"``); a unit of another dimension
(``"450 g"`` where a length is expected) is an error.

The rule for bare numbers (one rule, every YAML format):

* a bare number is SI: m, kg, kg m^2, Pa, kg/m^3, N m/rad, m/s^2;
* an angle always carries its unit (``"72 deg"`` or ``"1.2566 rad"``): a bare
  number where an angle is expected could be read either way and is refused.
  So does a coefficient per angle (``"11.5 1/rad"``, ``"0.2 1/deg"``: tyre data are
  printed in both).
  The one exception is a format whose definition fixes the unit: the benchmark
  parameter set of Meijaard et al. (2007), whose ``lam`` is radians (as
  BicycleParameters writes it); its reader passes ``bare_unit="rad"``.

Inside bikemass a value with a unit travels as a :class:`Quantity` (a number and its unit), never
as text: a design change (a chart's head angle, a solved pose's joint angle, a swept value in
the spec's unit) is put into a document as a Quantity, read by the same :func:`convert` as
``"<number> <unit>"`` text (so with the same arithmetic) and written out as that text only by a
file writer (:func:`bikemass.core.plain.plain`).
"""

import math
import re
from dataclasses import dataclass

INCH = 0.0254
"""One inch in metres."""
POUND = 0.45359237
"""One pound-mass in kilograms."""

DIMENSIONS = {
    "length": ("m", {"m": 1.0, "mm": 1e-3, "cm": 1e-2, "in": INCH, "ft": 12 * INCH}),
    "mass": ("kg", {"kg": 1.0, "g": 1e-3, "lb": POUND, "lbm": POUND}),
    "inertia": ("kg m^2", {"kg m^2": 1.0, "kg*m^2": 1.0, "kg mm^2": 1e-6, "g mm^2": 1e-9,
                           "g cm^2": 1e-7, "lb in^2": POUND * INCH**2, "lb ft^2": POUND * (12 * INCH)**2}),
    "angle": ("rad", {"rad": 1.0, "deg": math.pi / 180, "°": math.pi / 180}),
    "pressure": ("Pa", {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "GPa": 1e9, "N/mm^2": 1e6,
                        "psi": POUND * 9.80665 / INCH**2, "ksi": 1e3 * POUND * 9.80665 / INCH**2,
                        "Msi": 1e6 * POUND * 9.80665 / INCH**2}),
    "density": ("kg/m^3", {"kg/m^3": 1.0, "g/cm^3": 1e3, "g/cc": 1e3, "lb/in^3": POUND / INCH**3}),
    "stiffness": ("N m/rad", {"N m/rad": 1.0, "N*m/rad": 1.0, "kN m/rad": 1e3, "N m/deg": 180 / math.pi}),
    "linear stiffness": ("N/m", {"N/m": 1.0, "N/mm": 1e3, "kN/m": 1e3}),
    "acceleration": ("m/s^2", {"m/s^2": 1.0}),
    "inverse angle": ("1/rad", {"1/rad": 1.0, "1/deg": 180 / math.pi}),
    "length per angle": ("m/rad", {"m/rad": 1.0, "m/deg": 180 / math.pi, "mm/rad": 1e-3, "mm/deg": 0.18 / math.pi}),
    "speed": ("m/s", {"m/s": 1.0, "km/h": 1 / 3.6}),
    "damping": ("N m s/rad", {"N m s/rad": 1.0, "N*m*s/rad": 1.0, "N m s/deg": 180 / math.pi}),
    "dimensionless": ("", {"": 1.0}),
}
"""dimension -> (SI unit, {unit: factor to SI}).  ``pressure`` also covers elastic moduli,
``stiffness`` is rotational (moment per angle), ``inverse angle`` a coefficient per angle (a tyre's
force per unit load per radian of slip), ``length per angle`` a moment per unit load per angle (a tyre's
twisting torque coefficient)."""

ARTICLES = {"angle": "an", "acceleration": "an", "inertia": "an", "inverse angle": "an"}
UNIT_REQUIRED = ("angle", "inverse angle", "length per angle")
"""Dimensions whose bare numbers are refused (radians or degrees could be meant)."""

_QUANTITY = re.compile(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*")
_UNIT_DIMENSION = {unit: dim for dim, (_, table) in DIMENSIONS.items() for unit in table}


class UnitError(ValueError):
    """A value that is not a number of the expected dimension; the message says what was expected."""


@dataclass(frozen=True)
class Quantity:
    """A number with its unit (one of :data:`DIMENSIONS`'), typed: what ``"<number> <unit>"`` says
    in a file, without the text.  :func:`convert` reads it exactly as it reads that text.

    Parameters
    ----------
    value : float
        The number, in ``unit``.
    unit : str
        Its unit (``"m"``, ``"deg"``, ``"rad"``, ``"mm"``, ...).

    Examples
    --------
    >>> from bikemass.core.units import Quantity, convert
    >>> convert(Quantity(72.0, "deg"), "angle", "deg")
    72.0
    >>> Quantity(0.045, "m").text
    '0.045 m'
    """

    value: float
    unit: str

    def __post_init__(self):
        if dimension_of(self.unit) is None:
            raise UnitError(f"a known unit, got {self.unit!r}")
        object.__setattr__(self, "value", float(self.value))

    @property
    def dimension(self):
        """The dimension of :attr:`unit` (``"length"``, ``"angle"``, ...)."""
        return dimension_of(self.unit)

    def __repr__(self):
        """The text a file would hold, quoted: an error message names the value as it names one read
        from a file (``got '500.0 kg'``)."""
        return repr(self.text)

    @property
    def text(self):
        """``"<number> <unit>"`` with every digit: how a file writes it (a file writer's form only)."""
        return f"{self.value!r} {self.unit}"


def dimension_of(unit):
    """The dimension of ``unit`` (``"mm"`` -> ``"length"``), or None if unknown."""
    return _UNIT_DIMENSION.get(unit)


def describe(dimension):
    """What a value of ``dimension`` looks like, for error messages."""
    si, table = DIMENSIONS[dimension]
    noun = f"{ARTICLES.get(dimension, 'a')} {dimension}"
    if dimension == "dimensionless":
        return "a plain number (no unit)"
    others = ", ".join(u for u in table if u != si)
    if dimension == "angle":
        return (f"{noun} with its unit ('<number> deg' or '<number> rad'; "
                "a bare number could be either)")
    if dimension == "length per angle":
        return "a moment per unit load per angle with its unit ('<number> m/rad' or '<number> mm/deg')"
    if dimension == "inverse angle":
        return ("a coefficient per angle with its unit ('<number> 1/rad' or '<number> 1/deg'; "
                "a bare number could be either)")
    return f"{noun} (a number in {si}, or '<number> <unit>' with unit {others})"


def to_si(value, dimension, *, bare_unit=None):
    """``value`` (a number or ``"<number> <unit>"``) of ``dimension`` in SI, as a float.

    A bare number is taken in the dimension's SI unit, except angles, which need
    their unit unless the file format fixes it (``bare_unit="rad"`` or ``"deg"``).
    Raises :class:`UnitError` naming the expected dimension for anything else.
    """
    return convert(value, dimension, DIMENSIONS[dimension][0] if dimension in DIMENSIONS else None,
                   bare_unit=bare_unit)


def convert(value, dimension, unit, *, bare_unit=None):
    """Like :func:`to_si` but in ``unit`` (of ``dimension``); exact when ``value`` is written in ``unit``."""
    if dimension not in DIMENSIONS:
        raise KeyError(f"unknown dimension {dimension!r} (known: {', '.join(DIMENSIONS)})")
    si, table = DIMENSIONS[dimension]
    number, given = _split(value, dimension)
    if given == "":
        given = bare_unit or (None if dimension in UNIT_REQUIRED else si)
        if given is None:
            raise UnitError(f"{describe(dimension)}, got {_short(value)}")
    if given not in table:
        other = dimension_of(given)
        what = f"{ARTICLES.get(other, 'a')} {other}" if other else "an unknown unit"
        raise UnitError(f"{describe(dimension)}, got {_short(value)} ({what})")
    if given == unit:
        return number
    return number * table[given] / table[unit]


def factor(unit, to):
    """What a value in ``unit`` is multiplied by to be in ``to`` (a unit of the same dimension).

    >>> round(factor("1/deg", "1/rad"), 6)
    57.29578
    """
    return convert(Quantity(1.0, unit), dimension_of(to), to)


def _split(value, dimension):
    """(number, unit string) of a YAML value or a :class:`Quantity`."""
    if isinstance(value, Quantity):
        return value.value, value.unit
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise UnitError(f"{describe(dimension)}, got {type(value).__name__} {_short(value)}")
    if isinstance(value, (int, float)):
        try:
            return float(value), ""
        except OverflowError:
            raise UnitError(f"{describe(dimension)}, got a number too large for a float") from None
    match = _QUANTITY.fullmatch(value)
    if match is None:
        head = value.split()[0].lower().lstrip("+-.") if value.split() else ""
        if head in ("inf", "infinity", "nan"):                # what is wrong is the number, not its unit
            raise UnitError(f"{describe(dimension)}, got {_short(value)} (not a finite number)")
        raise UnitError(f"{describe(dimension)}, got {_short(value)}")
    return float(match.group(1)), match.group(2)


def split_quantity(value):
    """``(number, unit)`` of a number (unit ``""``) or a ``"<number> <unit>"`` string whose unit is
    one of :data:`DIMENSIONS`' (its dimension: :func:`dimension_of`); :class:`UnitError` otherwise."""
    number, unit = _split(value, "dimensionless")
    if unit and dimension_of(unit) is None:
        raise UnitError(f"a number or '<number> <unit>' with a known unit, got {_short(value)} (an unknown unit)")
    return number, unit


def _short(value, limit=40):
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."
