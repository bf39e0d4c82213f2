"""A chart bicycle -> the keypoints bicycle mapping the loader reads (docs/bicycles.md).

The chart fixes the frame (:mod:`.chart`); everything else comes from
``frames/chart_defaults.yaml`` unless the bicycle file overrides it: the tubeset
(``frame``), the cockpit (stem, bars, grips), the saddle, the crank length, the
brakes, the wheels' hoops (``wheel_parts``) and the components.  The result has
keypoints, tubes, components, wheels, a rear-frame beam structure and ``contacts``
(saddle, grips, bottom bracket, crank) like ``frames/jamis.yaml``.
"""

import functools

import numpy as np

from ..core.config import Node, load_yaml
from ..core.gate import note_read
from ..core.paths import frames_dir
from ..core.units import Quantity
from ..models.plausibility import warn
from .chart import check_redundant, construct, read_chart, tyre_change_note

CHART_TOP_KEYS = ("name", "source", "description", "note", "chart", "sizes", "frame", "cockpit", "saddle",
                  "crank_length", "brakes", "wheel_parts", "wheels", "components", "loads", "materials",
                  "keypoints", "sections", "tubes", "stiffness", "contacts")
COCKPIT_KEYS = ("material", "bar", "spacers", "stem_height", "stem_length", "stem_angle", "bar_width",
                "bar_reach", "bar_drop", "hood_drop", "drop_back", "bar_end_back", "bar_rise", "bar_sweep",
                "grip_inset", "sections", "grips", "note")
SADDLE_KEYS = ("height", "height_per_stack", "setback", "stack", "note")
WHEEL_PART_KEYS = ("rim", "spokes", "tire", "rear_hub", "front_hub", "rear_spacing", "front_spacing",
                   "rim_depth", "note")
_WHEEL_PART_DIMENSION = {"rim": "mass", "spokes": "mass", "tire": "mass", "rear_hub": "mass", "front_hub": "mass"}
"""Dimension of each wheel part key (the others are lengths)."""
FRAME_TUBES = ("head_tube_top", "head_tube", "top_tube", "down_tube", "seat_tube", "seat_tube_extension",
               "seat_stay_left", "seat_stay_right", "chain_stay_left", "chain_stay_right")
"""The rear frame's beam structure.  The top tube's centre line meets the head tube and the
seat tube one top-tube diameter below their tops (``top_tube_front``, ``seat_cluster``);
the seat stays meet at the seat cluster."""
FORK_HALF_WIDTH = 0.05
"""m: fork blades either side of the centre plane at the crown and at the axle."""
HUB_DIAMETER = 0.05
"""m: hub hoop diameter (and the spokes' inner diameter)."""
MAX_SADDLE_HEIGHT = 1.1
"""m: a saddle higher above the crank axis is warned about (LeMond's 0.883 x inseam gives about
0.95 m for a 2.1 m tall rider's 1.07 m inseam)."""
MIN_POST = 0.05
"""m: seat post showing above the seat tube at least, where the default saddle height would leave less."""
HOOP_THICKNESS = 0.02
"""m: axial thickness of the spoke and rim hoops."""


def load_defaults():
    """The chart defaults (``frames/chart_defaults.yaml``) as a :class:`~bikemass.core.config.Node`."""
    path = frames_dir() / "chart_defaults.yaml"
    node = _parsed(path, path.stat().st_mtime_ns)
    note_read(path)
    return Node(_tree_copy(node.value), node.source, node.key)


