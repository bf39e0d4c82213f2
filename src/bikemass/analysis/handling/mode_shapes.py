"""Mode shapes: each eigenvector of a linear model at one speed as the amplitude and phase of its
coordinates (roll, steer, the heading and lateral position, and a richer model's own).

The modes are the stability engine's (:func:`~bikemass.analysis.engine.modes.follow_modes`:
followed from standstill and named weave, capsize, caster, ...).  An eigenvector ``x`` of the
dynamic states with eigenvalue ``l`` extends to the kinematic states ``z`` (heading, lateral) as
``z = (l I - A_zz)^-1 A_zx x``, the part of the full eigenvector they carry (``l != 0``).  Each
shape is scaled so that its largest mechanical coordinate (roll, steer, ...; the dynamic states
without a model's mechanics) has amplitude 1 and phase 0; the other amplitudes are per unit of
that coordinate, the phases (degrees) lead it when positive.
"""

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from ...core.results import Result, quantity, renamed_units
from ...core.frozen import readonly, short_repr
from ...core.tables import Table
from ..engine.modes import follow_modes
from .plant import System, check_speed, linear_model


EIGENVALUE_UNIT = "1/s (real, imaginary)"
"""The unit of an eigenvalue (written as its real and imaginary part)."""
SHAPE_UNIT = "the coordinate's unit per unit of the mode's reference coordinate"
"""The unit of a shape's component: per unit of the mode's reference coordinate (its amplitude)."""
PHASE_UNIT = "deg"
"""The unit of :attr:`ModeShapes.phase`."""


def coordinates(model):
    """Indices of the states a shape shows: the mechanical coordinates (the dynamic states when the
    model has no mechanics), then the kinematic states; and how many of them lead (the first
    group, from which the reference is chosen)."""
    n = model.n_dynamic
    lead = list(range(len(model.mechanics.M))) if model.mechanics is not None else list(range(n))
    return lead + list(range(n, len(model.states))), len(lead)


def full_eigenvector(A, n_dynamic, value, vector):
    """The eigenvector of the whole state matrix ``A`` (N, N) from that of its dynamic block."""
    Azz = A[n_dynamic:, n_dynamic:]
    Azx = A[n_dynamic:, :n_dynamic]
    if not len(Azz):
        return vector
    kinematic = np.linalg.solve(value * np.eye(len(Azz)) - Azz, Azx @ vector)
    return np.concatenate([vector, kinematic])


