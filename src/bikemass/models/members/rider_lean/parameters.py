"""The leaning rider's parameters: the bicycle without the rider's upper body, the upper body, the hip joint.

The rider is split at the hips (Moore 2012, PhD thesis UC Davis, ch. "Extensions of the Whipple
model", section "Leaning rider extension"): the benchmark rear frame B keeps the bicycle's rear frame,
the legs and the pelvis; the upper body (torso, head, and the arms unless they hold the bars and move
with the front frame) leans about a longitudinal axis through the hip joints against a torsional
spring and damper.

The defaults of the joint, ``k = 128 N m/rad`` and ``c = 50 N m s/rad``, are de Lorenzo & Hubbard's
(1996, unpublished) estimates as quoted by Moore (2012, same section, text before his Fig. 4.16, the
values with which his leaning rider is stable between about 5 and 7 m/s on the Batavus Browser);
``k = c = 0`` is his free lean joint (Fig. 4.15).  An upper body of mass ``m`` with its centre of mass
``h`` above the hip axis is statically unstable on the joint alone (bicycle held) when
``k < m g h``: :attr:`RiderLeanParameters.gravity_stiffness` gives ``m g h`` to compare.
"""

import dataclasses
import math
from dataclasses import dataclass, field, fields
from typing import ClassVar

import numpy as np

from ....core.errors import InputError
from ....mass.inertia import MassProperties, combine
from ...parameters import NAMES, BenchmarkParameters
from ...plausibility import inertia_problem, warn


def unit(symbol, description):
    """A dataclass field's metadata: its SI unit and meaning."""
    return field(metadata={"unit": symbol, "description": description})


def units(cls):
    """``{field: SI unit}`` of a dataclass with :func:`unit` metadata."""
    return {f.name: f.metadata["unit"] for f in fields(cls) if "unit" in f.metadata}


def _checked(value, what, positive=(), nonnegative=()):
    """Every field a finite float (``positive`` or ``nonnegative`` where asked); InputError otherwise."""
    for f in fields(value):
        x = getattr(value, f.name)
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
            raise InputError(what, f.name, f"a finite number ({f.metadata['unit']}), got {x!r}")
        if (f.name in positive and not x > 0) or (f.name in nonnegative and x < 0):
            raise InputError(what, f.name, f"a {'positive' if f.name in positive else 'non-negative'} number "
                             f"({f.metadata['unit']}), got {x!r}")
        object.__setattr__(value, f.name, float(x))


LEAN_STIFFNESS = 128.0
"""De Lorenzo & Hubbard (1996) via Moore (2012): passive lean stiffness, N m/rad."""
LEAN_DAMPING = 50.0
"""De Lorenzo & Hubbard (1996) via Moore (2012): passive lean damping, N m s/rad."""


UPPER_MASS = (5.0, 300.0)
"""Upper-body masses (kg) outside this range are warned about."""
UPPER_REACH = 3.0
"""An upper body's centre of mass or hip axis more than this (m) above the ground or from the rear contact, or
below the ground, is warned about."""


@dataclass(frozen=True)
class UpperBody:
    """The leaning part of the rider, upright, in the benchmark frame (x forward, z down, origin at
    the rear contact); inertia about its own centre of mass, products as tensor elements."""

    mass: float = unit("kg", "mass")
    x: float = unit("m", "centre of mass x")
    z: float = unit("m", "centre of mass z (negative: above the ground)")
    Ixx: float = unit("kg m^2", "Ixx about the centre of mass")
    Iyy: float = unit("kg m^2", "Iyy about the centre of mass")
    Izz: float = unit("kg m^2", "Izz about the centre of mass")
    Ixz: float = unit("kg m^2", "Ixz (tensor element) about the centre of mass")
    hip_z: float = unit("m", "z of the lean (hip) axis, a line parallel to x (negative: above the ground)")

    def __post_init__(self):
        _checked(self, "upper body", positive=("mass", "Ixx", "Iyy", "Izz"))
        I = np.array([[self.Ixx, 0.0, self.Ixz], [0.0, self.Iyy, 0.0], [self.Ixz, 0.0, self.Izz]])
        problem = inertia_problem(I)
        if problem is not None and "principal moments" in problem:
            raise InputError("upper body", "Ixz", problem)
        if problem is not None:
            small, middle, large = np.linalg.eigvalsh(I)
            warn(f"upper body: the inertia breaks the triangle inequality (largest principal moment {large:.6g} > "
                 f"{small:.6g} + {middle:.6g} kg m^2); computed as given")
        if not UPPER_MASS[0] <= self.mass <= UPPER_MASS[1]:
            warn(f"upper body: mass = {self.mass:.6g} kg is outside {UPPER_MASS[0]:g}..{UPPER_MASS[1]:g} kg (a rider's "
                 "upper body: 20..80 kg); computed as given")
        for name, value in (("z", self.z), ("hip_z", self.hip_z)):
            if not -UPPER_REACH <= value <= 0:
                warn(f"upper body: {name} = {value:.6g} m is {'below the ground' if value > 0 else 'more than '}"
                     f"{'' if value > 0 else f'{UPPER_REACH:g} m above the ground'}; computed as given")
        if abs(self.x) > UPPER_REACH:
            warn(f"upper body: x = {self.x:.6g} m is more than {UPPER_REACH:g} m from the rear contact; computed as "
                 "given")

    def properties(self):
        """The upper body as :class:`~bikemass.mass.inertia.MassProperties`."""
        I = np.array([[self.Ixx, 0.0, self.Ixz], [0.0, self.Iyy, 0.0], [self.Ixz, 0.0, self.Izz]])
        return MassProperties(self.mass, [self.x, 0.0, self.z], I)


