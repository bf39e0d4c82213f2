"""Wheel sizes of geometry charts: ISO (ETRTO) bead-seat diameters and the wheel radius rule.

A chart names its wheel by the ISO bead-seat diameter (``"622 mm"``, or a bare number in
the chart's length unit) or by a common name (``700c``, ``29``, ``650b``, ``27.5``, ``26``,
``20``, ``16``, ...; written ``29er``, ``26"``, ``26 in`` or ``26 inch`` alike).  The
rolling radius is taken as ``BSD / 2 + tire height`` with the tire's height equal to its
width (a round tire on its rim), e.g. 700 x 25 mm: 0.311 + 0.025 = 0.336 m.
"""

from ..core.errors import InputError

BEAD_SEAT_DIAMETERS = {
    "700c": 0.622, "29": 0.622, "28": 0.622,
    "27": 0.630,
    "650b": 0.584, "27.5": 0.584,
    "26": 0.559,
    "650c": 0.571,
    "24": 0.507,
    "20": 0.406,
    "18": 0.355,
    "16": 0.305,
    "14": 0.254,
    "12": 0.203,
}
"""Common name -> ISO bead-seat diameter (m).  ``26`` is the mountain-bike 559 mm size,
``27`` the old road 630 mm size, and ``24``/``20``/``18``/``16``/``14``/``12`` the
commonest children's, BMX and folding sizes of each name (507/406/355/305/254/203 mm).
A Brompton's 16 in wheel (349 mm) or a 20 in 451 mm wheel is given by its BSD."""
_INCH_SUFFIXES = ('"', "inches", "inch", "in", "er")
"""Ways a chart writes "inch" after a wheel's name (``29er`` is the 29 in mountain wheel)."""


def _name(value):
    """A wheel name as the table writes it: lower case, no spaces, no inch mark."""
    name = str(value).strip().lower().replace(" ", "")
    for suffix in _INCH_SUFFIXES:
        if name.endswith(suffix) and name[:-len(suffix)] in BEAD_SEAT_DIAMETERS:
            return name[:-len(suffix)]
    return name


def bead_seat_diameter(node, bare_unit=None):
    """BSD (m) of a chart's ``wheel`` node: a common name, a length such as ``"622 mm"``,
    or a bare number in ``bare_unit`` (the chart's length unit; metres without one)."""
    value = node.value
    if isinstance(value, (int, float, str)) and not isinstance(value, bool) and _name(value) in BEAD_SEAT_DIAMETERS:
        return BEAD_SEAT_DIAMETERS[_name(value)]
    expected = (f"a wheel size: an ISO bead-seat diameter (\"622 mm\") or one of "
                f"{', '.join(BEAD_SEAT_DIAMETERS)}, got {value!r}")
    try:
        bsd = node.number("length", bare_unit=bare_unit)
    except InputError:
        node.fail(expected)
    if not 0.1 < bsd < 1.0:
        node.fail(f"an ISO bead-seat diameter between 100 and 1000 mm, got {value!r}"
                  + (f" ({bare_unit})" if bare_unit and not isinstance(value, str) else ""))
    return bsd


def wheel_radius(bsd, tire_width):
    """Rolling radius (m) of a wheel of bead-seat diameter ``bsd`` with a tire ``tire_width`` wide."""
    return bsd / 2 + tire_width
