"""The rear frames' beam models: S by both procedures and the natural frequencies (default
element size), per material.

Computed once for the study from the geometry bicycles' rear-frame structures
(``jamis``, ``cargo``); the same S (condensed) feeds the corrected stability run.
"""

from dataclasses import dataclass

from ..fe import BOUNDARY_CONDITIONS, DEFAULT_ELEMENT_SIZE, PROCEDURES, build_mesh, solve_modes

FRAMES = ("jamis", "cargo")
MATERIALS = ("steel", "titanium", "aluminum")
MODE_COUNT = {"free": 4, "fix-rear": 10, "fix-head": 10, "fix-both": 10}
"""Modes per boundary condition, as Tables 5-4 and 5-5 list them (free-free: the first four elastic)."""


@dataclass(frozen=True)
class FrameResults:
    """``S[procedure]`` (2x2, N m/rad) and ``frequencies[bc]`` (Hz) of one frame in one material."""

    S: dict
    frequencies: dict


def frame_results(inputs):
    """``{(frame, material): FrameResults}`` for :data:`FRAMES` x :data:`MATERIALS`."""
    out = {}
    for frame in FRAMES:
        structure = inputs.bicycle(frame).structure
        for name in MATERIALS:
            S = {p: inputs.frame_stiffness(frame, name, p) for p in PROCEDURES}
            mesh = build_mesh(structure, inputs.material(name), DEFAULT_ELEMENT_SIZE)
            freqs = {bc: solve_modes(mesh, bc, MODE_COUNT[bc]).frequencies_hz for bc in BOUNDARY_CONDITIONS}
            out[frame, name] = FrameResults(S, freqs)
    return out
