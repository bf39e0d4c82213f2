"""Rear-frame beam finite elements: equivalent stiffness S and natural frequencies.

``equivalent_stiffness(structure, material, procedure)`` -> 2x2 S (N m/rad);
``frame_modes(structure, bc, count, material, element_size)`` -> :class:`Modes` (Hz);
``frame_twist`` and ``fork_bending`` -> :class:`Compliance` (the flexible model's reduced coordinates).
The names are imported on first use: ``bikemass.fe.defaults`` alone does not load scipy.
"""

import importlib

from ..core.choices import Procedure, Support
from .defaults import DEFAULT_ELEMENT_SIZE

BOUNDARY_CONDITIONS = Support.values()
PROCEDURES = Procedure.values()

_LAZY = {"build_mesh": "model", "resolve_material": "model", "with_material": "model",
         "Modes": "modes", "frame_modes": "modes", "solve_modes": "modes",
         "equivalent_stiffness": "stiffness", "Compliance": "compliance", "frame_twist": "twist",
         "fork_structure": "fork", "fork_bending": "fork"}

__all__ = ["BOUNDARY_CONDITIONS", "DEFAULT_ELEMENT_SIZE", "PROCEDURES", *_LAZY]


def __getattr__(name):
    if name not in _LAZY:
        raise AttributeError(f"module 'bikemass.fe' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"{__name__}.{_LAZY[name]}"), name)
    globals()[name] = value
    return value
