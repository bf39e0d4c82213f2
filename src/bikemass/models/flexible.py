"""The ``flexible`` member of the model family: the Whipple bicycle whose rear frame twists and whose fork
bends, each a rotation about an axis with the stiffness and the inertia of its tubes' beam model
(docs/models-flexible.md).

Coordinates ``q = [roll, steer, frame twist, fork bending]`` (rad), equations (Kane's method,
:mod:`bikemass.models.derive.flexible`, shipped as :mod:`bikemass.models.generated.flexible_matrices`)::

    M q'' + v C1 q' + (K0 + v**2 K2) q = [T_phi, T_delta, 0, 0]
    psi' = H0 . q' + v H1 . q,      y' = v psi

From Python::

    bike = bm.load_bicycle("jamis")
    params = bm.parameters(bike, bm.load_rider("relaxed"))
    flexible = flexible_parameters(bike, "steel", params)        # the beam models, reduced
    model = flexible_model(flexible)                            # a LinearModel

An infinitely stiff compliance (``None``) drops its coordinate: ``flexible_model(flexible.rigid())``
is the Whipple bicycle.
"""

from dataclasses import dataclass, replace

import numpy as np

from ..fe.compliance import Compliance, frame_twist
from ..fe.fork import fork_bending, fork_structure
from ..fe.model import resolve_material
from ..fe.stiffness import head_tube_axis
from ..materials import Material
from ..parameters import BenchmarkParameters
from .generated import flexible_matrices as generated
from .linear import Signal, second_order_model
from .whipple import HEADING, INPUTS, LATERAL, ROLL_ANGLE, ROLL_RATE, STEER_ANGLE, STEER_RATE

FRAME_TWIST = Signal("frame-twist", "rad", "rotation of the head tube (and the front assembly) relative to the "
                                           "rear frame about the frame's twist axis")
FORK_BENDING = Signal("fork-bending", "rad", "rotation of the front wheel's hub relative to the front frame "
                                             "about the fork's bending axis")
FRAME_TWIST_RATE = Signal("frame-twist-rate", "rad/s", "frame twist rate")
FORK_BENDING_RATE = Signal("fork-bending-rate", "rad/s", "fork bending rate")
WOBBLE = "wobble"
"""The family of the compliances' modes (the engine names a mode by the family holding most of it)."""
NAME = "whipple+flexible"

_COMPLIANCE_KEYS = {"frame": "r", "fork": "f"}


@dataclass(frozen=True)
class FlexibleParameters:
    """A rigid benchmark parameter set and the two compliances; ``None`` is an infinitely stiff one."""

    rigid: BenchmarkParameters
    frame: Compliance = None
    fork: Compliance = None

    def values(self):
        """``{name: float}`` for :data:`~bikemass.models.generated.flexible_matrices.PARAMETERS`
        (an absent compliance gets placeholder values: its coordinate is dropped)."""
        out = self.rigid.to_dict()
        for which, key in _COMPLIANCE_KEYS.items():
            c = getattr(self, which) or Compliance(which, (0.0, 0.0), (1.0, 0.0), 1.0, 0.0, (0.0, 0.0), 0.0)
            out[f"x{key}"], out[f"z{key}"] = c.point
            out[f"n{key}x"], out[f"n{key}z"] = c.direction
            out[f"k{key}"], out[f"L{key}"], out[f"m{key}"] = c.stiffness, c.modal_momentum, c.modal_mass
            out[f"J{key}x"], out[f"J{key}z"] = c.modal_moment
        return out

    @property
    def coordinates(self):
        """Indices of the coordinates kept (0 roll, 1 steer, 2 frame twist, 3 fork bending)."""
        return (0, 1) + ((2,) if self.frame is not None else ()) + ((3,) if self.fork is not None else ())

    def rigid_limit(self):
        """Both compliances infinitely stiff: the Whipple bicycle of :attr:`rigid`."""
        return replace(self, frame=None, fork=None)

    def scaled(self, stiffness=1.0, inertia=1.0):
        """Both compliances with their stiffness and their tubes' inertia multiplied by factors."""
        return replace(self, **{w: c.scaled(stiffness, inertia) for w in _COMPLIANCE_KEYS
                                if (c := getattr(self, w)) is not None})


