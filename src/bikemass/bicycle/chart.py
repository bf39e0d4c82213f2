"""A manufacturer's geometry chart: reading it, building the frame from it, checking it.

Definitions (docs/bicycles.md, "Geometry charts", with a figure); heights are measured
up from the ground, x forward from the rear contact, both wheels of one radius so the
axle line is horizontal:

* ``stack``, ``reach``: vertical and horizontal distance from the bottom-bracket (BB)
  centre to the centre of the head tube's top;
* ``head_tube_angle``, ``seat_tube_angle``: from the horizontal;
* ``head_tube_length``: along the steer axis, top to bottom;
* ``seat_tube_length``: BB centre to the top of the seat tube (centre-to-top), along it;
* ``chainstay_length``: BB centre to rear axle, straight line;
* ``bb_drop``: BB centre below the axle line;
* ``fork_offset``: front axle ahead of the steer axis, perpendicular to it;
* ``wheel`` and ``tire_width`` (radius = BSD / 2 + tire width), or ``wheel_radius``.

A chart that prints ``bb_height`` but no ``bb_drop``, or ``trail`` but no ``fork_offset``,
gives the missing key through the wheel radius (:data:`STAND_INS`).

Derived (and, when the chart gives them, checked): ``wheelbase`` (axle to axle),
``front_center`` (BB centre to front axle, straight line, like the chainstay), ``trail`` (steer axis' ground point
ahead of the front contact), ``mechanical_trail`` (trail perpendicular to the steer
axis), ``wheel_flop`` (trail sin cos of the head angle), ``top_tube_length`` (effective:
horizontal from the head tube's top to the seat-tube line), ``bb_height``,
``standover`` (top of the top tube above the ground at its midpoint; needs the tube's
diameter, so the bicycle builder checks it).
"""

from dataclasses import dataclass

import numpy as np

from .wheel_sizes import bead_seat_diameter, wheel_radius

FRAME_KEYS = ("stack", "reach", "head_tube_angle", "seat_tube_angle", "head_tube_length",
              "seat_tube_length", "chainstay_length", "bb_drop", "fork_offset")
"""Chart keys that fix the frame (with the wheel)."""
ANGLE_KEYS = ("head_tube_angle", "seat_tube_angle")
CHECKED_KEYS = ("wheelbase", "front_center", "trail", "mechanical_trail", "top_tube_length",
                "bb_height", "standover")
"""Redundant chart keys: compared with the construction."""
TOLERANCES = {"wheelbase": 0.005, "front_center": 0.005, "top_tube_length": 0.005, "trail": 0.003,
              "mechanical_trail": 0.003, "bb_height": 0.003, "standover": 0.025}
"""Default tolerance (m) of each checked key.  5 mm for lengths built from several rounded
values (a head angle printed to 0.25 deg moves the front axle by ~3 mm); 3 mm for trail and
BB height (one rounding of the wheel radius); 25 mm for standover, whose point of measure
(and where the top tube meets the seat and head tubes) charts do not fix."""
STAND_INS = {"bb_drop": "bb_height", "fork_offset": "trail"}
"""A frame key a chart may leave out when it prints this one instead: BB drop = wheel radius -
BB height; fork offset = r cos(head angle) - trail sin(head angle) (both with the chart's wheel)."""
WHEEL_DEPENDENT = ("bb_height", "trail", "mechanical_trail", "standover")
"""Checked keys that move with the wheel radius (the frame fixed to the axles by bb_drop): a
chart measures them with its stock tyre."""
MAX_TYRE_CHANGE = 0.05
"""m: most a wheel's radius may differ from the chart's stock one (its bb_height + bb_drop) and
still be taken for another tyre on the same frame (700c x 25 to 29 x 2.6 in is 44 mm); further,
the published BB height is checked against the wheel given, as before."""
WHEEL_KEYS = ("wheel", "tire_width", "wheel_radius")
OTHER_KEYS = ("units", "tolerances", "note")
ANGLE_RANGE_DEG = (45.0, 90.0)
"""Head and seat angles must lie in (45, 90] deg from the horizontal."""
MAX_LENGTH = 2.0
"""m: a chart length above this is a unit mistake (a bare ``585`` read as metres)."""
BARE_UNITS = {"length": ("m", "mm", "cm", "in"), "angle": ("deg", "rad")}


