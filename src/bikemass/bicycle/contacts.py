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
"""

from dataclasses import dataclass

import numpy as np

HAND_POSITIONS = ("tops", "hoods", "drops", "aero")
"""The usual grip names (``bikemass pose --hands``); a bicycle may name others."""


@dataclass(frozen=True, eq=False)
class Contacts:
    """Contact points (m, benchmark frame) and the file/key each came from (for error messages)."""

    saddle: np.ndarray
    bottom_bracket: np.ndarray
    crank_length: float
    grips: dict
    source: str
    key: str = "contacts"

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
    return node.vector(3)


def read_contacts(node, keypoints):
    """:class:`Contacts` from the ``contacts`` node (points as keypoint names or vectors)."""
    node.check_keys(required=("saddle", "bottom_bracket", "crank_length"), optional=("grips", "note"))
    grips = {}
    for name, g in node.get("grips", {}).items():
        if not (isinstance(name, str) and name.isidentifier()) or name == "none":
            node.fail(f"a grip name (a word such as {', '.join(HAND_POSITIONS)}; not 'none'), got {name!r}",
                      f"grips.{name}")
        grips[name] = _point(g, keypoints)
    return Contacts(_point(node["saddle"], keypoints), _point(node["bottom_bracket"], keypoints),
                    node["crank_length"].number(positive=True), grips, str(node.source), node.key)
