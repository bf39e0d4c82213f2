"""The rider in the loop: the Hess, Moore & Hubbard (2012) manual-control model on any linear model.

Five sequential loops, inner to outer, each a pure gain on an error (Hess, Moore & Hubbard 2012,
"Modeling the Manually Controlled Bicycle", IEEE Trans. SMC-A 42(3); Moore 2012, *Human Control
of a Bicycle*, ch. "Control", section "Model Description", Figs. 10.6-10.7; the loop wiring of
Moore's HumanControl ``WhippleModel.mdl``)::

    psi_c    = k_y      (y_c     - y_Q)        lateral position of the front contact (visual)
    phi_c    = k_psi    (psi_c   - psi)        heading (visual)
    phidot_c = k_phi    (phi_c   - phi)        roll angle (visual)
    delta_c  = k_phidot (phidot_c - phidot)    roll rate (vestibular)
    u        = k_delta  (delta_c - delta)      steer angle (proprioceptive)
    T_delta  = G_nm(s) u,   G_nm(s) = w_nm^2 / (s^2 + 2 zeta_nm w_nm s + w_nm^2)

with the neuromuscular dynamics ``w_nm = 30 rad/s``, ``zeta_nm = 0.707`` (Moore 2012, Eq.
``eqNeuromuscular``; Moore, Hubbard & Hess 2016, BMD).  No time delay sits in the loops.  The
signals are the model's outputs by name (``steer-angle``, ``roll-rate``, ``roll-angle``,
``heading`` and ``front-lateral``, or the rear contact's ``lateral`` for a model that does not
name its front contact), so every model of the family takes the rider.

:func:`loop_system` builds the state space of the rider and the bicycle with the loops up to one
closed or open and the command injected at that loop; :func:`closed_loop` is the whole system.
"""

from dataclasses import dataclass

import numpy as np

from ...core.errors import InputError
from ...core.frozen import readonly, short_repr
from .gains import Gains, as_gains
from .plant import check_speed

NEUROMUSCULAR_FREQUENCY = 30.0
"""``w_nm`` (rad/s): Moore 2012, Eq. ``eqNeuromuscular`` and the text below it."""
NEUROMUSCULAR_DAMPING = 0.707
"""``zeta_nm``: Moore 2012, Eq. ``eqNeuromuscular`` (HumanControl ``generate_data.m``)."""

CONTROL = "steer-torque"
"""The input the rider drives (steer torque; Hess, Moore & Hubbard 2012's primary input)."""
FED_BACK = ("steer-angle", "roll-rate", "roll-angle", "heading")
"""The signals of the four inner loops, inner first."""
LATERAL_FED_BACK = ("front-lateral", "lateral")
"""The outermost loop's signal: the front contact's lateral position (Moore 2012: ``y_q``), or
the rear contact's where a model does not name the front contact."""


@dataclass(frozen=True, eq=False)
class RiderPlant:
    """A linear model at one speed as the rider sees it.

    Attributes
    ----------
    speed : float
        m/s.
    A : numpy.ndarray (N, N)
        The model's state matrix.
    b : numpy.ndarray (N,)
        The steer-torque column of ``B``.
    rows : numpy.ndarray (5, N)
        The signals fed back (steer angle, roll rate, roll angle, heading, lateral position).
    lateral : str
        Which lateral position is fed back (``front-lateral`` or ``lateral``).
    states : tuple of str
        The model's states.
    """

    speed: float
    A: np.ndarray
    b: np.ndarray
    rows: np.ndarray
    lateral: str
    states: tuple


def rider_plant(model, speed):
    """:class:`RiderPlant` of ``model`` (a LinearModel) at ``speed`` (m/s); InputError when the model
    lacks the steer torque or a fed back signal."""
    v = check_speed(speed)
    if CONTROL not in model.input_names:
        raise InputError("model", model.name, f"a model with the input {CONTROL} for the rider to drive")
    lateral = next((name for name in LATERAL_FED_BACK if name in model.output_names), None)
    missing = [name for name in FED_BACK if name not in model.output_names] + ([] if lateral else ["lateral"])
    if missing:
        raise InputError("model", model.name, f"the outputs the rider feeds back: missing {', '.join(missing)}")
    return RiderPlant(v, model.state_matrix(v), model.input_matrix(v)[:, model.input_names.index(CONTROL)],
                      model.output_matrix((*FED_BACK, lateral)), lateral, model.state_names)


