"""A body from a person's height, mass and sex: the thesis's segment kinds sized by
stature fractions and weighed by de Leva's (1996) mass fractions.

``body: {height: 1.80 m, mass: 75 kg, sex: male}`` (inline in a pose, or as the keys of
a file under ``bodies/``).  Tables: ``bodies/tables/de_leva_1996.yaml`` (mass percentages,
merged into head, torso, upper arm, lower arm, thigh, lower leg) and
``bodies/tables/stature.yaml`` (Drillis & Contini length fractions, Dempster densities).

Segments (lengths in units of the height H, defaults):

* head: top of the head to the shoulders, ``H (1 - shoulder_height)``, a cylinder;
* torso: shoulders to hip joints, ``H (shoulder_height - hip_height)``, a trapezoidal prism
  as wide as the hips at the bottom and ``shoulder_width - 2 x upper-arm diameter`` at the
  top (the thesis's rule), its depth from its mass and density;
* upper arm: shoulder to elbow; lower arm: elbow to the middle of the hand (the grip),
  ``forearm + hand / 2``; thigh: hip to knee joint; lower leg: knee to the floor.

Limb diameters follow from mass / (density x length), or from an optional girth
(``girths: {thigh: 56 cm}``, circumference).  Optional measured lengths override the
fractions: ``inseam`` (floor to crotch: hip-joint height = inseam + thigh radius),
``arm_length`` (shoulder joint to the centre of the closed hand, split in the fractions'
ratio) and ``shoulder_width`` (across the shoulders).
"""

from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from ..core.config import load_yaml
from ..core.paths import bodies_dir
from ..mass.solids import Cylinder, TrapezoidalPrism
from .anthropometry import Anthropometry, BodySegment

SEXES = ("male", "female")
SPEC_KEYS = ("height", "mass", "sex")
OPTIONAL_KEYS = ("name", "inseam", "arm_length", "shoulder_width", "girths", "density", "source", "note")
CYLINDERS = ("head", "upper_arm", "lower_arm", "thigh", "lower_leg")
DENSITY_RANGE = (700.0, 1500.0)
"""Plausible tissue densities (kg/m^3): a density or a girth implying one outside is refused."""


@dataclass(frozen=True)
class Tables:
    """Merged mass fractions ``{sex: {kind: fraction of body mass}}`` (one limb of a pair),
    length ``fractions`` of height, ``densities`` (kg/m^3) and the paired kinds."""

    mass: dict
    fractions: dict
    densities: dict
    pairs: tuple


@lru_cache(maxsize=1)
def tables() -> Tables:
    """The shipped tables, de Leva's columns scaled to sum to exactly 100 %."""
    leva = load_yaml(bodies_dir() / "tables" / "de_leva_1996.yaml")
    stature = load_yaml(bodies_dir() / "tables" / "stature.yaml")
    merge = {k: [s.string() for s in v.elements()] for k, v in leva["merge"].items()}
    pairs = tuple(p.string() for p in leva["pairs"].elements())
    mass = {}
    for sex, column in leva["percent"].items():
        pct = {k: v.number("dimensionless", positive=True) for k, v in column.items()}
        merged = {kind: sum(pct[s] for s in parts) for kind, parts in merge.items()}
        total = sum(m * (2 if kind in pairs else 1) for kind, m in merged.items())
        mass[sex] = {kind: m / total for kind, m in merged.items()}
    fractions = {k: v.number("dimensionless", positive=True) for k, v in stature["fractions"].items()}
    densities = {k: v.number("density", positive=True) for k, v in stature["densities"].items()}
    return Tables(mass, fractions, densities, pairs)


@dataclass(frozen=True)
class StatureBody:
    """Segment ``masses`` (kg, one limb), ``lengths`` and ``diameters`` (m), torso widths and
    depth (m), joint offsets (m) of a body built from height and mass."""

    masses: dict
    lengths: dict
    diameters: dict
    torso: dict
    shoulder_y: float
    hip_y: float


def _cylinder_diameter(mass, density, length):
    return 2.0 * np.sqrt(mass / (density * np.pi * length))


def build(height, mass, sex, inseam=None, arm_length=None, shoulder_width=None, girths=None,
          density=None):
    """:class:`StatureBody` of a person (m, kg; ``sex`` male|female); see the module docstring.

    ``density`` (kg/m^3) replaces the per-segment densities; ``girths`` = ``{kind: m}``."""
    t = tables()
    f, girths = t.fractions, dict(girths or {})
    dens = {k: density or v for k, v in t.densities.items()}
    masses = {k: mass * share for k, share in t.mass[sex].items()}
    lengths = {"head": height * (1.0 - f["shoulder_height"]),
               "upper_arm": height * f["upper_arm"],
               "lower_arm": height * (f["forearm"] + f["hand"] / 2)}
    if arm_length is not None:
        scale = arm_length / (lengths["upper_arm"] + lengths["lower_arm"])
        lengths["upper_arm"] *= scale
        lengths["lower_arm"] *= scale
    leg_split = (f["hip_height"] - f["knee_height"]) / f["hip_height"]
    hip_height = height * f["hip_height"]
    for _ in range(50 if inseam is not None else 1):
        lengths["thigh"] = hip_height * leg_split
        lengths["lower_leg"] = hip_height - lengths["thigh"]
        d_thigh = girths["thigh"] / np.pi if "thigh" in girths else \
            _cylinder_diameter(masses["thigh"], dens["thigh"], lengths["thigh"])
        if inseam is not None:
            hip_height = inseam + d_thigh / 2
    lengths["torso"] = height * f["shoulder_height"] - hip_height
    if not lengths["torso"] > 0:
        raise ValueError(f"an inseam below the shoulder height (hip joints at {hip_height:.3f} m, "
                         f"shoulders at {height * f['shoulder_height']:.3f} m)")
    diameters = {k: girths[k] / np.pi if k in girths else _cylinder_diameter(masses[k], dens[k], lengths[k])
                 for k in CYLINDERS}
    across = shoulder_width if shoulder_width is not None else height * f["shoulder_width"]
    width_top = across - 2 * diameters["upper_arm"]
    if not width_top > 0:
        raise ValueError(f"a shoulder width above twice the upper-arm diameter "
                         f"({2 * diameters['upper_arm']:.3f} m), got {across:.3f} m")
    width_bottom = height * f["hip_width"]
    depth = masses["torso"] / (dens["torso"] * lengths["torso"] * (width_top + width_bottom) / 2)
    torso = {"depth": depth, "width_top": width_top, "width_bottom": width_bottom}
    r_thigh = diameters["thigh"] / 2
    return StatureBody(masses, lengths, diameters, torso, across / 2 - diameters["upper_arm"] / 2,
                       max(width_bottom / 2 - r_thigh, r_thigh))


