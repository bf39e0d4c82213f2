"""An independent numerical route to the flexible model's linear equations (test support).

Plain numpy geometry, sharing nothing with the sympy derivation: exact rotation matrices (Rodrigues)
for every joint, the pitch found by Newton's method from the front contact's height, velocities and
accelerations by central differences of the configuration along its motion.

* :func:`linear_matrices`: Kane's equations ``F_r + F_r*`` of the four lateral speeds, evaluated
  numerically (the dependent rates and accelerations solved from the rolling constraints at each
  configuration, the constrained partial velocities likewise), differentiated by central differences
  in the state: ``M``, ``C(v)``, ``K(v)`` at any speed;
* :func:`static_stiffness`: ``K0`` as the Hessian of the potential energy (gravity on every mass, the
  two springs) over the lateral coordinates, the pitch following them on the ground.

The tubes' Ritz fields enter as the derivation represents them (a particle displaced sideways in the
parent's axes beside a negative particle fixed in the parent); their equivalence to the beam model's
field is argued in docs/models-flexible.md, not tested here.  ``p`` holds the flexible model's values
(bikemass.models.family.values).
"""

import numpy as np


def rotation(axis, angle):
    """Rotation matrix of ``angle`` about the unit ``axis`` (Rodrigues)."""
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


class Geometry:
    """The bicycle's bodies and points for a configuration ``(x, y, psi, phi, pitch, delta, theta_r,
    theta_f, beta_R, beta_F)``; ``p`` the parameter values of the generated module."""

    def __init__(self, p):
        self.p = p
        lam = p["lam"]
        self.steer = np.array([np.sin(lam), 0.0, np.cos(lam)])
        self.nr = np.array([p["nrx"], 0.0, p["nrz"]])
        self.nf = np.array([p["nfx"], 0.0, p["nfz"]])
        self.Zr = np.array([p["xr"], 0.0, p["zr"]])
        self.Zf = np.array([p["xf"], 0.0, p["zf"]])
        self.S0 = np.array([p["w"] + p["c"], 0.0, 0.0])

    def pose(self, c):
        """``{body: (rotation, origin function)}`` and points for configuration ``c``."""
        p = self.p
        x, y, psi, phi, pitch, delta, thr, thf, bR, bF = c
        RL = rotation([0, 0, 1], psi) @ rotation([1, 0, 0], phi)
        RB = RL @ rotation([0, 1, 0], pitch)
        RD = RB @ rotation(self.nr, thr)
        RH = RD @ rotation(self.steer, delta)
        RE = RH @ rotation(self.nf, thf)
        R0 = np.array([x, y, 0.0]) + RL @ np.array([0, 0, -p["rR"]])
        axle = np.array([0, 0, -p["rR"]])

        def in_B(X):
            return R0 + RB @ (np.asarray(X, float) - axle)

        Zr = in_B(self.Zr)

        def in_D(X):
            return Zr + RD @ (np.asarray(X, float) - self.Zr)

        S0 = in_D(self.S0)

        def in_H(X):
            return S0 + RH @ (np.asarray(X, float) - self.S0)

        Zf = in_H(self.Zf)

        def in_E(X):
            return Zf + RE @ (np.asarray(X, float) - self.Zf)

        F0 = in_E([p["w"], 0, -p["rF"]])
        ey = RE[:, 1]
        down = np.array([0, 0, 1.0]) - ey[2] * ey
        PF = F0 + p["rF"] * down / np.linalg.norm(down)
        return {"RB": RB, "RR": RB @ rotation([0, 1, 0], bR), "RH": RH, "RF": RE @ rotation([0, 1, 0], bF),
                "R0": R0, "PR": np.array([x, y, 0.0]), "F0": F0, "PF": PF, "in_B": in_B, "in_H": in_H}

    def masses(self, pose, c):
        """Point masses (position, mass) of the particle pairs and the bodies' centres of mass."""
        p = self.p
        thr, thf = c[6], c[7]
        out = [(pose["in_B"]([p["xB"], 0, p["zB"]]), p["mB"]), (pose["R0"], p["mR"]),
               (pose["in_H"]([p["xH"], 0, p["zH"]]), p["mH"]), (pose["F0"], p["mF"])]
        for key, place, R, theta in (("r", pose["in_B"], pose["RB"], thr), ("f", pose["in_H"], pose["RH"], thf)):
            at = place([p[f"xt{key}"], 0, p[f"zt{key}"]])
            mass = p[f"mt{key}"]
            out += [(at + p[f"dt{key}"] * theta * R[:, 1], mass), (at, -mass)]
        return out

    def solve_pitch(self, c):
        """``c`` with the pitch that puts the front contact on the ground."""
        c = np.array(c, float)
        for _ in range(50):
            h = self.pose(c)["PF"][2]
            step = 1e-7
            c2 = c.copy()
            c2[4] += step
            slope = (self.pose(c2)["PF"][2] - h) / step
            c[4] -= h / slope
            if abs(h) < 1e-15:
                break
        return c


