"""Rear-frame beam finite elements: equivalent stiffness S and natural frequencies.

``equivalent_stiffness(structure, material, procedure)`` -> 2x2 S (N m/rad);
``frame_modes(structure, bc, count, material, element_size)`` -> :class:`Modes` (Hz).
"""

from .boundary import BOUNDARY_CONDITIONS
from .model import DEFAULT_ELEMENT_SIZE, build_mesh, resolve_material, with_material
from .modes import Modes, frame_modes, solve_modes
from .stiffness import PROCEDURES, equivalent_stiffness

__all__ = ["BOUNDARY_CONDITIONS", "DEFAULT_ELEMENT_SIZE", "PROCEDURES", "Modes", "build_mesh",
           "equivalent_stiffness", "frame_modes", "resolve_material", "solve_modes", "with_material"]
