"""Test support: the thesis's rear-frame beam models as :class:`bikemass.mass.tubes.Structure` objects.

Jamis: built from reference/frame_tables.yaml: Table 3-11 keypoints and Table 3-5
sections, with the seat- and chain-stay diameters swapped (seat stays 0.625 in,
chain stays 0.750 in): the thesis's FE results come out only that way (see
docs/thesis.md#seat-and-chain-stays-swapped).

Cargo: Table 3-10 keypoints with a connectivity reconstructed from geometry (the
thesis's figure is missing); see :data:`CARGO_MEMBERS` and docs/fe.md.
"""

from pathlib import Path

import numpy as np
import yaml

from bikemass.mass.materials import load_materials
from bikemass.mass.sections import RoundSection, SquareSection
from bikemass.mass.tubes import Structure, Tube
from bikemass.core.units import INCH

REFERENCE = Path(__file__).parents[1] / "reference" / "frame_tables.yaml"

JAMIS_MEMBERS = (  # name, from, to, section key of Table 3-5
    ("head_tube", "4", "5", "head_tube"),
    ("down_tube", "5", "1", "down_tube"),
    ("seat_tube", "1", "2", "seat_tube"),
    ("seat_tube_extension", "2", "3", "seat_tube"),
    ("top_tube", "4", "2", "top_tube"),
    ("seat_stay_left", "2", "6", "seat_stays"),
    ("seat_stay_right", "2", "7", "seat_stays"),
    ("chain_stay_left", "1", "6", "chain_stays"),
    ("chain_stay_right", "1", "7", "chain_stays"),
)
STAY_SWAP = {"seat_stays": "chain_stays", "chain_stays": "seat_stays"}

MATERIALS = {"steel": 0, "titanium": 1, "aluminum": 2}
"""Material name -> column of Tables 3-12 / 5-4 / 5-5."""


def tables():
    return yaml.safe_load(REFERENCE.read_text())


def jamis_structure(material="steel"):
    """The Jamis rear frame of the thesis FE model, all tubes of ``material``."""
    data = tables()
    keypoints = {str(int(row[0])): np.array(row[1:4], float)
                 for row in data["table_3_11_jamis_keypoints"]}
    sections = data["table_3_5"]["jamis_sections"]
    mat = load_materials()[material]
    tubes = []
    for name, a, b, key in JAMIS_MEMBERS:
        od, wall = sections[STAY_SWAP.get(key, key)]
        tubes.append(Tube(name, a, b, keypoints[a], keypoints[b],
                          RoundSection(od * INCH, wall * INCH), mat, "rear_frame"))
    return Structure(tuple(tubes), ("6", "7"), ("4", "5"), keypoints)


def _chain(keys, section):
    return tuple((a, b, section) for a, b in zip(keys[:-1], keys[1:]))


CARGO_MEMBERS = (
    # Rear triangle: seat tube 3-33-5 (no Cargo seat-tube row in Table 3-5: taken as the 1.5 in
    # class), seat post 5-4 (collinear with it), top tube 5-6-7, chain stays to the bottom
    # bracket 3, seat stays to 34/35 (on the seat-tube wall, y = +-20 mm) bridged to 33.
    *_chain(["3", "33", "5"], "steering_tube"),
    ("5", "4", "seat_post"),
    *_chain(["5", "6", "7"], "top_tube"),
    ("6", "9", "top_tube"), ("9", "11", "top_tube"),            # down tube + brace (assumed)
    ("1", "3", "rear_stays_hoops_linkage"), ("2", "3", "rear_stays_hoops_linkage"),
    ("1", "34", "rear_stays_hoops_linkage"), ("2", "35", "rear_stays_hoops_linkage"),
    ("33", "34", "rear_stays_hoops_linkage"), ("33", "35", "rear_stays_hoops_linkage"),
    # Outer steering tube at x = 0.851 (vertical; the handlebar shaft inside it is front frame),
    # bottom tube from the bottom bracket, two bottom tubes forward under the load platform.
    *_chain(["12", "10", "13", "9", "19", "7"], "steering_tube"),
    *_chain(["3", "11", "10"], "steering_tube"),
    ("12", "14", "steering_tube"),
    *_chain(["13", "24", "25", "15"], "steering_tube"),
    ("14", "15", "steering_tube"),
    # Wheel arch (straight through 32) to the head tube 16 (bottom) - 18 - 17 (top).
    *_chain(["14", "32", "16"], "steering_tube"),
    *_chain(["16", "18", "17"], "steering_tube"),
    # Square-tube load platform at z = -0.2667 on the bottom tube (24, 25), front struts to 16.
    *_chain(["20", "24", "21"], "storage_frame_square"),
    *_chain(["22", "30", "25", "31", "23"], "storage_frame_square"),
    ("20", "22", "storage_frame_square"), ("21", "23", "storage_frame_square"),
    ("30", "16", "rear_stays_hoops_linkage"), ("31", "16", "rear_stays_hoops_linkage"),
)
"""Cargo rear-frame members (from, to, Table 3-5 section key): the best of the connectivities
tried (docs/fe.md).  Keypoints 26-29 and 36-39 (hoops, linkage) and 8 (handlebar) are
front-frame parts and are left out."""


def cargo_structure(material="steel"):
    """The Cargo rear frame as reconstructed here (see :data:`CARGO_MEMBERS`), all of ``material``."""
    data = tables()
    points = {str(int(row[0])): np.array(row[1:4], float) for row in data["table_3_10_cargo_keypoints"]}
    sections = data["table_3_5"]["cargo_sections"]
    mat = load_materials()[material]
    tubes, used = [], {}
    for a, b, key in CARGO_MEMBERS:
        od, wall = sections[key]
        section = (SquareSection(od * INCH, wall * INCH) if key == "storage_frame_square"
                   else RoundSection(od * INCH, wall * INCH))
        tubes.append(Tube(f"{a}-{b}", a, b, points[a], points[b], section, mat, "rear_frame"))
        used.update({a: points[a], b: points[b]})
    return Structure(tuple(tubes), ("1", "2"), ("17", "16"), used)