@dataclass(frozen=True)
class Chart:
    """A geometry chart in SI (m, rad); ``checks`` holds the redundant values given (m)."""

    stack: float
    reach: float
    head_tube_angle: float
    seat_tube_angle: float
    head_tube_length: float
    seat_tube_length: float
    chainstay_length: float
    bb_drop: float
    fork_offset: float
    wheel_radius: float
    tire_width: float | None = None
    checks: tuple = ()
    tolerances: tuple = ()
    stock_radius: float | None = None
    """Radius (m) of the wheel the chart's published BB height (and trail, standover) were measured
    with, where it differs from ``wheel_radius`` (another tyre on the frame): bb_height + bb_drop."""

    def stock_values(self, values):
        """``values`` (construction, m) with the wheel-dependent keys as the stock wheel makes them:
        every height shifts by the change of radius, trail by its cotangent of the head angle."""
        if self.stock_radius is None:
            return dict(values)
        dr, ha = self.stock_radius - self.wheel_radius, self.head_tube_angle
        shift = {"bb_height": dr, "standover": dr, "trail": dr / np.tan(ha), "mechanical_trail": dr * np.cos(ha)}
        return {k: v + shift[k] if k in shift and v is not None else v for k, v in values.items()}

    def points(self):
        """Frame points ``{name: (x, height)}`` (m) and the derived chart values, see :func:`construct`."""
        return construct(self)


def _units(node):
    if not node.has("units"):
        return {}
    units = node["units"]
    units.check_keys(optional=tuple(BARE_UNITS))
    return {dim: units[dim].string(choices=BARE_UNITS[dim]) for dim in BARE_UNITS if units.has(dim)}


def _value(node, dimension, units):
    """A chart value in SI: ``"585 mm"``, or a bare number in ``units[dimension]`` (chart
    ``units:``); without it a bare length is metres and a bare angle is refused."""
    if isinstance(node.value, (int, float)) and not isinstance(node.value, bool) and dimension in units:
        return node.number(dimension, bare_unit=units[dimension])
    return node.number(dimension)


