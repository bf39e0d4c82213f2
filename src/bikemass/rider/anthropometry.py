"""Anthropometry: a body's segments (shape, sizes, mass) read from ``bodies/<name>.yaml``.

Each segment is a uniform solid whose local origin is the centre of its top plane
(the end nearest the head, shoulder, hip or knee), running along local +z, as in
Williams (2015), Table 3-2.  ``pair: true`` marks limbs present at +y and -y;
``mass`` is the mass of one segment (kg), so the density is mass / exact volume.
"""

from dataclasses import dataclass
from pathlib import Path

from ..core.config import load_yaml
from ..core.paths import available, bodies_dir, named_file
from ..mass.solids import Cylinder, TrapezoidalPrism

SHAPES = {
    "cylinder": (Cylinder, ("diameter", "length")),
    "trapezoidal_prism": (TrapezoidalPrism, ("depth", "width_top", "width_bottom", "length")),
}
"""Shape name -> (solid class, its size keys in constructor order, m)."""


@dataclass(frozen=True, eq=False)
class BodySegment:
    """One segment of an anthropometry: ``solid`` in its local frame, ``mass`` (kg) of one copy."""

    name: str
    solid: object
    mass: float
    pair: bool


@dataclass(frozen=True, eq=False)
class Anthropometry:
    """A named set of body segments read from ``source``."""

    name: str
    source: Path
    segments: dict


def load_anthropometry(path) -> Anthropometry:
    """Read an anthropometry YAML file (see ``bodies/thesis_rider.yaml``)."""
    node = load_yaml(path)
    node.check_keys(required=("name", "segments"), optional=("source", "joints"))
    segments = {}
    for name, seg in node["segments"].items():
        shape = seg["shape"].string(choices=tuple(SHAPES))
        cls, sizes = SHAPES[shape]
        seg.check_keys(required=("shape", "mass", *sizes), optional=("pair",))
        solid = cls(*(seg[k].number("length", positive=True) for k in sizes))
        pair = seg.get("pair", False).boolean()
        segments[name] = BodySegment(name, solid, seg["mass"].number("mass", positive=True), pair)
    if not segments:
        node.fail("at least one segment", "segments")
    return Anthropometry(node["name"].string(), Path(path), segments)


def find_anthropometry(body) -> Path:
    """Path of the anthropometry named by the pose's ``body`` node.

    A shipped name (``thesis_rider`` or ``thesis-rider``) is looked up in ``bodies/``;
    a name ending in ``.yaml`` is a file next to the pose file.
    """
    name = body.string()
    if name.endswith((".yaml", ".yml")):
        path = named_file(body)
        if path.is_file():
            return path
    else:
        for stem in {name, name.replace("-", "_")}:
            path = bodies_dir() / f"{stem}.yaml"
            if path.is_file():
                return path
    known = ", ".join(available(bodies_dir()))
    body.fail(f"a shipped anthropometry ({known}) or a .yaml file next to the pose, got {name!r}")
