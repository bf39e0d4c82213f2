"""Names -> models: turns the BIKE / POSE / stiffness arguments of every command into objects.

``parameters(bike, rider, combine)`` gives the benchmark parameter set of a
bicycle (a shipped name, a bicycle YAML file or a benchmark parameter file),
optionally with a rider; ``stiffness(bike, which)`` gives the 2x2 rear-frame
stiffness S (N m/rad) or ``None`` for a rigid frame.
"""

import numpy as np

from .config import load_yaml
from .parameters import from_node, is_parameter_file
from .paths import frames_dir, resolve

COMBINE_CHOICES = ("exact", "thesis")
"""Rider + rear frame: 'exact' = parallel-axis theorem; 'thesis' = inertias added (Eq. 3.6)."""


def parameters(bike, rider=None, combine="exact"):
    """Benchmark parameter set for ``bike`` (+ ``rider``), see the module docstring."""
    node = load_yaml(resolve(bike, frames_dir(), "bicycle"))
    if is_parameter_file(node):
        if rider not in (None, "none"):
            node.fail("a bicycle without rider for a parameter file (its rear frame already has one)")
        return from_node(node)
    node.fail("a benchmark parameter file (bicycle YAML support comes with the bicycle model)")


def stiffness(bike, which):
    """2x2 S (N m/rad) named ``which`` for ``bike``: 'infinite' -> None, or a YAML file with key S."""
    if which in (None, "infinite", "rigid"):
        return None
    node = load_yaml(which)
    node.check_keys(required=("S",), optional=("units", "source", "name"))
    S = node["S"].matrix((2, 2))
    if not np.all(np.linalg.eigvalsh((S + S.T) / 2) > 0):
        node.fail("a positive definite 2x2 stiffness matrix (N m/rad)", "S")
    return S
