"""The benchmark bicycle as Meijaard et al. (2007) print it, for tests that compare bikemass with the
paper rather than with itself: M, C1, K0 (without g), K2 of their Sec. 4 (14-15 significant digits),
Table 1's wheelbase, trail and steer-axis tilt, the weave and capsize speeds, and the state matrix
assembled from them here (independently of bikemass's model builder)."""

import numpy as np

M = np.array([[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]])
C1 = np.array([[0.0, 33.86641391492494], [-0.85035641456978, 1.68540397397560]])
K0 = np.array([[-80.95, -2.59951685249872], [-2.59951685249872, -0.80329488458618]])
K2 = np.array([[0.0, 76.59734589573222], [0.0, 2.65431523794604]])
WHEELBASE, TRAIL, TILT, G = 1.02, 0.08, np.pi / 10, 9.81
"""Table 1: w (m), c (m), lam (rad); g (m/s^2)."""
WEAVE, CAPSIZE = 4.29238253634111, 6.02426201538837
"""Sec. 4: the weave and capsize speeds (m/s)."""


def mechanical_state_matrix(v):
    """The 4 x 4 state matrix (roll, steer, roll rate, steer rate) at ``v`` m/s."""
    Minv = np.linalg.inv(M)
    return np.block([[np.zeros((2, 2)), np.eye(2)], [-Minv @ (G * K0 + v ** 2 * K2), -Minv @ (v * C1)]])


def state_matrix(v):
    """The 6 x 6 state matrix (roll, steer, roll rate, steer rate, heading, lateral of the rear contact)
    at ``v`` m/s: the heading ``psi' = (v delta + c delta') cos(lam) / w`` and ``y' = v psi``."""
    A = np.zeros((6, 6))
    A[:4, :4] = mechanical_state_matrix(v)
    A[4, 1] = v * np.cos(TILT) / WHEELBASE
    A[4, 3] = TRAIL * np.cos(TILT) / WHEELBASE
    A[5, 4] = v
    return A


def roll_per_steer_torque(v, w):
    """The frequency response roll angle / steer torque (rad/(N m)) at ``v`` m/s and angular
    frequencies ``w`` (rad/s)."""
    A = mechanical_state_matrix(v)
    b = np.concatenate([np.zeros(2), np.linalg.inv(M)[:, 1]])
    return np.array([np.linalg.solve(1j * x * np.eye(4) - A, b)[0] for x in w])
