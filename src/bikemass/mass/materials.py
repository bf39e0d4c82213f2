"""Materials: Young's modulus E (Pa), Poisson's ratio nu, density (kg/m^3)."""

import os
from dataclasses import dataclass

from ..core.config import load_yaml
from ..core.gate import note_read
from ..core.paths import frames_dir


@dataclass(frozen=True)
class Material:
    """An isotropic material (SI)."""

    key: str
    name: str
    E: float
    nu: float
    density: float

    @property
    def G(self):
        """Shear modulus E / (2 (1 + nu)) (Pa)."""
        return self.E / (2 * (1 + self.nu))


_READ = {}
"""The last table read from each materials file, with the file's modification time and size."""


def load_materials(path=None):
    """``{key or alias: Material}`` from a materials YAML file (default ``frames/materials.yaml``).

    Read once per version of the file (its modification time and size: every bicycle a sweep
    builds asks for the table); a new dict each call."""
    path = os.fspath(path or frames_dir() / "materials.yaml")
    try:
        stat = os.stat(path)
        version = (stat.st_mtime_ns, stat.st_size)
    except OSError:
        version = None                                   # load_yaml names the problem
    cached = _READ.get(path)
    if version is None or cached is None or cached[0] != version:
        cached = _READ[path] = (version, read_materials(load_yaml(path)))
    else:
        note_read(path)
    return dict(cached[1])


def read_materials(root):
    """``{key or alias: Material}`` from a mapping node of material definitions."""
    table = {}
    for key, node in root.items():
        node.check_keys(required=("E", "nu", "density"), optional=("name", "aliases"))
        nu = node["nu"].number("dimensionless", positive=True)
        if nu >= 0.5:
            node.fail("a Poisson's ratio below 0.5", "nu")
        mat = Material(key, node.get("name", key).string(), node["E"].number("pressure", positive=True),
                       nu, node["density"].number("density", positive=True))
        table[key] = mat
        for alias in node.get("aliases", []).elements():
            table[alias.string()] = mat
    return table


def frame_label(stiffness):
    """What a stiffness choice is, in words for a title or a document: ``rigid frame``, ``<material> on
    the bicycle's tube sections`` (a material is a property of the tubes, not a frame) for a
    :class:`Material` or a material's key, else ``frame stiffness <the choice>`` (a file)."""
    if stiffness is None or (isinstance(stiffness, str) and stiffness in ("infinite", "rigid")):
        return "rigid frame"
    material = stiffness if isinstance(stiffness, Material) else load_materials().get(stiffness)
    if material is not None:
        return f"{material.name} on the bicycle's tube sections"
    return f"frame stiffness {stiffness}"