LATERAL = (3, 5, 6, 7)
"""Indices of roll, steer, frame twist and fork bending in the configuration."""


def potential(geometry, q):
    """Potential energy (J) at lateral coordinates ``q`` (4,), the pitch on the ground."""
    c = np.zeros(10)
    c[list(LATERAL)] = q
    c = geometry.solve_pitch(c)
    pose = geometry.pose(c)
    p = geometry.p
    gravity = sum(-m * p["g"] * r[2] for r, m in geometry.masses(pose, c))
    return gravity + 0.5 * p["kr"] * q[2] ** 2 + 0.5 * p["kf"] * q[3] ** 2


def static_stiffness(p, h=1e-4):
    """``K0`` (4x4, N m/rad) as the Hessian of :func:`potential` (central differences, step ``h``)."""
    g = Geometry(p)
    K = np.zeros((4, 4))
    for i in range(4):
        for j in range(4):
            total = 0.0
            for si, sj, w in ((1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)):
                q = np.zeros(4)
                q[i] += si * h
                q[j] += sj * h
                total += w * potential(g, q)
            K[i, j] = total / (4 * h * h)
    return K


def _vee(W):
    """The axial vector of the antisymmetric part of ``W``."""
    return np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2


BODIES = ("B", "R", "H", "F")


def _inertias(p):
    return {"B": np.array([[p["IBxx"], 0, p["IBxz"]], [0, p["IByy"], 0], [p["IBxz"], 0, p["IBzz"]]]),
            "R": np.diag([p["IRxx"], p["IRyy"], p["IRxx"]]),
            "H": np.array([[p["IHxx"], 0, p["IHxz"]], [0, p["IHyy"], 0], [p["IHxz"], 0, p["IHzz"]]]),
            "F": np.diag([p["IFxx"], p["IFyy"], p["IFxx"]])}


class Motion:
    """Positions of the point masses and rotations of the bodies along ``c + t c' + t**2 c'' / 2``,
    and their velocities and accelerations at ``t = 0`` by central differences (step ``h``)."""

    def __init__(self, geometry, c, rates, accelerations=None, h=1e-4):
        acc = np.zeros(10) if accelerations is None else accelerations
        poses = {t: geometry.pose(c + t * rates + t * t / 2 * acc) for t in (-h, 0.0, h)}
        masses = {t: geometry.masses(poses[t], c + t * rates + t * t / 2 * acc) for t in poses}
        self.velocities = [(a - b) / (2 * h) for (a, _), (b, _) in zip(masses[h], masses[-h])]
        self.accelerations = [(a - 2 * o + b) / h ** 2 for (a, _), (o, _), (b, _)
                              in zip(masses[h], masses[0.0], masses[-h])]
        self.masses = [m for _, m in masses[0.0]]
        self.rotations = {b: poses[0.0]["R" + b] for b in BODIES}
        self.omega = {b: _vee((poses[h]["R" + b] - poses[-h]["R" + b]) / (2 * h) @ poses[0.0]["R" + b].T)
                      for b in BODIES}
        self.alpha = {b: _vee((poses[h]["R" + b] - 2 * poses[0.0]["R" + b] + poses[-h]["R" + b]) / h ** 2
                              @ poses[0.0]["R" + b].T) for b in BODIES}
        pose = poses[0.0]
        point = lambda key: (geometry.pose(c + h * rates)[key] - geometry.pose(c - h * rates)[key]) / (2 * h)
        rear = point("R0") + np.cross(self.omega["R"], pose["PR"] - pose["R0"])
        front = point("F0") + np.cross(self.omega["F"], pose["PF"] - pose["F0"])
        self.slip = np.r_[rear[:2], front]
        """The contact points' material velocities: rear x, y; front x, y, z."""