@dataclass(frozen=True)
class LeanJoint:
    """The hip joint's passive torque ``-(stiffness lean + damping lean')``."""

    stiffness: float = field(default=LEAN_STIFFNESS, metadata={"unit": "N m/rad", "description": "stiffness"})
    damping: float = field(default=LEAN_DAMPING, metadata={"unit": "N m s/rad", "description": "damping"})

    def __post_init__(self):
        _checked(self, "lean joint", nonnegative=("stiffness", "damping"))


@dataclass(frozen=True)
class RiderLeanParameters:
    """The parameters of the Whipple bicycle with a leaning rider (the ``rider-lean`` model; Moore 2012).

    One value whether it comes from a bicycle and a seated rider split at the hips
    (:func:`~bikemass.rider.lean_split.rider_lean_parameters`) or from BicycleParameters'
    ``MooreRiderLean2012`` parameter set (:func:`bikemass.load_parameter_set`; Moore's 36 named
    values converted exactly, :func:`~bikemass.models.moore2012.from_moore_values`).  SI, benchmark
    frame.

    Attributes
    ----------
    bicycle : BenchmarkParameters
        The benchmark set whose rear frame B holds the bicycle's rear frame with the rider's legs and
        pelvis (not the upper body).
    upper : UpperBody
        The leaning upper body: mass (kg), centre of mass (m), inertia (kg m^2), the hip axis's z (m).
    joint : LeanJoint
        The hip joint's stiffness (N m/rad) and damping (N m s/rad).

    See Also
    --------
    bikemass.load_parameter_set : Reads them from a ``MooreRiderLean2012`` set.
    bikemass.models.moore2012 : The conversions between them and Moore's named values.

    Examples
    --------
    The Jamis with the Relaxed rider split at the hips, written as Moore's values and read back:

    >>> import json, os, tempfile
    >>> import bikemass as bm
    >>> from bikemass.models.moore2012 import to_moore_values
    >>> from bikemass.rider.lean_split import rider_lean_parameters
    >>> bike = bm.load_bicycle("jamis")
    >>> lean = rider_lean_parameters(bike, bm.seated_rider(bike, "relaxed"))
    >>> path = os.path.join(tempfile.mkdtemp(), "jamis-lean.yml")
    >>> document = {"parameterization": "MooreRiderLean2012", "values": to_moore_values(lean, speed=5.0)}
    >>> _ = open(path, "w").write(json.dumps(document))
    >>> read = bm.load_parameter_set(path)
    >>> print(type(read.parameters).__name__, f"upper body {read.parameters.upper.mass:.2f} kg,",
    ...       f"mg {read.values['mg']:.2f} kg")
    RiderLeanParameters upper body 56.35 kg, mg 56.35 kg
    """

    bicycle: BenchmarkParameters
    upper: UpperBody
    joint: LeanJoint = LeanJoint()

    MODEL: ClassVar[str] = "rider-lean"
    """The member of the model family these parameters are of: what an analysis builds from them when
    it is not told a model (:func:`bikemass.models.registry.model_of`)."""

    def values(self):
        """``{name: float}`` of the generated code's parameters (the 26 benchmark ones and the member's)."""
        u, j = self.upper, self.joint
        return {**{name: getattr(self.bicycle, name) for name in NAMES}, "mU": u.mass, "xU": u.x, "zU": u.z, "IUxx": u.Ixx, "IUyy": u.Iyy,
                "IUzz": u.Izz, "IUxz": u.Ixz, "zhip": u.hip_z, "klean": j.stiffness, "clean": j.damping}

    def rigid(self):
        """The benchmark set of the same bicycle and rider with the upper body held rigid (merged into B)."""
        b = self.bicycle
        I = np.array([[b.IBxx, 0.0, b.IBxz], [0.0, b.IByy, 0.0], [b.IBxz, 0.0, b.IBzz]])
        whole = combine((MassProperties(b.mB, [b.xB, 0.0, b.zB], I), self.upper.properties()))
        J = whole.inertia
        return dataclasses.replace(b, mB=whole.mass, xB=whole.com[0], zB=whole.com[2], IBxx=J[0, 0],
                                   IByy=J[1, 1], IBzz=J[2, 2], IBxz=J[0, 2])

    @property
    def gravity_stiffness(self):
        """``m g h`` (N m/rad): the upper body's gravity torque per radian of lean about the hip axis."""
        return self.upper.mass * self.bicycle.g * (self.upper.hip_z - self.upper.z)

    def replace(self, **changes):
        """A copy with ``bicycle``, ``upper`` or ``joint`` changed."""
        return RiderLeanParameters(**{**{f.name: getattr(self, f.name) for f in fields(self)}, **changes})