def anthropometry(b: StatureBody, name, source) -> Anthropometry:
    """The :class:`Anthropometry` (uniform solids) of a :class:`StatureBody`."""
    pairs = tables().pairs
    segments = {"head": Cylinder(b.diameters["head"], b.lengths["head"]),
                "torso": TrapezoidalPrism(b.torso["depth"], b.torso["width_top"], b.torso["width_bottom"],
                                          b.lengths["torso"])}
    for kind in ("upper_arm", "lower_arm", "thigh", "lower_leg"):
        segments[kind] = Cylinder(b.diameters[kind], b.lengths[kind])
    return Anthropometry(name, Path(source), {k: BodySegment(k, s, b.masses[k], k in pairs)
                                              for k, s in segments.items()})


def joints(b: StatureBody):
    """Chain attachment points in the torso's local frame (m): neck, shoulder, hip; seat depth."""
    return {"neck": np.zeros(3), "shoulder": np.array([0.0, b.shoulder_y, 0.0]),
            "hip": np.array([0.0, b.hip_y, b.lengths["torso"]]), "seat": b.diameters["thigh"] / 2}


BMI_RANGE = (10.0, 100.0)
"""Body-mass index (kg/m^2) a body from height and mass must have: beyond every recorded adult
and child on both sides (a mass typed in grams, or a height in feet, lands outside)."""
LENGTH_RANGES = {"arm_length": (0.25, 0.55), "shoulder_width": (0.15, 0.40)}
"""Measured lengths as fractions of the height they must lie between (the stature table's
typical values are about 0.39 and 0.26)."""


def read_spec(node):
    """(name, :class:`StatureBody`) of a ``{height, mass, sex, ...}`` node; bad input -> InputError."""
    node.check_keys(required=SPEC_KEYS, optional=OPTIONAL_KEYS)
    height, mass = node["height"].number("length", positive=True), node["mass"].number("mass", positive=True)
    if not 0.5 <= height <= 2.6:
        node.fail(f"a standing height between 0.5 and 2.6 m, got {node['height'].value!r}", "height")
    sex = node["sex"].string(SEXES)
    optional = {k: node[k].number("density" if k == "density" else "length", positive=True)
                for k in ("inseam", "arm_length", "shoulder_width", "density")
                if node.has(k)}
    girths = {}
    if node.has("girths"):
        g = node["girths"]
        g.check_keys(optional=CYLINDERS)
        girths = {k: v.number("length", positive=True) for k, v in g.items()}
    if not BMI_RANGE[0] <= mass / height ** 2 <= BMI_RANGE[1]:
        node.fail(f"a body mass for a {height:.2f} m person between {BMI_RANGE[0] * height ** 2:.0f} and "
                  f"{BMI_RANGE[1] * height ** 2:.0f} kg (body-mass index {BMI_RANGE[0]:g} to {BMI_RANGE[1]:g} "
                  f"kg/m^2), got {node['mass'].value!r}", "mass")
    for key, (low, high) in LENGTH_RANGES.items():
        if key in optional and not low * height <= optional[key] <= high * height:
            node.fail(f"{key.replace('_', ' ')} between {low:g} and {high:g} times the height ({low * height:.3f} to "
                      f"{high * height:.3f} m), got {node[key].value!r}", key)
    if "inseam" in optional and not optional["inseam"] < height * tables().fractions["shoulder_height"]:
        node.fail(f"an inseam below the shoulder height, got {node['inseam'].value!r}", "inseam")
    lo, hi = DENSITY_RANGE
    if "density" in optional and not lo <= optional["density"] <= hi:
        node.fail(f"a body density between {lo:g} and {hi:g} kg/m^3, got {node['density'].value!r}", "density")
    try:
        body = build(height, mass, sex, girths=girths, **optional)
    except ValueError as exc:
        node.fail(str(exc))
    for kind in girths:
        d = body.diameters[kind]
        implied = body.masses[kind] / (np.pi * d * d / 4 * body.lengths[kind])
        if not lo <= implied <= hi:
            node.fail(f"a girth giving a density between {lo:g} and {hi:g} kg/m^3 for the segment's "
                      f"de Leva mass ({body.masses[kind]:.2f} kg over {body.lengths[kind]:.3f} m), got "
                      f"{node['girths'][kind].value!r}: {implied:.0f} kg/m^3", f"girths.{kind}")
    default = f"{sex} {height:.2f} m {mass:g} kg"
    return node.get("name", default).string(), body