INDEPENDENT = (3, 5, 6, 7, 8)
"""Roll, steer, frame twist, fork bending and the rear wheel's spin."""
DEPENDENT = (0, 1, 2, 4, 9)
"""x, y, yaw, pitch and front spin: given by the rolling constraints."""


def constrained_rates(geometry, c, independent):
    """The full rate vector (10,) at configuration ``c`` for the ``independent`` rates (5,)."""
    rates = np.zeros(10)
    rates[list(INDEPENDENT)] = independent
    G = np.column_stack([Motion(geometry, c, np.eye(10)[k]).slip for k in DEPENDENT])
    rates[list(DEPENDENT)] = np.linalg.solve(G, -Motion(geometry, c, rates).slip)
    return rates


def constrained_accelerations(geometry, c, rates, independent, tau=1e-5):
    """The full acceleration vector (10,) for the ``independent`` accelerations (5,): the constraints'
    rate of change along the motion is zero."""
    acc = np.zeros(10)
    acc[list(INDEPENDENT)] = independent
    G = np.column_stack([Motion(geometry, c, np.eye(10)[k]).slip for k in DEPENDENT])
    drift = (Motion(geometry, c + tau * rates, rates).slip - Motion(geometry, c - tau * rates, rates).slip) / (2 * tau)
    acc[list(DEPENDENT)] = np.linalg.solve(G, -Motion(geometry, c, acc).slip - drift)
    return acc


def kane_residual(p, v, q, u, a):
    """Kane's equations ``F_r + F*_r`` (4,) for the lateral speeds at the state ``q, u, a`` (lateral
    coordinates, rates, accelerations (4,) each), the rear wheel spinning at ``-v/rR``: numerically,
    every quantity from :class:`Geometry` (springs and dampers included: each damper's generalised force
    is minus its coefficient times its own coordinate's rate, a Rayleigh dissipation function)."""
    g = Geometry(p)
    c = np.zeros(10)
    c[list(LATERAL)] = q
    c = g.solve_pitch(c)
    rates = constrained_rates(g, c, np.r_[u, -v / p["rR"]])
    acc = constrained_accelerations(g, c, rates, np.r_[a, 0.0])
    motion = Motion(g, c, rates, acc)
    inertia = _inertias(p)
    out = np.zeros(4)
    for r in range(4):
        partial = Motion(g, c, constrained_rates(g, c, np.eye(5)[r]))
        total = 0.0
        for vr, m, acc_i in zip(partial.velocities, motion.masses, motion.accelerations):
            total += m * vr @ (np.array([0, 0, p["g"]]) - acc_i)
        for b in BODIES:
            I = motion.rotations[b] @ inertia[b] @ motion.rotations[b].T
            w = motion.omega[b]
            total += partial.omega[b] @ (-(I @ motion.alpha[b]) - np.cross(w, I @ w))
        out[r] = total
    out[2] -= p["kr"] * q[2] + p.get("cr", 0.0) * u[2]
    out[3] -= p["kf"] * q[3] + p.get("cf", 0.0) * u[3]
    out[1] -= p.get("cs", 0.0) * u[1]          # the steering bearing's damper: steer is D to H's rotation
    return out


def linear_matrices(p, v, eps=1e-4):
    """``(M, C, K)`` (4x4 each) at speed ``v`` from :func:`kane_residual` by central differences."""
    e = np.eye(4)
    z = np.zeros(4)
    def column(make):
        return -(kane_residual(p, v, *make(eps)) - kane_residual(p, v, *make(-eps))) / (2 * eps)
    M = np.column_stack([column(lambda s, k=k: (z, z, s * e[k])) for k in range(4)])
    C = np.column_stack([column(lambda s, k=k: (z, s * e[k], z)) for k in range(4)])
    K = np.column_stack([column(lambda s, k=k: (s * e[k], z, z)) for k in range(4)])
    return M, C, K
