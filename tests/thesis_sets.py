"""Test support: the thesis's stability parameter sets (Williams 2015, Chapters 4-5).

Built from reference/bicycle_parameters.yaml: the Table 3-9 bicycles, the
Table 3-4 riders and the Table 3-12 stiffnesses, combined as the thesis did
(Eq. 3.4-3.6): masses summed, centre of mass mass-weighted, inertias **added
without parallel-axis terms** (docs/thesis.md#rider-and-rear-frame-combined).  "No Rider" is the
frame alone; the "Benchmark" row is the Meijaard et al. (2007) bicycle.  Cargo
stiffness: the off-diagonals are symmetrised with the K_phidelta value, and the
titanium K_deltadelta erratum 2007.0 is read as 2207.0 (a one-digit slip; see
docs/thesis.md#table-3-12-errata).  The production combination lives with the
bicycle model; this module only reproduces the thesis's inputs for the tests.
"""

from pathlib import Path

import numpy as np
import yaml

from bikemass.models.parameters import BenchmarkParameters

REFERENCE = Path(__file__).parents[1] / "reference"
TABLES = yaml.safe_load((REFERENCE / "stability_tables.yaml").read_text())
_PARAMETERS = yaml.safe_load((REFERENCE / "bicycle_parameters.yaml").read_text())
RIDERS = ("No Hands", "Relaxed", "On Hoods", "Aerobars", "Aero Tuck")
CARGO_TITANIUM_KDD = 2207.0   # printed 2007.0 (Table 3-12 erratum)
G = 9.81


def frame(bicycle):
    """BenchmarkParameters of a Table 3-9 column ('Benchmark', 'Jamis', 'Cargo', 'Cargo load')."""
    b = _PARAMETERS["bicycles"][bicycle]
    return BenchmarkParameters(
        w=b["w"], c=b["t"], lam=np.pi / 2 - b["head_angle"], g=G,
        rR=b["R_rw"], mR=b["m_rw"], IRxx=b["Axx"], IRyy=b["Ayy"],
        xB=b["x_rf"], zB=b["z_rf"], mB=b["m_rf"],
        IBxx=b["Bxx"], IByy=b["Byy"], IBzz=b["Bzz"], IBxz=b["Bxz"],
        xH=b["x_ff"], zH=b["z_ff"], mH=b["m_ff"],
        IHxx=b["Cxx"], IHyy=b["Cyy"], IHzz=b["Czz"], IHxz=b["Cxz"],
        rF=b["R_fw"], mF=b["m_fw"], IFxx=b["Dxx"], IFyy=b["Dyy"])


def with_rider(p, rider):
    """Thesis Eq. 3.6: rider (Table 3-4) added to the rear frame, inertias simply summed."""
    r = _PARAMETERS["riders"][rider]
    m = p.mB + r["m"]
    return p.replace(
        mB=m, xB=(p.mB * p.xB + r["m"] * r["x"]) / m, zB=(p.mB * p.zB + r["m"] * r["z"]) / m,
        IBxx=p.IBxx + r["Ixx"], IByy=p.IByy + r["Iyy"], IBzz=p.IBzz + r["Izz"],
        IBxz=p.IBxz + r["Ixz"])


def thesis_set(bicycle, rider):
    """Parameters of one table row: ``rider`` is 'Benchmark', 'No Rider' or a Table 3-4 pose."""
    if rider == "Benchmark":
        return frame("Benchmark")
    p = frame(bicycle)
    return p if rider == "No Rider" else with_rider(p, rider)


def stiffness(bicycle, material):
    """Table 3-12 S (N m/rad) for 'Jamis'/'Cargo' and 'Infinite'/'Steel'/'Titanium'/'Aluminum'."""
    if material == "Infinite":
        return None
    S = np.array(_PARAMETERS["stiffness"][bicycle][material], dtype=float)
    if bicycle == "Cargo" and material == "Titanium":
        S[1, 1] = CARGO_TITANIUM_KDD
    S[1, 0] = S[0, 1]
    return S


CHAPTER4 = {  # table -> (bicycle of Table 3-9, marginal?)
    "T4_2": ("Jamis", False), "T4_3": ("Jamis", True),
    "T4_4": ("Cargo", False), "T4_5": ("Cargo", True),
    "T4_6": ("Cargo load", False), "T4_7": ("Cargo load", True),
}
CHAPTER5 = {"T5_1": "Jamis", "T5_2": "Cargo", "T5_3": "Cargo load"}