def flexible_parameters(bicycle, material, params, frame=True, fork=True, timoshenko=True):
    """:class:`FlexibleParameters` of a bicycle: its rear frame's and fork's beam models, reduced.

    Parameters
    ----------
    bicycle : Bicycle
        A bicycle with a rear-frame ``structure`` (:func:`bikemass.load_bicycle`); its fork is its
        front-frame tubes ``fork*``/``steerer`` or the default fork (:mod:`bikemass.fe.fork`).
    material : str, Material or None
        Every frame and fork tube in this material (a name of ``frames/materials.yaml`` or a
        one-material file); ``None`` keeps each tube's own.  The mass properties in ``params`` stay
        as they are (as the thesis kept the steel frames' for every material).
    params : BenchmarkParameters
        The rigid parameter set (bicycle and rider), e.g. ``bm.parameters(bicycle, rider)``.
    frame, fork : bool
        Whether the rear frame twists and the fork bends (``False``: that part is rigid).
    timoshenko : bool
        Timoshenko beams (default) or Euler-Bernoulli.

    Returns
    -------
    FlexibleParameters
    """
    if isinstance(material, str):
        material = resolve_material(material)
    if material is not None and not isinstance(material, Material):
        raise TypeError(f"material: a name or a Material, got {type(material).__name__}")
    if bicycle.structure is None:
        raise ValueError(f"bicycle {bicycle.name!r} has no rear-frame beam structure ('structure:' in its "
                         "file): the flexible model needs the frame's tubes")
    contact = np.array([params.w, 0.0, 0.0])
    axis = head_tube_axis(bicycle.structure)
    if abs(np.arctan2(axis[0], axis[2]) - params.lam) > 1e-3:
        raise ValueError(f"bicycle {bicycle.name!r}: the head tube's axis is tilted "
                         f"{np.arctan2(axis[0], axis[2]):.4f} rad, the parameter set's steer axis {params.lam:.4f} rad")
    twist = frame_twist(bicycle.structure, contact, material, timoshenko) if frame else None
    bending = fork_bending(fork_structure(bicycle, material), contact, axis, timoshenko) if fork else None
    return FlexibleParameters(params, twist, bending)


def flexible_matrices(flexible):
    """``(M, C1, K0, K2)`` on the kept coordinates (:attr:`FlexibleParameters.coordinates`)."""
    keep = np.ix_(flexible.coordinates, flexible.coordinates)
    return tuple(X[keep] for X in generated.matrices(flexible.values()))


def flexible_model(flexible):
    """The :class:`~bikemass.models.linear.LinearModel` of :class:`FlexibleParameters`.

    States: roll, steer and the kept compliances, their rates, then heading and lateral (kinematic);
    inputs roll-torque and steer-torque.  Families: ``"bicycle"`` (roll, steer) and ``"wobble"`` (the
    compliances).  Named ``"whipple+flexible"`` (``"whipple"`` when both compliances are rigid).
    """
    keep = flexible.coordinates
    M, C1, K0, K2 = flexible_matrices(flexible)
    H0, H1 = (h[list(keep)] for h in generated.heading(flexible.values()))
    n = len(keep)
    extra = {2: (FRAME_TWIST, FRAME_TWIST_RATE), 3: (FORK_BENDING, FORK_BENDING_RATE)}
    coordinates = (ROLL_ANGLE, STEER_ANGLE, *(extra[k][0] for k in keep[2:]))
    rates = (ROLL_RATE, STEER_RATE, *(extra[k][1] for k in keep[2:]))
    heading = [np.r_[np.zeros(n), H0, 0.0, 0.0], np.r_[H1, np.zeros(n), 0.0, 0.0]]
    lateral = [None, np.r_[np.zeros(2 * n), 1.0, 0.0]]
    F = np.zeros((n, 2))
    F[0, 0] = F[1, 1] = 1.0
    families = {"bicycle": (0, 1), **({WOBBLE: tuple(range(2, n))} if n > 2 else {})}
    return second_order_model(NAME if n > 2 else "whipple", coordinates, rates, M, [None, C1], [K0, None, K2], F,
                              INPUTS, kinematics=[(HEADING, heading), (LATERAL, lateral)], families=families)
