"""Beam mesh of a rear-frame :class:`~bikemass.mass.tubes.Structure`.

Every tube becomes ``ceil(L / element_size)`` equal two-node elements (one if
``element_size`` is None); tubes meeting at a keypoint share its node (rigid
centre-line joints, as the thesis's keypoint model).  Keypoint nodes come
first, in the order of ``structure.keypoints``; interior nodes follow tube by tube.
"""

from dataclasses import dataclass, replace

import numpy as np

from ..core.errors import InputError
from ..core.frozen import frozen_fields
from ..mass.materials import load_materials
from .properties import beam_properties



@dataclass(frozen=True)
class FrameMesh:
    """Nodes (N, 3) in m, elements (n, 2) node indices, and per-element section/material arrays."""

    nodes: np.ndarray
    elements: np.ndarray
    tube_index: np.ndarray
    """Index into ``structure.tubes`` of each element."""
    properties: dict
    """Per-element arrays: E, G, density, area, I, J, polar, kappa (SI)."""
    keypoint_nodes: dict
    """``{keypoint name: node index}``."""
    structure: object

    def __post_init__(self):           # read-only arrays and mappings (a mode result holds the mesh)
        frozen_fields(self, "nodes", "elements", "tube_index", "properties", "keypoint_nodes")

    @property
    def n_dof(self):
        return 6 * len(self.nodes)


def with_material(structure, material):
    """``structure`` with every tube's material replaced by ``material`` (geometry unchanged)."""
    if material is None:
        return structure
    return replace(structure, tubes=tuple(replace(t, material=material) for t in structure.tubes))


def resolve_material(name):
    """A shipped material by key or alias (steel, titanium, aluminum, ...) or a one-material YAML file.

    A file uses the format of ``frames/materials.yaml``: ``key: {E, nu, density}``.
    """
    shipped = load_materials()
    if name in shipped:
        return shipped[name]
    if name.endswith((".yaml", ".yml")):
        table = load_materials(name)
        if len({id(m) for m in table.values()}) != 1:
            raise InputError(name, "(top)", "exactly one material (key: {E, nu, density})")
        return next(iter(table.values()))
    raise InputError(name, "(material)", "a material YAML file or one of: " + ", ".join(sorted(shipped)))


def _check(structure):
    names = set(structure.keypoints)
    for tube in structure.tubes:
        for key, point in ((tube.start_key, tube.start), (tube.end_key, tube.end)):
            if key not in names:
                raise ValueError(f"tube {tube.name!r}: keypoint {key!r} is not in the structure")
            if not np.allclose(structure.keypoints[key], point, atol=1e-9):
                raise ValueError(f"tube {tube.name!r}: end {key!r} does not sit on its keypoint")
        if tube.start_key == tube.end_key:
            raise ValueError(f"tube {tube.name!r} starts and ends at keypoint {tube.start_key!r}")
    for key in tuple(structure.dropouts) + tuple(structure.head_tube):
        if key not in names:
            raise ValueError(f"support keypoint {key!r} is not in the structure")


def _element_count(length, element_size):
    return 1 if element_size is None else max(1, int(np.ceil(length / element_size - 1e-9)))


def element_count(structure, element_size=None):
    """Number of beam elements :func:`build_mesh` makes of ``structure`` at ``element_size`` (m)."""
    return sum(_element_count(t.length, element_size) for t in structure.tubes)


def build_mesh(structure, material=None, element_size=None):
    """:class:`FrameMesh` of ``structure`` (optionally with ``material`` for all tubes)."""
    structure = with_material(structure, material)
    _check(structure)
    names = list(structure.keypoints)
    keypoint_nodes = {name: i for i, name in enumerate(names)}
    nodes = [np.asarray(structure.keypoints[name], float) for name in names]
    elements, tube_index, props = [], [], []
    for t, tube in enumerate(structure.tubes):
        count = _element_count(tube.length, element_size)
        a, b = keypoint_nodes[tube.start_key], keypoint_nodes[tube.end_key]
        frac = np.arange(1, count)[:, None] / count
        first = len(nodes)
        nodes.extend(tube.start + frac * (tube.end - tube.start))
        chain = np.r_[a, np.arange(first, first + count - 1), b]
        elements.append(np.column_stack([chain[:-1], chain[1:]]))
        tube_index.append(np.full(count, t))
        mat = tube.material
        p = beam_properties(tube.section, mat.nu)
        props.append(np.tile([mat.E, mat.G, mat.density, p.area, p.I, p.J, p.polar, p.kappa], (count, 1)))
    table = np.concatenate(props)
    keys = ("E", "G", "density", "area", "I", "J", "polar", "kappa")
    return FrameMesh(np.array(nodes), np.concatenate(elements), np.concatenate(tube_index),
                     {k: table[:, i] for i, k in enumerate(keys)}, keypoint_nodes, structure)
