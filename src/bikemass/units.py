"""Unit conversion to SI for numbers read from YAML.

A number in a YAML file is SI (m, kg, kg m^2, Pa, kg/m^3, rad unless the key
says degrees).  A string ``"<number> <unit>"`` is converted, so thesis values
can be written as printed: ``"1.25 in"``, ``"0.474 lb"``, ``"205 GPa"``,
``"7.85 g/cm^3"``, ``"72 deg"``.
"""

import math

INCH = 0.0254
"""One inch in metres."""
POUND = 0.45359237
"""One pound-mass in kilograms."""

_FACTORS = {
    # length -> m
    "m": 1.0, "mm": 1e-3, "cm": 1e-2, "in": INCH, "ft": 12 * INCH,
    # mass -> kg
    "kg": 1.0, "g": 1e-3, "lb": POUND, "lbm": POUND,
    # inertia -> kg m^2
    "kg m^2": 1.0, "kg*m^2": 1.0, "lb in^2": POUND * INCH**2,
    # modulus / pressure -> Pa
    "Pa": 1.0, "MPa": 1e6, "GPa": 1e9,
    # density -> kg/m^3
    "kg/m^3": 1.0, "g/cm^3": 1e3, "g/cc": 1e3,
    # angle -> rad
    "rad": 1.0, "deg": math.pi / 180,
    # stiffness
    "N m/rad": 1.0,
}

UNITS = tuple(_FACTORS)


def to_si(value):
    """Return ``value`` in SI: numbers pass through, ``"<number> <unit>"`` strings convert.

    Raises ``ValueError`` (with the known units) for anything else.
    """
    if isinstance(value, bool):
        raise ValueError("expected a number, got a boolean")
    if isinstance(value, (int, float)):
        return float(value)
    if isinstance(value, str):
        number, _, unit = value.strip().partition(" ")
        unit = unit.strip()
        try:
            x = float(number)
        except ValueError:
            raise ValueError(f"expected a number or '<number> <unit>', got {value!r}") from None
        if unit == "":
            return x
        if unit not in _FACTORS:
            raise ValueError(f"unknown unit {unit!r} in {value!r} (known: {', '.join(UNITS)})")
        return x * _FACTORS[unit]
    raise ValueError(f"expected a number or '<number> <unit>', got {type(value).__name__} {value!r}")