def loop_system(plant, gains, inject, closed, output=None):
    """``(A, b, c)`` of the rider and the bicycle with the command entering at loop ``inject``.

    Parameters
    ----------
    plant : RiderPlant
    gains : sequence of float
        The gains of loops ``0 .. inject`` (inner first; more are ignored).
    inject : int
        The loop whose command is the input (0 steer angle .. 4 lateral position).
    closed : sequence of bool
        Which of the loops ``0 .. inject`` are fed back (an open loop passes its command on).
    output : array_like (N,), optional
        The output row on the bicycle's states; default the signal of loop ``inject``.

    Returns
    -------
    A : numpy.ndarray (N + 2, N + 2)
        States: the bicycle's, then the steer torque (N m) and its rate (N m/s).
    b, c : numpy.ndarray (N + 2,)
    """
    A, n = plant.A, len(plant.A)
    # u = k0 (k1 (... ki (r - yi) ...) - y1) - y0): r enters with k0 k1 ... ki, loop j's signal
    # (when fed back) with -k0 k1 ... kj
    reference = float(np.prod(gains[:inject + 1]))
    feedback, product = np.zeros(n), 1.0
    for i in range(inject + 1):
        product *= gains[i]
        if closed[i]:
            feedback += product * plant.rows[i]
    w2 = NEUROMUSCULAR_FREQUENCY ** 2
    Ac = np.zeros((n + 2, n + 2))
    Ac[:n, :n], Ac[:n, n] = A, plant.b
    Ac[n, n + 1] = 1.0
    Ac[n + 1, :n] = -w2 * feedback
    Ac[n + 1, n], Ac[n + 1, n + 1] = -w2, -2 * NEUROMUSCULAR_DAMPING * NEUROMUSCULAR_FREQUENCY
    bc = np.zeros(n + 2)
    bc[n + 1] = w2 * reference
    cc = np.zeros(n + 2)
    cc[:n] = plant.rows[inject] if output is None else output
    return Ac, bc, cc


RIDER_STATES = ("steer-torque", "steer-torque-rate")
"""The states the rider adds: the neuromuscular system's output torque (N m) and its rate (N m/s)."""


@dataclass(frozen=True, eq=False, repr=False)
class ClosedLoop:
    """The bicycle with the rider's five loops closed, commanded by the lateral position.

    Attributes
    ----------
    speed : float
        m/s.
    gains : Gains
    states : tuple of str
        The model's states, then ``steer-torque`` (N m) and ``steer-torque-rate`` (N m/s).
    A : numpy.ndarray (N + 2, N + 2)
        Closed-loop state matrix.
    b : numpy.ndarray (N + 2,)
        How the commanded lateral position (m) enters.
    lateral : str
        The lateral position fed back (``front-lateral`` or ``lateral``).
    eigenvalues : numpy.ndarray
        Of ``A`` (1/s), sorted; read-only.
    """

    speed: float
    gains: Gains
    states: tuple
    A: np.ndarray
    b: np.ndarray
    lateral: str
    eigenvalues: np.ndarray

    def __post_init__(self):
        for name in ("A", "b", "eigenvalues"):
            object.__setattr__(self, name, readonly(getattr(self, name)))

    @property
    def max_real(self):
        """The largest real part of the closed-loop eigenvalues (1/s)."""
        return float(self.eigenvalues.real.max())

    @property
    def stable(self):
        """Every closed-loop eigenvalue has a negative real part (``False`` where they could not be
        computed: a loop whose matrix overflowed)."""
        return bool(self.max_real < 0)

    def __repr__(self):
        return short_repr(self, ("speed", f"{self.speed:g} m/s"), ("states", len(self.states)),
                          ("stable", self.stable), ("max_real", f"{self.max_real:.4g} 1/s"))


def closed_loop(plant, gains):
    """:class:`ClosedLoop` of a :class:`RiderPlant` with ``gains`` (:class:`Gains` or five numbers)."""
    gains = as_gains(gains)
    with np.errstate(over="ignore", invalid="ignore"):         # huge gains: an overflowed matrix, refused below
        A, b, _ = loop_system(plant, tuple(gains), 4, (True,) * 5)
    if np.all(np.isfinite(A)):
        eigenvalues = np.sort_complex(np.linalg.eigvals(A))
    else:                                     # gains so large the loop overflows: no eigenvalue to speak of
        eigenvalues = np.full(len(A), complex(np.nan, np.nan))
    return ClosedLoop(plant.speed, gains, (*plant.states, *RIDER_STATES), A, b, plant.lateral, eigenvalues)