def read_chart(node):
    """:class:`Chart` from a ``chart`` mapping (values with units, or bare in ``units:``)."""
    node.check_keys(required=tuple(k for k in FRAME_KEYS if k not in STAND_INS),
                    optional=tuple(STAND_INS) + WHEEL_KEYS + CHECKED_KEYS + OTHER_KEYS)
    units = _units(node)

    def given(key):
        return node.has(key) and not node[key].missing
    for key, stand_in in STAND_INS.items():
        if not given(key) and not given(stand_in):
            node.fail(f"a required key that is missing (or {stand_in} instead)", key)
    for key in FRAME_KEYS:
        if key not in STAND_INS and not given(key):
            node.fail("a value (null is for a published check a chart leaves out, not for a frame dimension)", key)
    v = {}
    for key in FRAME_KEYS:
        if given(key):
            v[key] = _value(node[key], "angle" if key in ANGLE_KEYS else "length", units)
    for key in ANGLE_KEYS:
        lo, hi = ANGLE_RANGE_DEG
        if not np.radians(lo) < v[key] <= np.radians(hi):
            node.fail(f"an angle from the horizontal in ({lo:g}, {hi:g}] deg, got "
                      f"{np.degrees(v[key]):g} deg", key)
    for key in ("stack", "reach", "head_tube_length", "seat_tube_length", "chainstay_length"):
        if not 0 < v[key] < MAX_LENGTH:
            node.fail(f"a positive length below {MAX_LENGTH:g} m, got {v[key]:g} m", key)
    radius, tire = _wheel(node, units)
    stood_in = tuple(stand_in for key, stand_in in STAND_INS.items() if key not in v)
    if "bb_drop" not in v:
        v["bb_drop"] = radius - _value(node["bb_height"], "length", units)
    if "fork_offset" not in v:
        ha = v["head_tube_angle"]
        v["fork_offset"] = radius * np.cos(ha) - _value(node["trail"], "length", units) * np.sin(ha)
    for key in ("bb_drop", "fork_offset"):
        if not abs(v[key]) < MAX_LENGTH / 4:
            node.fail(f"a length below {MAX_LENGTH / 4:g} m, got {v[key]:g} m", key if key in node.mapping()
                      else STAND_INS[key])
    if abs(v["bb_drop"]) >= v["chainstay_length"]:
        node.fail(f"a chainstay longer than the bb_drop {v['bb_drop'] * 1000:.1f} mm "
                  f"(got {v['chainstay_length'] * 1000:.1f} mm)", "chainstay_length")
    checks = tuple((k, _value(node[k], "length", units)) for k in CHECKED_KEYS
                   if given(k) and k not in stood_in)     # null: not published (for this size)
    tolerances = {}
    if node.has("tolerances"):
        t = node["tolerances"]
        t.check_keys(optional=CHECKED_KEYS)
        tolerances = {k: _value(t[k], "length", units) for k in CHECKED_KEYS if t.has(k)}
    stock = None
    if "bb_height" not in stood_in and given("bb_height") and given("bb_drop"):
        stock = _value(node["bb_height"], "length", units) + v["bb_drop"]
        tolerance = {**TOLERANCES, **tolerances}["bb_height"]
        if not tolerance < abs(stock - radius) <= MAX_TYRE_CHANGE:
            stock = None                      # the stock wheel, or a BB height the check refuses
    chart = Chart(**v, wheel_radius=radius, tire_width=tire, checks=checks,
                  tolerances=tuple(tolerances.items()), stock_radius=stock)
    _check_feasible(chart, node)
    return chart


def _wheel(node, units):
    if node.has("wheel_radius") == node.has("wheel"):
        node.fail("exactly one of wheel (with tire_width) or wheel_radius", "wheel")
    if node.has("wheel_radius"):
        if node.has("tire_width"):
            node.fail("no tire_width with wheel_radius (the radius already includes the tire)", "tire_width")
        radius = _value(node["wheel_radius"], "length", units)
        if not 0.05 < radius < 1.0:
            node.fail(f"a wheel radius between 0.05 and 1 m, got {radius:g} m", "wheel_radius")
        return radius, None
    bsd = bead_seat_diameter(node["wheel"], units.get("length"))
    tire = _value(node["tire_width"], "length", units)
    if not 0.005 < tire < 0.15:
        node.fail(f"a tire width between 5 and 150 mm, got {tire * 1000:g} mm", "tire_width")
    return wheel_radius(bsd, tire), tire


