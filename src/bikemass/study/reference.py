"""The thesis's published tables (``reference/*.yaml``, checked transcriptions).

Read only by the comparison side of the study (report tables, match counts, the
explanation of misses), never by the code that computes a result.
"""

from functools import lru_cache

from ..core.gate import load_data
from ..core.paths import reference_dir


def _load(name):
    return _read(reference_dir() / f"{name}.yaml")


@lru_cache(maxsize=None)
def _read(path):
    """One parsed table file (kept by its path, so another data folder is read afresh)."""
    return load_data(path)


def stability_tables():
    """Tables 4-2..4-7 and 5-1..5-3: ``{"T4_2": {rider: [...]}, "T5_1": {material: {rider: [...]}}}``."""
    return _load("stability_tables")


def rider_tables():
    """Tables 3-2, 3-3, 3-4 (``table_3_4``: columns = the five poses)."""
    return _load("rider_tables")


def frame_tables():
    """Tables 3-5..3-12, 5-4, 5-5."""
    return _load("frame_tables")


def bicycle_tables():
    """Table 3-9 (``bicycles``), 3-4 (``riders``), 3-12 (``stiffness``) in SI."""
    return _load("bicycle_parameters")


def wobble_bands():
    """The published wobble frequency bands: ``[{"name", "low", "high"}]`` (Hz), ``wobble_bands.yaml``."""
    return _load("wobble_bands")["bands"]
