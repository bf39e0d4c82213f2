"""Names -> models: turns the BIKE / POSE / stiffness arguments of every command into objects.

``parameters(bike, rider, combine)`` gives the benchmark parameter set of a
bicycle (a shipped name, a bicycle YAML file or a benchmark parameter file),
optionally with a rider; ``stiffness(bike, which)`` gives the 2x2 rear-frame
stiffness S (N m/rad) or ``None`` for a rigid frame.
"""

import numpy as np

from .config import load_yaml
from .errors import InputError

COMBINE_CHOICES = ("exact", "thesis")
"""Rider + rear frame: 'exact' = parallel-axis theorem; 'thesis' = inertias added (Eq. 3.6)."""


def parameters(bike, rider=None, combine="exact", method="mesh"):
    """Benchmark parameter set for ``bike`` (+ ``rider``), see the module docstring;
    ``method`` mesh|exact: mass properties from trimesh meshes or closed-form solids."""
    from .bicycle import bicycle_parameters
    return bicycle_parameters(bicycle(bike), load_rider(rider), combine, method)


def bicycle(bike):
    """The :class:`~bikemass.bicycle.Bicycle` named ``bike`` (shipped name, YAML or parameter file)."""
    from .bicycle import load_bicycle
    return load_bicycle(bike)


def load_rider(pose):
    """The rider in ``pose`` (shipped pose name or pose file), or ``None`` for None/'none'."""
    if pose in (None, "none"):
        return None
    from .rider import load_rider as load
    return load(pose)


STIFFNESS_SOURCES = ("auto", "published", "computed")
"""Where a material's S comes from: published values if the bicycle carries them, else the
beam FE of its rear frame ('auto'); or only one of the two."""


def stiffness(bike, which, source="auto", procedure="condensed"):
    """2x2 S (N m/rad) named ``which`` for ``bike``: 'infinite' -> None, a material name
    (published ``stiffness:`` of the bicycle, or computed by the beam FE of its rear-frame
    ``structure`` with ``procedure`` condensed|thesis, see ``source``), or a YAML file with key S."""
    if source not in STIFFNESS_SOURCES:
        raise ValueError(f"source must be one of {STIFFNESS_SOURCES}, got {source!r}")
    if which in (None, "infinite", "rigid"):
        return None
    from .materials import load_materials
    materials = load_materials()
    if which in materials:
        model = bicycle(bike)
        S = None if source == "computed" else model.published_stiffness(materials[which])
        if S is None and source != "published" and model.structure is not None:
            from .fe import equivalent_stiffness
            S = equivalent_stiffness(model.structure, materials[which], procedure)
        if S is None:
            raise InputError(model.source, "stiffness", f"a {source} stiffness for {which} "
                             "(no published stiffness and no rear-frame structure for the beam model)")
        return S
    node = load_yaml(which)
    node.check_keys(required=("S",), optional=("units", "source", "name"))
    S = node["S"].matrix((2, 2))
    if not np.all(np.linalg.eigvalsh((S + S.T) / 2) > 0):
        node.fail("a positive definite 2x2 stiffness matrix (N m/rad)", "S")
    return S
