"""The Cargo rear frame: Table 3-12 (S) and Table 5-5 (frequencies) with a reconstructed connectivity.

The thesis's figure of this model is missing, so tests/thesis_frames.py
reconstructs the members from the 39 keypoints (docs/fe.md lists the assumptions
and the per-entry errors).  What can be tested strictly is what does not depend
on the reconstruction (the material scaling of S, which exposes the Table 3-12
erratum); the rest is a regression guard at the accuracy the reconstruction
reaches (S within 13 %, frequencies median 6 %, worst 19 %).
"""

import numpy as np
import pytest

from bikemass.fe import equivalent_stiffness, frame_modes
from thesis_frames import MATERIALS, cargo_structure, tables

TABLES = tables()
BCS = {"free": "free", "fix-rear": "fix_rear", "fix-head": "fix_head", "fix-both": "fix_both"}
TITANIUM_KDD_CORRECTED = 2207.0
"""docs/thesis.md#table-3-12-errata: Table 3-12 prints Cargo titanium K_dd = 2007.0; it must be ~2207."""


@pytest.fixture(scope="module")
def stiffness():
    return {m: equivalent_stiffness(cargo_structure(m), procedure="thesis") for m in MATERIALS}


def test_material_scaling_of_S_matches_table_and_shows_the_titanium_erratum(stiffness):
    # S / S_steel depends on E and nu only, hardly on the connectivity: compare it with the table's.
    printed = {m: np.array(TABLES["table_3_12"]["cargo"][m]) for m in MATERIALS}
    for m in ("titanium", "aluminum"):
        ours = stiffness[m] / stiffness["steel"]
        theirs = printed[m] / printed["steel"]
        if m == "titanium":
            assert abs(ours[1, 1] / theirs[1, 1] - 1) > 0.08            # 2007.0 does not fit ...
            theirs[1, 1] = TITANIUM_KDD_CORRECTED / printed["steel"][1, 1]  # ... 2207 does
        np.testing.assert_allclose(ours, theirs, rtol=0.005)


def test_stiffness_near_table_3_12(stiffness):
    for m in MATERIALS:
        printed = np.array(TABLES["table_3_12"]["cargo"][m])
        if m == "titanium":
            printed[1, 1] = TITANIUM_KDD_CORRECTED
        error = stiffness[m] / printed - 1
        assert np.all(np.abs(error) < 0.13), (m, error)


def test_frequencies_near_table_5_5():
    errors = []
    for m, column in MATERIALS.items():
        structure = cargo_structure(m)
        for bc, key in BCS.items():
            reference = np.array(TABLES["table_5_5_cargo"][key])[:, column]
            errors.extend(frame_modes(structure, bc, len(reference)).frequencies_hz / reference - 1)
    errors = np.abs(errors)
    assert len(errors) == 102
    assert np.median(errors) < 0.07 and errors.max() < 0.20
