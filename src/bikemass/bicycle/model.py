"""The :class:`Bicycle` value: geometry, keypoints, tubes, parts by body, FE structure, published data."""

from dataclasses import dataclass, replace

import numpy as np

from ..core.errors import InputError, shown
from ..core.frozen import frozen_fields, short_repr
from ..mass.parts import body_properties
from ..mass.tubes import Structure
from .components import BODIES


@dataclass(frozen=True, eq=False)
class Bicycle:
    """A bicycle read from ``frames/<name>.yaml`` (or a benchmark parameter file).

    ``parts`` holds every placed part (tubes, components, loads, wheel hoops, lumped
    bodies), each with its ``body`` in :data:`BODIES`.  ``structure`` is the rear-frame
    beam model (or ``None``), ``stiffness`` the published S matrices by material key
    (N m/rad), ``published`` the parameter set of a benchmark parameter file (else ``None``),
    ``contacts`` the rider contact points (:class:`~bikemass.bicycle.contacts.Contacts`) or ``None``;
    ``chart`` the geometry chart it was built from (:class:`~bikemass.bicycle.chart.Chart`) or ``None``,
    ``size`` the size picked from a size run,
    ``rider_included`` whether the rear frame already holds a rider (then none may be added),
    ``speed`` the speed (m/s) a parameter-set file gives beside the parameters (BicycleParameters'
    ``v``; not a bicycle parameter, the file's suggestion of a speed to look at) or ``None``,
    ``measured`` the :class:`~bikemass.bicycle.parameter_text.MeasuredParameters` of a measured
    bicycle (a parameter file with standard deviations, or a measured-data file: ``published``
    with its ``std``) or ``None``.

    See Also
    --------
    bikemass.load_bicycle : Makes one from a name, a file or a mapping.
    bikemass.parameters : Its benchmark parameter set.

    Examples
    --------
    >>> import bikemass as bm
    >>> bike = bm.load_bicycle("jamis")
    >>> sorted(bike.bodies())
    ['front_frame', 'front_wheel', 'rear_frame', 'rear_wheel']
    >>> print(f"rear frame {bike.bodies()['rear_frame'].mass:.3f} kg")
    rear frame 4.557 kg
    """

    name: str
    source: str
    geometry: object
    keypoints: dict
    tubes: tuple
    parts: tuple
    structure: Structure | None = None
    stiffness: dict | None = None
    published: object = None
    contacts: object = None
    chart: object = None
    size: str | None = None
    rider_included: bool = False
    speed: float | None = None
    measured: object = None

    def __post_init__(self):
        frozen_fields(self, "keypoints", "tubes", "parts", "stiffness")

    def __repr__(self):
        extra = [("size", repr(self.size))] if self.size else []
        return short_repr(self, ("name", repr(self.name)), *extra, ("wheelbase", f"{self.geometry.wheelbase:.4g} m"),
                          ("parts", len(self.parts)), ("tubes", len(self.tubes)),
                          ("structure", self.structure is not None), ("contacts", self.contacts is not None),
                          ("source", repr(shown(self.source))))

    def body_parts(self, body):
        """Parts of ``body`` (one of :data:`BODIES`)."""
        if body not in BODIES:
            raise InputError("body", body, f"body must be one of {', '.join(BODIES)}, got {body!r}")
        return tuple(p for p in self.parts if p.body == body)

    def bodies(self, method="mesh"):
        """``{body: MassProperties}`` of the four bodies (parts summed, ``method`` mesh|exact)."""
        return {b: body_properties(self.body_parts(b), method) for b in BODIES}

    def with_material(self, material):
        """The same bicycle with every tube (and the FE structure) in ``material``.

        Geometry and the mass model are kept, as the thesis kept the steel frames'
        mass properties for every material (Williams 2015, Sec. 3.2.2).
        """
        tubes = tuple(replace(t, material=material) for t in self.tubes)
        structure = self.structure
        if structure is not None:
            structure = replace(structure, tubes=tuple(replace(t, material=material) for t in structure.tubes))
        return replace(self, tubes=tubes, structure=structure)

    def published_stiffness(self, material):
        """Published 2x2 S (N m/rad) for ``material`` (a :class:`~bikemass.mass.materials.Material`), or None."""
        S = (self.stiffness or {}).get(material.key)
        return None if S is None else np.array(S)
