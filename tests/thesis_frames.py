"""Test support: the thesis's Jamis rear-frame beam model as a :class:`bikemass.tubes.Structure`.

Built from tests/reference/frame_tables.yaml: Table 3-11 keypoints and Table 3-5
sections, with the seat- and chain-stay diameters swapped (seat stays 0.625 in,
chain stays 0.750 in): the thesis's FE results come out only that way (see
THESIS_NOTES.md, "Rear frames").
"""

from pathlib import Path

import numpy as np
import yaml

from bikemass.materials import load_materials
from bikemass.sections import RoundSection
from bikemass.tubes import Structure, Tube
from bikemass.units import INCH

REFERENCE = Path(__file__).parent / "reference" / "frame_tables.yaml"

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