@dataclass(frozen=True, eq=False, repr=False)
class ModeShapes(Result):
    """The modes of a linear model at one speed, each as the amplitude and phase of its coordinates.

    Attributes
    ----------
    speed : float
        Forward speed (m/s).
    labels : tuple of str
        The engine's tracked labels (``weave 1``, ``weave 2``, ``capsize``, ``caster``, ...).
    names : tuple of str
        What each root is at this speed (``weave``, ``weave, real (upper)``, ``capsize``, ...).
    eigenvalues : numpy.ndarray (m,)
        Complex, 1/s.
    coordinates, coordinate_units : tuple of str
        The coordinates shown and their units (``units``, the name of ``coordinate_units`` before
        0.3, still reads it with a DeprecationWarning; ``units()`` is the units block of :meth:`to_dict`).
    shapes : numpy.ndarray (m, k)
        Complex components, scaled so the largest mechanical coordinate is 1 (phase 0).
    reference : tuple of str
        Each mode's largest mechanical coordinate (amplitude 1, phase 0).
    n_mechanical : int
        How many of the coordinates (the first) are mechanical (roll, steer, ...); the others are
        kinematic (heading, lateral).

    Arrays are read-only; :attr:`amplitude` and :attr:`phase` are ``|shapes|`` and its angle (deg).

    See Also
    --------
    bikemass.mode_shapes : Makes it.

    Examples
    --------
    >>> import bikemass as bm
    >>> shapes = bm.mode_shapes(bm.parameters("benchmark"), 5.0)
    >>> shapes.coordinates, shapes.coordinate_units
    (('roll-angle', 'steer-angle', 'heading', 'lateral'), ('rad', 'rad', 'rad', 'm'))
    >>> shapes.reference[2], shapes.units()["phase"]
    ('roll-angle', 'deg')
    """

    speed: float = quantity("m/s", "forward speed")
    labels: tuple = ()
    names: tuple = ()
    eigenvalues: np.ndarray = quantity(EIGENVALUE_UNIT, "each mode's eigenvalue (complex)", default=None)
    coordinates: tuple = ()
    coordinate_units: tuple = ()
    shapes: np.ndarray = quantity(SHAPE_UNIT, "(m, k) complex, the largest mechanical coordinate 1", default=None)
    reference: tuple = ()
    n_mechanical: int = 0

    units = renamed_units("coordinate_units")

    def __post_init__(self):
        object.__setattr__(self, "eigenvalues", readonly(self.eigenvalues, complex))
        object.__setattr__(self, "shapes", readonly(self.shapes, complex))
        for name in ("labels", "names", "coordinates", "coordinate_units", "reference"):
            object.__setattr__(self, name, tuple(getattr(self, name)))
        object.__setattr__(self, "speed", float(self.speed))
        object.__setattr__(self, "n_mechanical", int(self.n_mechanical))

    @property
    def amplitude(self):
        """``|shape|`` (m, k): per unit of each mode's reference coordinate."""
        return readonly(np.abs(self.shapes))

    @property
    def phase(self):
        """Phase (m, k) in degrees in (-180, 180], relative to each mode's reference coordinate."""
        return readonly(np.degrees(np.angle(self.shapes)) + 0.0)

    def shape(self, label):
        """``{coordinate: (amplitude, phase in deg)}`` of the mode ``label``."""
        i = self.labels.index(label)
        return {c: (float(self.amplitude[i, k]), float(self.phase[i, k])) for k, c in enumerate(self.coordinates)}

    def tables(self):
        """``{"shapes": Table}``: one row per mode and coordinate (``bikemass mode-shapes``'s table):
        ``mode``, ``name``, the eigenvalue's ``real`` and ``imaginary`` parts (1/s), ``coordinate``,
        its ``unit``, ``amplitude`` (per unit of the mode's reference coordinate) and ``phase`` (deg).
        The speed is the frame's ``attrs``."""
        k = len(self.coordinates)
        z = np.repeat(self.eigenvalues, k)
        columns = {"mode": list(np.repeat(self.labels, k)), "name": list(np.repeat(self.names, k)),
                   "real": z.real, "imaginary": z.imag, "coordinate": list(self.coordinates) * len(self.labels),
                   "unit": list(self.coordinate_units) * len(self.labels), "amplitude": self.amplitude.ravel(),
                   "phase": self.phase.ravel()}
        units = {"real": "1/s", "imaginary": "1/s", "amplitude": "coordinate's unit per unit of the reference",
                 "phase": PHASE_UNIT}
        return {"shapes": Table(columns, units, {"speed": self.speed})}

    def to_dict(self):
        """Plain data: speed, coordinates, and per mode its label, name, eigenvalue ``[re, im]``,
        reference coordinate and ``shape: {coordinate: {amplitude, phase}}``."""
        return {"speed": self.speed, "coordinates": list(self.coordinates),
                "modes": [{"label": label, "name": name, "eigenvalue": [float(z.real), float(z.imag)],
                           "reference": ref,
                           "shape": {c: {"amplitude": float(a), "phase": float(p)}
                                     for c, a, p in zip(self.coordinates, self.amplitude[i], self.phase[i])}}
                          for i, (label, name, z, ref) in enumerate(zip(self.labels, self.names, self.eigenvalues,
                                                                         self.reference))]}

    def unit_block(self):
        """The units block of :meth:`to_dict` (``units()``): the speed's and the eigenvalue's as their
        fields declare, each shape's amplitude per unit of its reference coordinate, its phase in
        :data:`PHASE_UNIT`."""
        declared = self.field_units()
        return {"speed": declared["speed"], "eigenvalue": declared["eigenvalues"], "amplitude": declared["shapes"],
                "phase": PHASE_UNIT}

    def __repr__(self):
        return short_repr(self, ("speed", f"{self.speed:g} m/s"), ("modes", ", ".join(self.labels)),
                          ("coordinates", ", ".join(self.coordinates)))


def mode_shapes(system: System, speed: float,
                stiffness: "ArrayLike | None" = None) -> ModeShapes:
    """Every mode of a linear model at ``speed``: eigenvalue and the amplitude and phase of each
    coordinate.

    Parameters
    ----------
    system : LinearModel, Scenario, Built, BenchmarkParameters or RiderLeanParameters
        A linear model, a scenario, or a parameter set (the Whipple bicycle, or the leaning rider's
        model of RiderLeanParameters).
    speed : float
        Forward speed (m/s).
    stiffness : array_like (2, 2), optional
        Rear-frame stiffness S (N m/rad) of a parameter set.

    Returns
    -------
    ModeShapes
        One row per tracked mode (weave 1, weave 2, capsize, caster, ... ; a weave pair gives two
        conjugate rows), one column per coordinate (roll-angle, steer-angle, heading, lateral).

    Raises
    ------
    InputError
        A bad speed or S, or a system of another type.

    See Also
    --------
    plot_mode_shapes : Draw them as phasors.
    stability : The modes over speed.

    Examples
    --------
    >>> import bikemass as bm
    >>> shapes = bm.mode_shapes(bm.parameters("benchmark"), 5.0)
    >>> amplitude, phase = shapes.shape("weave 2")["roll-angle"]
    >>> print(shapes.names, f"roll {amplitude:.3f} at {phase:.1f} deg of steer")
    ('weave', 'weave', 'capsize', 'caster') roll 0.771 at 10.0 deg of steer
    """
    model = linear_model(system, stiffness)
    v = check_speed(speed)
    modes = follow_modes(model, [v])
    A = model.state_matrix(v)
    shown, lead = coordinates(model)
    values = modes.eigenvalues[0]
    rows, references = [], []
    for i, value in enumerate(values):
        x = full_eigenvector(A, model.n_dynamic, value, modes.eigenvectors[0, :, i])[shown]
        k = int(np.argmax(np.abs(x[:lead])))
        x = x / x[k]
        rows.append(x.real + 0j if value.imag == 0 else x)     # a real root's shape is real
        references.append(model.state_names[shown[k]])
    return ModeShapes(v, tuple(modes.labels), tuple(str(n) for n in modes.names()[0]), values,
                      tuple(model.state_names[k] for k in shown), tuple(model.states[k].unit for k in shown),
                      np.array(rows), tuple(references), lead)
