"""Mass properties: mass (kg), centre of mass (m) and inertia tensor (kg m^2).

The inertia tensor is about the centre of mass with axes parallel to the
benchmark frame (:mod:`bikemass.core.convention`); products of inertia are tensor
elements (``Ixz = -integral(x z dm)``).
"""

from dataclasses import dataclass

import numpy as np

from ..core.results import quantity


def _frozen(a, shape):
    a = np.array(a, dtype=float).reshape(shape)
    a.setflags(write=False)
    return a


def point_inertia(mass, offset):
    """Inertia of a point ``mass`` at ``offset`` about the origin: m (|d|^2 E - d d^T)."""
    d = np.asarray(offset, dtype=float)
    return mass * (d @ d * np.eye(3) - np.outer(d, d))


@dataclass(frozen=True, eq=False)
class MassProperties:
    """Immutable mass, centre of mass and central inertia tensor (SI, benchmark frame)."""

    mass: float = quantity("kg", "total mass")
    com: np.ndarray = quantity("m", "centre of mass (x, y, z), benchmark frame")
    inertia: np.ndarray = quantity("kg m^2", "3x3 inertia tensor about the centre of mass")

    def __post_init__(self):
        object.__setattr__(self, "mass", float(self.mass))
        object.__setattr__(self, "com", _frozen(self.com, 3))
        object.__setattr__(self, "inertia", _frozen(self.inertia, (3, 3)))

    # -- constructors -------------------------------------------------------
    @classmethod
    def point(cls, mass, position):
        """A point mass at ``position`` (no inertia about itself)."""
        return cls(mass, position, np.zeros((3, 3)))

    @classmethod
    def zero(cls):
        return cls(0.0, np.zeros(3), np.zeros((3, 3)))

    @classmethod
    def from_trimesh(cls, mesh, density):
        """Mass properties of a watertight trimesh mesh of uniform ``density`` (kg/m^3)."""
        props = mesh.mass_properties if density == 1.0 else _with_density(mesh, density)
        return cls(props["mass"], props["center_mass"], props["inertia"])

    # -- algebra ------------------------------------------------------------
    def __add__(self, other):
        """Combine two bodies with the parallel-axis theorem."""
        return combine((self, other))

    def inertia_about(self, point):
        """Inertia tensor about ``point`` (axes parallel to the frame), kg m^2."""
        return self.inertia + point_inertia(self.mass, self.com - np.asarray(point, dtype=float))

    def in_axes(self, axes):
        """Central inertia in the axes whose unit vectors are the columns of ``axes`` (R^T I R)."""
        R = np.asarray(axes, dtype=float)
        return R.T @ self.inertia @ R

    def transformed(self, rotation, translation=(0.0, 0.0, 0.0)):
        """The body moved rigidly: rotated by ``rotation`` (3x3) then translated (m)."""
        R = np.asarray(rotation, dtype=float)
        return MassProperties(self.mass, R @ self.com + translation, R @ self.inertia @ R.T)

    def principal(self):
        """Principal moments (ascending, kg m^2) and axes (columns)."""
        return np.linalg.eigh(self.inertia)

    def to_dict(self):
        """``{"mass": kg, "com": [x, y, z], "inertia": [[3x3]]}``."""
        return {"mass": self.mass, "com": self.com.tolist(), "inertia": self.inertia.tolist()}

    def __repr__(self):
        J = self.inertia
        return (f"MassProperties(mass={self.mass:.6g} kg, com={np.round(self.com, 6).tolist()} m, "
                f"Ixx={J[0, 0]:.6g}, Iyy={J[1, 1]:.6g}, Izz={J[2, 2]:.6g}, Ixz={J[0, 2]:.6g} kg m^2)")


def _with_density(mesh, density):
    mesh = mesh.copy()
    mesh.density = density
    return mesh.mass_properties


def combine(parts):
    """Total mass properties of ``parts`` (parallel-axis theorem)."""
    parts = list(parts)
    mass = sum(p.mass for p in parts)
    if mass <= 0:
        raise ValueError("cannot combine bodies of zero total mass")
    com = sum(p.mass * p.com for p in parts) / mass
    inertia = sum(p.inertia_about(com) for p in parts)
    return MassProperties(mass, com, inertia)


def combine_without_parallel_axis(parts):
    """The thesis's Eq. 3.4-3.6: masses summed, CoM mass-weighted, central inertias simply added.

    Physically wrong (it drops the m d^2 terms); kept to reproduce the thesis's tables.
    """
    parts = list(parts)
    mass = sum(p.mass for p in parts)
    com = sum(p.mass * p.com for p in parts) / mass
    return MassProperties(mass, com, sum(p.inertia for p in parts))