def construct(chart):
    """Frame points (x forward, height up, m; origin the rear contact) and derived values.

    Points: ``rear_axle``, ``front_axle``, ``bottom_bracket``, ``head_top``, ``head_bottom``,
    ``seat_top``; values: ``wheelbase``, ``front_center``, ``trail``, ``mechanical_trail``,
    ``wheel_flop``, ``top_tube_length`` (effective), ``bb_height`` (m).
    """
    r, ha, sa = chart.wheel_radius, chart.head_tube_angle, chart.seat_tube_angle
    bb = np.array([np.sqrt(chart.chainstay_length ** 2 - chart.bb_drop ** 2), r - chart.bb_drop])
    head_top = bb + [chart.reach, chart.stack]
    up_steer = np.array([-np.cos(ha), np.sin(ha)])
    head_bottom = head_top - chart.head_tube_length * up_steer
    forward_normal = np.array([np.sin(ha), np.cos(ha)])
    # the axle is fork_offset ahead of the steer axis, at height r
    foot_height = r - chart.fork_offset * np.cos(ha)
    foot = head_top + (head_top[1] - foot_height) / np.sin(ha) * -up_steer
    front_axle = foot + chart.fork_offset * forward_normal
    ground = head_top[0] + head_top[1] / np.tan(ha)
    trail = ground - front_axle[0]
    seat_top = bb + chart.seat_tube_length * np.array([-np.cos(sa), np.sin(sa)])
    points = {"rear_axle": np.array([0.0, r]), "front_axle": front_axle, "bottom_bracket": bb,
              "head_top": head_top, "head_bottom": head_bottom, "seat_top": seat_top}
    values = {"wheelbase": front_axle[0], "front_center": float(np.hypot(*(front_axle - bb))), "trail": trail,
              "mechanical_trail": trail * np.sin(ha), "wheel_flop": trail * np.sin(ha) * np.cos(ha),
              "top_tube_length": chart.reach + chart.stack / np.tan(sa), "bb_height": bb[1]}
    return points, values


def _check_feasible(chart, node):
    points, values = construct(chart)
    if points["front_axle"][0] <= points["bottom_bracket"][0]:
        node.fail(f"a front axle ahead of the bottom bracket (front centre {values['front_center'] * 1000:.1f} mm)",
                  "reach")
    if values["bb_height"] <= 0:
        node.fail(f"a bottom bracket above the ground (bb_drop {chart.bb_drop * 1000:.1f} mm and a wheel "
                  f"radius of {chart.wheel_radius * 1000:.1f} mm put it {values['bb_height'] * 1000:.1f} mm high)",
                  "bb_drop")
    fork_length = (points["head_bottom"][1] - chart.wheel_radius) / np.sin(chart.head_tube_angle)
    if fork_length <= 0:
        node.fail(f"a head tube whose bottom is above the front axle (it is {-fork_length * 1000:.1f} mm "
                  f"below it along the steer axis: stack too small or head tube too long)", "head_tube_length")
    if points["seat_top"][1] <= points["bottom_bracket"][1]:
        node.fail("a seat tube rising from the bottom bracket", "seat_tube_angle")


def check_redundant(chart, values, node, extra=None):
    """Fail at the first checked chart key whose value differs from the construction
    (``values``, m) by more than its tolerance; ``extra`` adds values derived elsewhere."""
    values = chart.stock_values({**values, **(extra or {})})
    tolerances = {**TOLERANCES, **dict(chart.tolerances)}
    for key, given in chart.checks:
        if key not in values:
            continue
        built = values[key]
        if abs(built - given) > tolerances[key]:
            stock = (f" with its stock wheel ({chart.stock_radius * 1000:.1f} mm radius: bb_height + bb_drop)"
                     if chart.stock_radius is not None and key in WHEEL_DEPENDENT else "")
            node.fail(f"a {key} within {tolerances[key] * 1000:g} mm of {built * 1000:.1f} mm, what the chart's "
                      f"frame gives{stock} (stack, reach, angles, bb_drop, fork_offset, chainstay, wheel); "
                      f"got {given * 1000:.1f} mm", key)


def tyre_change_note(chart, values, source):
    """A warning line where the chart's wheel is not the one its published values were measured
    with (``chart.stock_radius``): what the wheel given makes of the BB height and trail; else None."""
    if chart.stock_radius is None:
        return None
    stock = chart.stock_values(values)
    changed = ", ".join(f"{key.replace('_', ' ')} {stock[key] * 1000:.1f} -> {values[key] * 1000:.1f} mm"
                        for key in ("bb_height", "trail") if values.get(key) is not None)
    return (f"{source}: chart.wheel: a wheel of {chart.wheel_radius * 1000:.1f} mm radius on a frame whose chart "
            f"was measured with one of {chart.stock_radius * 1000:.1f} mm (bb_height + bb_drop): the published "
            f"BB height and trail are checked with the stock wheel, the bicycle is built with this one ({changed})")
