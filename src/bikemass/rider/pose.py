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

from ..core.errors import InputError
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
UNPAIRED = ("head", "torso")
"""Segments of a chain pose that are single (every other one is a mirrored pair)."""


def is_lumped(segment):
    """Whether a pose's segment (its plain value) is a lumped body: ``mass``, ``com``, ``inertia``, given
    in the bicycle's frame, not placed by an anthropometry."""
    return isinstance(segment, dict) and "mass" in segment


def read_pose(node, as_printed=False):
    """(name, parts) of the pose in the YAML ``node`` (see the module docstring)."""
    node.check_keys(required=("segments",), optional=("name", "body", "source", "posture", "units"))
    if node.has("units"):
        _check_units(node["units"])
    segments = node["segments"]
    if not segments.mapping():
        segments.fail("at least one segment")
    placed = [(k, s) for k, s in segments.items() if not is_lumped(s.value)]
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
        elif is_lumped(seg.value):
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
    if not mirror:
        if seg.has("left"):
            seg.fail("no left: placement (only a mirrored pair has a left copy)", "left")
        return _parts(segment, values["location"], values["angle"], frame, False)
    y = values["location"][1]
    if y == 0:
        seg.fail("a nonzero y for a mirrored pair (the copies sit at +y and -y)", "location")
    left = _left_placement(seg["left"], y) if seg.has("left") else None
    return _parts(segment, values["location"], values["angle"], frame, True, left)


def _parts(segment, location, angle, frame, mirror, left=None):
    """The part of body ``segment`` at ``location`` (m) and ``angle`` (deg), or with ``mirror`` the
    pair: its -y copy the mirror image or the ``left`` placement."""
    placement = Placement.thesis_segment(location, angle)
    if not mirror:
        return [Part(segment.name, segment.solid, segment.mass, placement, frame)]
    other = left if left is not None else Placement(MIRROR_Y @ placement.rotation @ MIRROR_Y,
                                                    MIRROR_Y @ placement.translation)
    return [Part(f"{segment.name}_{'right' if p.translation[1] > 0 else 'left'}",
                 segment.solid, segment.mass, p, frame) for p in (placement, other)]


def pose_parts(pose, anthropometry, front=(), source=None):
    """The parts of ``anthropometry`` placed by the solved chain ``pose`` (a
    :class:`~bikemass.rider.chain.ChainPose`), the segments in ``front`` on the front frame: the
    parts :func:`read_pose` makes of the pose's placement form (``pose.placement_form``), from the
    typed placements rather than from the document read back.

    Parameters
    ----------
    pose : ChainPose
        A solved pose (``Solution.pose``); its placements are in m and deg.
    anthropometry : Anthropometry
        The body's segments (``load_body(...).anthropometry``): one for each placed segment.
    front : sequence of str
        Segments that move with the front frame (hands on the bars).
    source : str or Path, optional
        Named by an error (a segment the body lacks, a body segment left unplaced).

    Returns
    -------
    tuple of Part

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.rider.body import load_body
    >>> from bikemass.rider.pose import pose_parts
    >>> from bikemass.core.config import Node
    >>> posed = bm.pose_rider("jamis", hands="hoods")
    >>> body = load_body(Node("thesis_rider", "body", "body")).anthropometry
    >>> [p.name for p in pose_parts(posed.solution.pose, body)][:3]
    ['head', 'torso', 'upper_arm_right']
    """
    right, left = pose.placements()
    parts = []
    for name, (location, angle) in right.items():
        where = f"segments.{name}"
        if name not in anthropometry.segments:
            raise InputError(source, where, f"a segment of the anthropometry ({', '.join(anthropometry.segments)})")
        segment = anthropometry.segments[name]
        mirror = name not in UNPAIRED
        if mirror != segment.pair:
            raise InputError(source, where + ".mirror", f"a {'pair' if mirror else 'single segment'} in the "
                             f"anthropometry ({segment.name} is {'not ' if mirror else ''}one)")
        location = np.array([float(x) + 0.0 for x in location])
        if mirror and location[1] == 0:
            raise InputError(source, where + ".location", "a nonzero y for a mirrored pair (the copies sit at "
                             "+y and -y)")
        other = None
        if name in left:
            other = Placement.thesis_segment(np.array([float(x) + 0.0 for x in left[name][0]]),
                                             float(left[name][1]) + 0.0)
        parts += _parts(segment, location, float(angle) + 0.0, FRAMES["front" if name in front else "rear"],
                        mirror, other)
    missing = [k for k in anthropometry.segments if k not in right]
    if missing:
        raise InputError(source, "segments", f"a placement for every segment of the body (missing: "
                         f"{', '.join(missing)})")
    return tuple(parts)


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

