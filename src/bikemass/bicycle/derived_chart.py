"""The geometry chart of any bicycle, chart or keypoints (definitions in :mod:`.chart`).

Frame points of a keypoints bicycle: the bottom bracket is keypoint ``bottom_bracket``
(or the ``contacts`` one), the head tube the ``structure``'s pair (or keypoints
``head_top``/``head_bottom``), the seat tube's top the far end of tube
``seat_tube_extension`` (else ``seat_tube``, else keypoint ``seat_top``), the top tube
the tube ``top_tube``.  Values that need a point the bicycle lacks are ``None``
(a benchmark parameter file has only the wheels and the steer axis).
"""

import numpy as np

from ..core.units import Quantity

CHART_ORDER = ("wheelbase", "front_center", "trail", "mechanical_trail", "wheel_flop", "stack", "reach",
               "head_tube_angle", "seat_tube_angle", "head_tube_length", "seat_tube_length",
               "top_tube_length", "chainstay_length", "bb_drop", "bb_height", "standover", "fork_offset",
               "rear_wheel_radius", "front_wheel_radius")
"""Keys of :func:`derived_chart`, in the order tables show them."""
ANGLES = ("head_tube_angle", "seat_tube_angle")
"""Keys in degrees; every other key is a length in m."""


def _xh(p):
    """Benchmark [x, y, z] -> (x, height)."""
    return np.array([p[0], -p[2]], dtype=float)


def _tube(bicycle, name):
    return next((t for t in bicycle.tubes if t.name == name), None)


def frame_points(bicycle):
    """``{bottom_bracket, head_top, head_bottom, seat_top}`` as (x, height) (m), those found."""
    kp = bicycle.keypoints
    points = {}
    if "bottom_bracket" in kp:
        points["bottom_bracket"] = _xh(kp["bottom_bracket"])
    elif bicycle.contacts is not None:
        points["bottom_bracket"] = _xh(bicycle.contacts.bottom_bracket)
    head = bicycle.structure.head_tube if bicycle.structure is not None else ("head_top", "head_bottom")
    if all(k in kp for k in head):
        points["head_top"], points["head_bottom"] = (_xh(kp[k]) for k in head)
    seat = _tube(bicycle, "seat_tube_extension") or _tube(bicycle, "seat_tube")
    if seat is not None and "bottom_bracket" in points:
        ends = [_xh(seat.start), _xh(seat.end)]
        points["seat_top"] = max(ends, key=lambda p: np.linalg.norm(p - points["bottom_bracket"]))
    elif "seat_top" in kp:
        points["seat_top"] = _xh(kp["seat_top"])
    return points


def derived_chart(bicycle):
    """``{key: value}`` (m; angles in deg) for every key of :data:`CHART_ORDER` (``None`` if unknown)."""
    g = bicycle.geometry
    ha = g.head_angle
    out = dict.fromkeys(CHART_ORDER)
    out.update(wheelbase=g.wheelbase, trail=g.trail, mechanical_trail=g.trail * np.sin(ha),
               wheel_flop=g.trail * np.sin(ha) * np.cos(ha), head_tube_angle=np.degrees(ha),
               fork_offset=g.fork_offset(), rear_wheel_radius=g.rear_wheel_radius,
               front_wheel_radius=g.front_wheel_radius)
    p = frame_points(bicycle)
    rear, front = _xh(g.rear_axle), _xh(g.front_axle)
    if "bottom_bracket" in p:
        bb = p["bottom_bracket"]
        axle_line = rear[1] + (front[1] - rear[1]) * bb[0] / g.wheelbase
        out.update(front_center=np.hypot(*(front - bb)), chainstay_length=np.hypot(*(bb - rear)),
                   bb_drop=axle_line - bb[1], bb_height=bb[1])
        if "head_top" in p:
            out.update(stack=p["head_top"][1] - bb[1], reach=p["head_top"][0] - bb[0])
        if "seat_top" in p:
            d = p["seat_top"] - bb
            seat_angle = np.arctan2(d[1], -d[0])
            out.update(seat_tube_angle=np.degrees(seat_angle), seat_tube_length=np.hypot(*d))
            if "head_top" in p:
                out["top_tube_length"] = out["reach"] + out["stack"] / np.tan(seat_angle)
    if "head_top" in p:
        out["head_tube_length"] = np.hypot(*(p["head_top"] - p["head_bottom"]))
    top = _tube(bicycle, "top_tube")
    if top is not None:
        radius = getattr(top.section, "outer_diameter", None) or top.section.side
        out["standover"] = (_xh(top.start)[1] + _xh(top.end)[1]) / 2 + radius / 2
    return {k: (None if v is None else float(v)) for k, v in out.items()}


def chart_mapping(chart):
    """A ``chart:`` mapping that rebuilds the frame of ``derived_chart`` output: its values typed
    with their units (:class:`~bikemass.core.units.Quantity`, m and deg), read as they are by
    ``bm.load_bicycle({"name": ..., "chart": ...})`` and written as ``"<number> <unit>"`` text by
    :func:`~bikemass.core.plain.file_form` for a file."""
    keys = ("stack", "reach", "head_tube_angle", "seat_tube_angle", "head_tube_length", "seat_tube_length",
            "chainstay_length", "bb_drop", "fork_offset")
    missing = [k for k in keys if chart[k] is None]
    if missing:
        raise ValueError(f"the bicycle has no {', '.join(missing)} (no frame keypoints)")
    out = {k: Quantity(chart[k], "deg" if k in ANGLES else "m") for k in keys}
    out["wheel_radius"] = Quantity(chart["rear_wheel_radius"], "m")
    return out
