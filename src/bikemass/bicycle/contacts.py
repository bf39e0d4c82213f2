"""Rider contact points of a bicycle: the ``contacts:`` section of its YAML file.

::

    contacts:
      saddle: [0.153, 0, -0.9985]      # where the rider's sit point rests (m, or a keypoint name)
      bottom_bracket: bottom_bracket   # crank axis (a keypoint name or [x, y, z])
      crank_length: 170 mm
      grips:                           # hand positions: the right hand's point (mirrored to -y)
        tops: bar_right
        hoods: hood_right

Only x and z matter to the planar rider chain (docs/poses.md); y is kept for drawings.

Where the bicycle does not fix the saddle, ``saddle: {fit: lemond, seat_tube_angle: 73 deg}``
(or ``towards: KEYPOINT`` for the seat tube's direction from the bottom bracket) puts the
sit point on the seat-tube line through the bottom bracket at LeMond's saddle height,
0.883 x the rider's inseam from the crank axis (:data:`SADDLE_RULES`); an optional
``setback`` moves it that far (m, horizontal) behind the seat-tube line, and an optional
``lowest`` (m from the crank axis) is as low as the saddle goes (the seat tube's top plus
the saddle): a rider too short for the frame then cannot reach the pedals (an error).
"""

from dataclasses import dataclass

import numpy as np

from ..core.frozen import frozen_fields
from ..models.plausibility import warn

HAND_POSITIONS = ("tops", "hoods", "drops", "aero")
"""The usual grip names (``bikemass pose --hands``); a bicycle may name others."""

SADDLE_RULES = {"lemond": 0.883}
"""Saddle height (crank axis to the sit point along the seat tube) as a fraction of the
rider's inseam: LeMond & Gordis (1987), "Greg LeMond's Complete Book of Bicycling"."""


@dataclass(frozen=True, eq=False)
class Contacts:
    """Contact points (m, benchmark frame) and the file/key each came from (for error messages)."""

    saddle: np.ndarray
    bottom_bracket: np.ndarray
    crank_length: float
    grips: dict
    source: str
    key: str = "contacts"
    saddle_fit: tuple = None
    """``(rule, unit direction from the crank axis up the seat tube, setback (m), lowest (m))``
    when ``saddle`` is fitted to the rider (then ``saddle`` is None), else None."""

    def sit_point(self, inseam):
        """The saddle point (m) for a rider of ``inseam`` (m): fixed, or fitted by the rule."""
        if self.saddle_fit is None:
            return self.saddle
        rule, direction, setback, lowest = self.saddle_fit
        height = max(SADDLE_RULES[rule] * inseam, lowest)
        return self.bottom_bracket + height * direction - [setback, 0.0, 0.0]

    def __post_init__(self):
        frozen_fields(self, "saddle", "bottom_bracket", "grips")

    def pedal(self, crank_deg, side="right"):
        """Pedal spindle centre at crank angle ``crank_deg`` (deg, 0 = right crank forward,
        positive = pedalling: the front going down), right or left (opposite) side."""
        a = np.radians(crank_deg) + (np.pi if side == "left" else 0.0)
        return self.bottom_bracket + self.crank_length * np.array([np.cos(a), 0.0, np.sin(a)])


def _point(node, keypoints):
    if isinstance(node.value, str):
        if node.value not in keypoints:
            node.fail(f"a keypoint name ({', '.join(keypoints) or 'none defined'}) or [x, y, z], "
                      f"got {node.value!r}")
        return np.array(keypoints[node.value], dtype=float)
    return node.vector("length", 3)


CRANK_RANGE = (0.05, 0.3)
"""Crank lengths (m) outside this range are warned about (children's to tall riders' cranks: 0.09..0.2 m)."""


def read_contacts(node, keypoints):
    """:class:`Contacts` from the ``contacts`` node (points as keypoint names or vectors)."""
    node.check_keys(required=("saddle", "bottom_bracket", "crank_length"), optional=("grips", "note"))
    grips = {}
    for name, g in node.get("grips", {}).items():
        if not (isinstance(name, str) and name.isidentifier()) or name == "none":
            node.fail(f"a grip name (a word such as {', '.join(HAND_POSITIONS)}; not 'none'), got {name!r}",
                      f"grips.{name}")
        grips[name] = _point(g, keypoints)
    bottom_bracket = _point(node["bottom_bracket"], keypoints)
    saddle, fit = None, None
    if isinstance(node["saddle"].value, dict):
        fit = _saddle_fit(node["saddle"], keypoints, bottom_bracket)
    else:
        saddle = _point(node["saddle"], keypoints)
    crank = node["crank_length"].number("length", positive=True)
    if not CRANK_RANGE[0] <= crank <= CRANK_RANGE[1]:
        warn(f"{node.source}: {node.key + '.' if node.key else ''}crank_length: {crank:.6g} m is outside "
             f"{CRANK_RANGE[0]:g}..{CRANK_RANGE[1]:g} m (bicycle cranks: 0.09..0.2 m; a bare number is in m, 170 mm "
             "is '170 mm'); computed as given")
    return Contacts(saddle, bottom_bracket, crank, grips, str(node.source), node.key, fit)


def _saddle_fit(node, keypoints, bottom_bracket):
    """(rule, direction, setback, lowest) of a fitted saddle: ``{fit, seat_tube_angle}`` or
    ``{fit, towards}``, optionally with ``setback`` and ``lowest``."""
    node.check_keys(required=("fit",), optional=("seat_tube_angle", "towards", "setback", "lowest", "note"))
    rule = node["fit"].string(tuple(SADDLE_RULES))
    setback = node["setback"].number("length") if node.has("setback") else 0.0
    lowest = node["lowest"].number("length", nonnegative=True) if node.has("lowest") else 0.0
    if node.has("seat_tube_angle") == node.has("towards"):
        node.fail("exactly one of seat_tube_angle (from horizontal) or towards (a keypoint on the seat tube)")
    if node.has("seat_tube_angle"):
        a = np.radians(node["seat_tube_angle"].number("angle", unit="deg"))
        if not 0 < a < np.pi:
            node.fail("a seat tube angle between 0 and 180 deg from horizontal", "seat_tube_angle")
        return rule, np.array([-np.cos(a), 0.0, -np.sin(a)]), setback, lowest
    d = _point(node["towards"], keypoints) - bottom_bracket
    d[1] = 0.0
    if not d[2] < 0:
        node.fail("a keypoint above the bottom bracket (up the seat tube)", "towards")
    return rule, d / np.linalg.norm(d), setback, lowest
