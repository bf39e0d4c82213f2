"""A pose: where each segment of an anthropometry sits, read from ``bodies/poses/<name>.yaml``.

Pose file (metres, degrees; Williams 2015, Table 3-3 conventions)::

    name: Relaxed
    body: thesis_rider            # an anthropometry in bodies/
    segments:
      head:      {location: [0.402, 0.0, -1.895], angle: 15.362 deg}
      upper_arm: {location: [0.322, 0.238, -1.609], angle: -20.251 deg, mirror: true}

* ``location``: centre of the segment's top plane in the benchmark frame;
* ``angle``: clockwise about y seen from +y with x to the right; the segment's
  axis is ``(-sin a, 0, cos a)`` (0 = hanging straight down);
* ``mirror: true``: a pair (``pair: true`` in the anthropometry) at +y and -y;
* ``left: {location, angle}``: the -y copy of a pair placed on its own instead of as
  the mirror image (e.g. legs on pedals at a crank angle, docs/poses.md);
* ``frame: front``: the segment moves with the front frame (default ``rear``);
* ``printed: {location: [...], angle: ...}``: the value as published, used instead
  with ``as_printed=True`` (records an erratum machine-readably).

A segment with ``mass``, ``com`` and ``inertia`` (kg, m, kg m^2 about the com,
tensor products) is a lumped body and needs no anthropometry.
"""

import numpy as np

from ..mass.inertia import MassProperties
from ..mass.parts import Part
from ..mass.placement import Placement
from ..mass.solids import Lumped
from ..models.plausibility import check_inertia
from .body import load_body

FRAMES = {"rear": "rear_frame", "front": "front_frame"}
"""Pose ``frame`` value -> :attr:`Part.body`."""

PLACED_KEYS = ("location", "angle")
LUMPED_KEYS = ("mass", "com", "inertia")
MIRROR_Y = np.diag([1.0, -1.0, 1.0])


def read_pose(node, as_printed=False):
    """(name, parts) of the pose in the YAML ``node`` (see the module docstring)."""
    node.check_keys(required=("segments",), optional=("name", "body", "source", "posture", "units"))
    if node.has("units"):
        _check_units(node["units"])
    segments = node["segments"]
    if not segments.mapping():
        segments.fail("at least one segment")
    placed = [(k, s) for k, s in segments.items() if not (isinstance(s.value, dict) and "mass" in s.value)]
    body = None
    if placed:
        if not node.has("body"):
            placed[0][1].fail("a lumped body with mass, com, inertia (placed segments need a "
                              "top-level body: naming their anthropometry)")
        body = load_body(node["body"]).anthropometry
    parts = []
    for key, seg in segments.items():
        if body is not None and key in body.segments:
            parts += _placed_parts(seg, body.segments[key], as_printed)
        elif isinstance(seg.value, dict) and "mass" in seg.value:
            parts.append(_lumped_part(key, seg))
        else:
            known = ", ".join(body.segments) if body else "none"
            seg.fail(f"a segment of the anthropometry ({known}) or a lumped body with {', '.join(LUMPED_KEYS)}")
    if body is not None:
        _check_all_placed(segments, body, [k for k, _ in placed])
    name = node.get("name", str(node.source)).string()
    return name, tuple(parts)


POSE_UNITS = {"location": "m", "angle": "deg", "mass": "kg", "com": "m", "inertia": "kg m^2"}
"""The units a pose file's numbers are read in (what ``bikemass pose --format yaml`` states)."""


def _check_units(node):
    """A ``units`` block may only state the units the values are read in (a number with another
    unit is written as ``"<number> <unit>"``)."""
    for key, unit in node.items():
        if key in POSE_UNITS and unit.value != POSE_UNITS[key]:
            unit.fail(f"{POSE_UNITS[key]} (write a value in another unit as '<number> <unit>')")


def _check_all_placed(segments, body, placed):
    missing = [k for k in body.segments if k not in placed]
    if missing:
        segments.fail(f"a placement for every segment of {body.source.name} (missing: {', '.join(missing)})")


def _frame(seg):
    return FRAMES[seg.get("frame", "rear").string(choices=tuple(FRAMES))]


def angle_deg(node):
    """An angle in degrees from ``"<x> deg"`` or ``"<x> rad"`` (a bare number is refused, see units)."""
    return node.number("angle", unit="deg")


def _placed_parts(seg, segment, as_printed):
    """The part (or the +y/-y pair) of body ``segment`` placed by the pose node ``seg``."""
    seg.check_keys(required=PLACED_KEYS, optional=("mirror", "frame", "printed", "left"))
    values = {"location": seg["location"].vector("length", 3), "angle": angle_deg(seg["angle"])}
    if seg.has("printed"):
        printed = seg["printed"]
        printed.check_keys(optional=PLACED_KEYS)
        published = {k: v.vector("length", 3) if k == "location" else angle_deg(v) for k, v in printed.items()}
        if as_printed:
            values.update(published)
    mirror = seg.get("mirror", False).boolean()
    if mirror != segment.pair:
        what = "a pair (pair: true)" if segment.pair else "a single segment (no pair: true)"
        seg.fail(f"mirror: {str(segment.pair).lower()} ({segment.name} is {what} in the anthropometry)",
                 "mirror")
    frame = _frame(seg)
    placement = Placement.thesis_segment(values["location"], values["angle"])
    if not mirror:
        if seg.has("left"):
            seg.fail("no left: placement (only a mirrored pair has a left copy)", "left")
        return [Part(segment.name, segment.solid, segment.mass, placement, frame)]
    y = values["location"][1]
    if y == 0:
        seg.fail("a nonzero y for a mirrored pair (the copies sit at +y and -y)", "location")
    other = Placement(MIRROR_Y @ placement.rotation @ MIRROR_Y, MIRROR_Y @ placement.translation)
    if seg.has("left"):
        other = _left_placement(seg["left"], y)
    return [Part(f"{segment.name}_{'right' if p.translation[1] > 0 else 'left'}",
                 segment.solid, segment.mass, p, frame) for p in (placement, other)]


def _left_placement(node, y):
    """The -y copy of a pair placed on its own (``left: {location, angle}``, e.g. legs on pedals)."""
    node.check_keys(required=PLACED_KEYS)
    location = node["location"].vector("length", 3)
    if not location[1] * y < 0:
        node.fail(f"a y on the other side from the pair's location (y = {y:g})", "location")
    return Placement.thesis_segment(location, angle_deg(node["angle"]))


def _lumped_part(key, seg):
    """A lumped body (mass, com, central inertia) as one part."""
    seg.check_keys(required=LUMPED_KEYS, optional=("frame",))
    inertia = check_inertia(seg["inertia"].matrix("inertia", (3, 3)), seg, "inertia")
    props = MassProperties(seg["mass"].number("mass", positive=True), seg["com"].vector("length", 3), inertia)
    return Part(key, Lumped(props), props.mass, Placement.identity(), _frame(seg))

