"""Wheel sizes of geometry charts: ISO (ETRTO) bead-seat diameters and the wheel radius rule.

A chart names its wheel by the ISO bead-seat diameter (``"622 mm"``) or by a common
name (``700c``, ``29``, ``650b``, ``27.5``, ``26``, ``20``, ``16``).  The rolling radius
is taken as ``BSD / 2 + tire height`` with the tire's height equal to its width (a
round tire on its rim), e.g. 700 x 25 mm: 0.311 + 0.025 = 0.336 m.
"""

BEAD_SEAT_DIAMETERS = {
    "700c": 0.622, "29": 0.622, "28": 0.622,
    "650b": 0.584, "27.5": 0.584,
    "26": 0.559,
    "650c": 0.571,
    "24": 0.507,
    "20": 0.406,
    "16": 0.305,
}
"""Common name -> ISO bead-seat diameter (m).  ``26`` is the mountain-bike 559 mm size and
``20``/``16`` the BMX and children's/folding 406/305 mm sizes (the commonest of each name)."""


def bead_seat_diameter(node):
    """BSD (m) of a chart's ``wheel`` node: a common name or a length such as ``"622 mm"``."""
    value = node.value
    name = str(value).strip().lower().removesuffix('"').removesuffix("in").strip()
    if isinstance(value, (int, float, str)) and name in BEAD_SEAT_DIAMETERS:
        return BEAD_SEAT_DIAMETERS[name]
    if isinstance(value, str) and " " in value.strip():
        bsd = node.number("length", positive=True)
        if not 0.1 < bsd < 1.0:
            node.fail(f"an ISO bead-seat diameter between 100 and 1000 mm, got {value!r}")
        return bsd
    node.fail(f"a wheel size: an ISO bead-seat diameter with its unit (\"622 mm\") or one of "
              f"{', '.join(BEAD_SEAT_DIAMETERS)}, got {value!r}")


def wheel_radius(bsd, tire_width):
    """Rolling radius (m) of a wheel of bead-seat diameter ``bsd`` with a tire ``tire_width`` wide."""
    return bsd / 2 + tire_width
