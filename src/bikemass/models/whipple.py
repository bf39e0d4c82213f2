"""The Whipple bicycle (Meijaard et al. 2007) and its quasi-static flexible rear frame (Williams 2015)
as :class:`~bikemass.models.linear.LinearModel` s.

Equations of motion (Meijaard et al. 2007, Eq. 1), roll ``phi`` and steer ``delta`` (rad)::

    M q'' + v C1 q' + (g K0 + v**2 K2) q = [T_phi, T_delta]

and the kinematics of the rear contact (their section 6): heading ``psi`` and lateral position ``y``
(right, m)::

    psi' = (v delta + c delta') cos(lam) / w,      y' = v psi

and, as a further output, the lateral position of the front contact (linearised; the output
the Hess, Moore & Hubbard 2012 rider feeds back, Moore 2012 section "Model Description")::

    y_Q = y + w psi - c cos(lam) delta

A flexible rear frame (Williams 2015, Eq. 3.27-3.30) replaces ``g K0`` by the static stiffness
``g K0 - (g K0)^T (g K0 + S)^-1 g K0`` of the frame's 2x2 stiffness ``S`` (N m/rad) in series with
gravity; ``M``, ``C1`` and ``K2`` stay.

The matrices come from the generated model family (:mod:`bikemass.models.whipple_generated`: the
code ``python -m bikemass.models.derive`` writes from Kane's method), the one numerical path of
every model; the hand-written closed form of :mod:`bikemass.models.canonical` is their test oracle.
"""

import numpy as np

from .flexible_static import static_stiffness
from .linear import Signal, second_order_model
from .whipple_generated import whipple_matrices

ROLL_ANGLE = Signal("roll-angle", "rad", "roll angle of the rear frame, positive to the right")
STEER_ANGLE = Signal("steer-angle", "rad", "steer angle of the front frame, positive to the right")
ROLL_RATE = Signal("roll-rate", "rad/s", "roll angular rate")
STEER_RATE = Signal("steer-rate", "rad/s", "steer angular rate")
HEADING = Signal("heading", "rad", "yaw angle of the rear frame, positive to the right")
LATERAL = Signal("lateral", "m", "lateral position of the rear contact, positive to the right")
FRONT_LATERAL = Signal("front-lateral", "m", "lateral position of the front contact, positive to the right")
ROLL_TORQUE = Signal("roll-torque", "N m", "torque between the ground and the rear frame about the x axis")
STEER_TORQUE = Signal("steer-torque", "N m", "torque between the rear and front frames about the steer axis")

INPUTS = (ROLL_TORQUE, STEER_TORQUE)
"""The inputs of every bicycle model, in this order."""
COORDINATES, RATES, KINEMATIC = (ROLL_ANGLE, STEER_ANGLE), (ROLL_RATE, STEER_RATE), (HEADING, LATERAL)
"""The Whipple bicycle's states in order: the coordinates, their rates, the kinematic states."""
FURTHER_OUTPUTS = (FRONT_LATERAL,)
"""Its outputs beyond the states."""


def whipple_model(params, stiffness=None):
    """The Whipple bicycle of a benchmark parameter set, rigid or with a quasi-static flexible rear frame.

    Parameters
    ----------
    params : BenchmarkParameters
        The 26 Meijaard et al. (2007) parameters (SI); any object with those attributes works, and
        complex values give a complex model (the complex-step derivatives of the sensitivities).
    stiffness : array_like (2, 2) or None
        The rear frame's stiffness S (N m/rad, rows and columns roll and steer); ``None``: rigid.

    Returns
    -------
    LinearModel
        States roll-angle, steer-angle, roll-rate, steer-rate (dynamic), heading, lateral;
        inputs roll-torque, steer-torque; the further output front-lateral.  Named ``"whipple"``,
        or ``"whipple+flexible-static"`` with a stiffness.
    """
    m = whipple_matrices(params)
    gK0 = static_stiffness(params.g * m.K0, stiffness)      # params.g, not m.g: it may be complex
    cl = np.cos(params.lam)
    heading = [np.array([0, 0, 0, params.c * cl / params.w, 0, 0]),
               np.array([0, cl / params.w, 0, 0, 0, 0])]
    lateral = [None, np.array([0, 0, 0, 0, 1.0, 0])]
    front = np.array([0, -params.c * cl, 0, 0, params.w, 1.0])
    name = "whipple" if stiffness is None else "whipple+flexible-static"
    return second_order_model(name, COORDINATES, RATES, m.M, [None, m.C1], [gK0, None, m.K2], np.eye(2), INPUTS,
                              kinematics=list(zip(KINEMATIC, (heading, lateral))),
                              outputs=list(zip(FURTHER_OUTPUTS, (front,))))