def _tree_copy(value):
    """A copy of a parsed YAML value: new mappings and lists, the (immutable) scalars shared
    (``copy.deepcopy`` does the same four times slower: its memo and dispatch per scalar)."""
    if isinstance(value, dict):
        return {k: _tree_copy(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_tree_copy(v) for v in value]
    return value


@functools.lru_cache(maxsize=4)
def _parsed(path, mtime):
    """The parsed defaults file (kept while the file is unchanged: parsing it dominates a load)."""
    return load_yaml(path)


def _xyz(p, y=0.0):
    """(x, height) -> benchmark [x, y, z] (z down)."""
    return [float(p[0]), float(y), float(-p[1])]


def _merged(default, node, allowed):
    """``default``'s mapping with ``node``'s keys on top (keys checked against ``allowed``);
    a Node over the result blamed on ``node``'s file and key."""
    node.check_keys(optional=allowed)
    value = {**_tree_copy(default.mapping()), **node.mapping()}
    return Node(value, node.source, node.key)


def _length(node):
    return node.number("length")


def expand_chart(node):
    """``(mapping Node, Chart)``: the keypoints bicycle mapping for chart bicycle ``node``."""
    node.check_keys(required=("name", "chart"), optional=CHART_TOP_KEYS)
    defaults = load_defaults()
    chart = read_chart(node["chart"])
    points, values = construct(chart)
    kp = {k: _xyz(p) for k, p in points.items()}

    tubeset, material, sections = _frame(node, defaults)
    cockpit = _merged(defaults["cockpit"], node.get("cockpit", {}), COCKPIT_KEYS)
    bars, grips, bar_tubes = _cockpit(chart, points, cockpit)
    kp.update(bars)
    sections.update({k: v.value for k, v in cockpit["sections"].items()})
    saddle = _merged(defaults["saddle"], node.get("saddle", {}), SADDLE_KEYS)
    saddle_point, post_top = _saddle(chart, points, saddle)
    kp["seatpost_top"] = _xyz(post_top)
    wheels = _wheel_parts(node, defaults, chart)
    half_rear = wheels["rear_spacing"] / 2
    for side, y in (("left", -1), ("right", 1)):
        kp[f"dropout_{side}"] = _xyz(points["rear_axle"], y * half_rear)
        kp[f"crown_{side}"] = _xyz(points["head_bottom"], y * FORK_HALF_WIDTH)
        kp[f"fork_end_{side}"] = _xyz(points["front_axle"], y * FORK_HALF_WIDTH)
    for name, point in node.get("keypoints", {}).items():
        if name in kp:
            point.fail(f"a keypoint name other than the chart's ({', '.join(kp)})")
        kp[name] = point.value
    sections.update(node.get("sections", {}).value)

    top_tube = _top_tube_diameter(sections, node)
    for name, top, length, angle in (("top_tube_front", "head_top", chart.head_tube_length, chart.head_tube_angle),
                                     ("seat_cluster", "seat_top", chart.seat_tube_length, chart.seat_tube_angle)):
        if top_tube >= length:
            node.fail(f"a top tube thinner than the {top.split('_')[0]} tube is long ({length * 1000:.0f} mm)",
                      "frame.sections.top_tube")
        points[name] = points[top] - top_tube * np.array([-np.cos(angle), np.sin(angle)])
        kp[name] = _xyz(points[name])
    midpoint_height = (points["top_tube_front"][1] + points["seat_cluster"][1]) / 2
    check_redundant(chart, values, node["chart"], {"standover": midpoint_height + top_tube / 2})
    note = tyre_change_note(chart, values, node.source)
    if note:
        warn(note)

    cockpit_material = cockpit["material"].string()
    tubes = [_tube(n, a, b, s) for n, a, b, s in (
        ("head_tube_top", "head_top", "top_tube_front", "head_tube"),
        ("head_tube", "top_tube_front", "head_bottom", "head_tube"),
        ("top_tube", "top_tube_front", "seat_cluster", "top_tube"),
        ("down_tube", "head_bottom", "bottom_bracket", "down_tube"),
        ("seat_tube", "bottom_bracket", "seat_cluster", "seat_tube"),
        ("seat_tube_extension", "seat_cluster", "seat_top", "seat_tube"),
        ("seat_stay_left", "seat_cluster", "dropout_left", "seat_stay"),
        ("seat_stay_right", "seat_cluster", "dropout_right", "seat_stay"),
        ("chain_stay_left", "bottom_bracket", "dropout_left", "chain_stay"),
        ("chain_stay_right", "bottom_bracket", "dropout_right", "chain_stay"))]
    tubes.append(_tube("seatpost", "seat_top", "seatpost_top", "seatpost", material=cockpit_material))
    tubes += [_tube(n, a, b, "fork", body="front_frame") for n, a, b in (
        ("fork_crown", "crown_left", "crown_right"), ("fork_blade_left", "crown_left", "fork_end_left"),
        ("fork_blade_right", "crown_right", "fork_end_right"))]
    tubes.append(_tube("steerer", "head_bottom", "stem_top", "steerer", body="front_frame"))
    tubes += [_tube(n, a, b, s, body="front_frame", material=cockpit_material) for n, a, b, s in bar_tubes]
    tubes += node.get("tubes", []).value

    anchors = _anchors(points, kp, saddle_point, grips, cockpit["bar"].value,
                       node.get("brakes", defaults["brakes"].value).string(choices=("rim", "disc")), chart)
    mapping = {
        "name": node["name"].value,
        "geometry": {"wheelbase": float(values["wheelbase"]), "trail": float(values["trail"]),
                     "head_angle": Quantity(chart.head_tube_angle, "rad"), "rear_wheel_radius": chart.wheel_radius,
                     "front_wheel_radius": chart.wheel_radius, "fork_offset": chart.fork_offset},
        "keypoints": kp,
        "material": material,
        "sections": sections,
        "tubes": tubes,
        "structure": {"tubes": list(FRAME_TUBES), "dropouts": ["dropout_left", "dropout_right"],
                      "head_tube": ["head_top", "head_bottom"]},
        "components": _components(node, defaults, anchors),
        "wheels": node["wheels"].value if node.has("wheels") else _wheels(wheels, chart),
        "contacts": node["contacts"].value if node.has("contacts") else {
            "saddle": _saddle_contact(node, chart, saddle, saddle_point),
            "bottom_bracket": "bottom_bracket",
            "crank_length": node.get("crank_length", defaults["crank_length"].value).value,
            "grips": grips},
    }
    for key in ("source", "description", "loads", "stiffness", "materials"):
        if node.has(key):
            mapping[key] = node[key].value
    return Node(mapping, node.source, ""), chart


def _frame(node, defaults):
    frame = node.get("frame", {})
    frame.check_keys(optional=("tubeset", "material", "sections", "note"))
    names = tuple(k for k, _ in defaults["tubesets"].items())
    name = frame.get("tubeset", defaults["tubeset"].value).string(choices=names)
    tubeset = defaults["tubesets"][name]
    sections = {k: v.value for k, v in tubeset["sections"].items()}
    for role, spec in frame.get("sections", {}).items():
        if role not in sections:
            spec.fail(f"a frame tube of the tubeset ({', '.join(sections)})")
        sections[role] = spec.value
    material = frame.get("material", tubeset["material"].value).string()
    return name, material, sections


def _tube(name, start, end, section, body="rear_frame", material=None):
    tube = {"name": name, "from": start, "to": end, "section": section, "body": body}
    if material is not None:
        tube["material"] = material
    return tube


def _top_tube_diameter(sections, node):
    spec = Node(sections["top_tube"], node.source, "frame.sections.top_tube")
    return spec["side"].number("length") if spec.has("side") else spec["outer_diameter"].number("length")


def _cockpit(chart, points, c):
    """Keypoints of steerer, stem and bars, the grips (right hand) and the bar tubes."""
    ha = chart.head_tube_angle
    up = np.array([-np.cos(ha), np.sin(ha)])
    forward = np.array([np.sin(ha), np.cos(ha)])
    stem_top = points["head_top"] + (_length(c["spacers"]) + _length(c["stem_height"]) / 2) * up
    angle = c["stem_angle"].number("angle")
    clamp = stem_top + _length(c["stem_length"]) * (np.cos(angle) * forward + np.sin(angle) * up)
    half = _length(c["bar_width"]) / 2
    if half <= 0:
        c.fail("a positive bar width", "bar_width")
    kp = {"stem_top": _xyz(stem_top), "bar_clamp": _xyz(clamp)}
    bar = c["bar"].string(choices=("drop", "flat"))
    if bar == "drop":
        reach, drop = _length(c["bar_reach"]), _length(c["bar_drop"])
        shape = {"bar": clamp, "hood": clamp + [reach, -_length(c["hood_drop"])],
                 "drop": clamp + [reach - _length(c["drop_back"]), -drop]}
        shape["drop_end"] = shape["drop"] + [-_length(c["bar_end_back"]), 0.01]
        for part, p in shape.items():
            kp[f"{part}_left"], kp[f"{part}_right"] = _xyz(p, -half), _xyz(p, half)
        grips = {"tops": "bar_right", "hoods": "hood_right", "drops": "drop_right"}
        tubes = [("handlebar_top", "bar_left", "bar_right", "handlebar")]
        for side in ("left", "right"):
            tubes += [(f"bar_reach_{side}", f"bar_{side}", f"hood_{side}", "handlebar"),
                      (f"bar_drop_{side}", f"hood_{side}", f"drop_{side}", "handlebar"),
                      (f"bar_end_{side}", f"drop_{side}", f"drop_end_{side}", "handlebar")]
    else:
        end = clamp + [-_length(c["bar_sweep"]), _length(c["bar_rise"])]
        kp["bar_left"], kp["bar_right"] = _xyz(end, -half), _xyz(end, half)
        grip = _xyz(end, half - _length(c["grip_inset"]))
        grips = {"tops": grip, "hoods": grip}      # one grip, by the levers (as the Cargo's flat bar)
        tubes = [("handlebar_left", "bar_clamp", "bar_left", "handlebar"),
                 ("handlebar_right", "bar_clamp", "bar_right", "handlebar")]
    stem_length = _length(c["stem_length"])
    if stem_length < 0:
        c.fail(f"a stem length of 0 or more, got {stem_length * 1000:g} mm", "stem_length")
    if stem_length > 0:            # 0: bars clamped on the steerer (folding bicycles' stem posts)
        tubes.insert(0, ("stem", "stem_top", "bar_clamp", "stem"))
    for name, offset in c.get("grips", {}).items():
        forward_up = offset.vector("length", 2)
        grips[name] = _xyz(clamp + forward_up, half)
    return kp, grips, tubes


def _saddle(chart, points, s):
    """Saddle top point and seat post top (x, height)."""
    sa = chart.seat_tube_angle
    along = np.array([-np.cos(sa), np.sin(sa)])
    shortest = chart.seat_tube_length + _length(s["stack"]) + MIN_POST
    if s.has("height"):
        height = _length(s["height"])
    else:
        height = max(s["height_per_stack"].number("dimensionless", positive=True) * chart.stack, shortest)
    post = height - _length(s["stack"])
    if post <= chart.seat_tube_length:
        s.fail(f"a saddle height above the seat tube's top plus the saddle's stack "
               f"({(chart.seat_tube_length + _length(s['stack'])) * 1000:.0f} mm), got {height * 1000:.0f} mm",
               "height")
    if height > MAX_SADDLE_HEIGHT:
        warn(f"{s.source}: {s.key}.height: a saddle {height * 1000:.0f} mm above the crank axis, more than "
             f"{MAX_SADDLE_HEIGHT * 1000:.0f} mm: no rider's legs reach that far (LeMond: 0.883 x inseam)")
    bb = points["bottom_bracket"]
    return bb + height * along - [_length(s["setback"]), 0.0], bb + post * along


def _saddle_contact(node, chart, saddle, saddle_point):
    """The rider's sit point: the saddle where the file sets its height (``height`` or
    ``height_per_stack``), else fitted to each rider's inseam along the seat tube (LeMond),
    no lower than the saddle on a seat post pushed fully into the seat tube."""
    own = node.get("saddle", {})
    if own.has("height") or own.has("height_per_stack"):
        return _xyz(saddle_point)
    return {"fit": "lemond", "towards": "seat_top", "setback": _length(saddle["setback"]),
            "lowest": chart.seat_tube_length + _length(saddle["stack"])}


def _wheel_parts(node, defaults, chart):
    """Hoop masses (kg) and hub spacings (m) of the wheels, defaults by bead-seat diameter."""
    d = defaults["wheels"]
    given = node.get("wheel_parts", {})
    given.check_keys(optional=WHEEL_PART_KEYS)
    tire = chart.tire_width if chart.tire_width is not None else 0.025
    bsd = 2 * (chart.wheel_radius - tire)
    sizes = {int(k): v for k, v in d["sizes"].items()}
    nearest = min(sizes, key=lambda s: abs(s / 1000 - bsd))
    table = sizes[nearest]
    scale = bsd / (nearest / 1000)
    parts = {"rim": table["rim"].number("mass") * scale, "spokes": table["spokes"].number("mass") * scale,
             "tire": table["tire"].number("mass") * tire / table["reference_width"].number("length"),
             "bsd": bsd, "tire_width": tire}
    for key in ("rear_hub", "front_hub", "rear_spacing", "front_spacing", "rim_depth"):
        parts[key] = d[key].number(_WHEEL_PART_DIMENSION.get(key, "length"))
    for key in WHEEL_PART_KEYS[:-1]:
        if given.has(key):
            parts[key] = given[key].number(_WHEEL_PART_DIMENSION.get(key, "length"), positive=True)
    if parts["bsd"] - 2 * parts["rim_depth"] <= HUB_DIAMETER:
        given.fail("a rim depth leaving room for the spokes", "rim_depth")
    return parts


def _wheels(w, chart):
    """Standard ``wheels:`` mapping: hub, spokes, rim and tire hoops of both wheels."""
    rim_inner = w["bsd"] - 2 * w["rim_depth"]
    outer = 2 * chart.wheel_radius

    def hoops(hub, spacing):
        return {"hub": {"inner_diameter": 0.0, "outer_diameter": HUB_DIAMETER, "thickness": spacing, "mass": hub},
                "spokes": {"inner_diameter": HUB_DIAMETER, "outer_diameter": rim_inner,
                           "thickness": HOOP_THICKNESS, "mass": w["spokes"]},
                "rim": {"inner_diameter": rim_inner, "outer_diameter": w["bsd"], "thickness": HOOP_THICKNESS,
                        "mass": w["rim"]},
                "tire": {"inner_diameter": w["bsd"], "outer_diameter": outer, "thickness": w["tire_width"],
                         "mass": w["tire"]}}
    return {"rear": {"hoops": hoops(w["rear_hub"], w["rear_spacing"])},
            "front": {"hoops": hoops(w["front_hub"], w["front_spacing"])}}


def _anchors(points, kp, saddle_point, grips, bar, brakes, chart):
    """Named points (benchmark [x, y, z]) that default components are placed at."""
    anchors = {k: np.array(v, dtype=float) for k, v in kp.items() if not isinstance(v, str)}
    anchors["saddle"] = np.array(_xyz(saddle_point))
    lever = grips["hoods"] if bar == "drop" else grips["tops"]
    anchors["levers"] = np.array(kp[lever] if isinstance(lever, str) else lever)
    anchors["chain_line"] = (anchors["bottom_bracket"] + anchors["rear_axle"]) / 2
    reach = chart.wheel_radius + 0.01
    if brakes == "rim":
        for which, axle, toward in (("rear", "rear_axle", "seat_top"), ("front", "front_axle", "head_bottom")):
            direction = anchors[toward] - anchors[axle]
            anchors[f"{which}_brake"] = anchors[axle] + reach * direction / np.linalg.norm(direction)
    else:
        anchors["rear_brake"] = anchors["rear_axle"] + [-0.05, 0.0, -0.05]
        anchors["front_brake"] = anchors["front_axle"] + [-0.04, 0.0, -0.04]
    return anchors


def _components(node, defaults, anchors):
    """Default components merged by name with the file's ``components`` mapping (null removes one)."""
    given = node.get("components", {})
    chosen = {name: spec.mapping() for name, spec in defaults["components"].items()}
    for name, spec in given.items():
        if spec.missing:
            chosen.pop(name, None)
        else:
            chosen[name] = {**chosen.get(name, {}), **spec.mapping()}
    out = []
    for name, spec in chosen.items():
        item = Node(spec, node.source, f"components.{name}")
        entry = {k: v for k, v in spec.items() if k not in ("anchor", "offset")}
        entry["name"] = name
        entry.setdefault("body", "rear_frame")
        if item.has("anchor") == item.has("at"):
            item.fail("exactly one of anchor (a chart point: " + ", ".join(sorted(anchors)) + ") or at")
        if item.has("at") and isinstance(item["at"].value, str):
            entry["at"] = anchors[item["at"].string(choices=tuple(sorted(anchors)))].tolist()
        if item.has("anchor"):
            anchor = item["anchor"].string(choices=tuple(sorted(anchors)))
            offset = item["offset"].vector("length") if item.has("offset") else np.zeros(3)
            entry["at"] = (anchors[anchor] + offset).tolist()
        out.append(entry)
    return out
