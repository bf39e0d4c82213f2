"""Kane's equations of a constrained multibody system, linearised about a steady motion.

A :class:`System` has coordinates ``q`` (n) and speeds ``u`` (o) with kinematic differential
equations ``q' = N(q) u``, holonomic constraints ``f_c(q) = 0`` solved for the dependent coordinates
``q_D`` and nonholonomic constraints ``f_v(q, u) = A(q) u = 0`` (the time derivatives of ``f_c`` are
added) solved for the dependent speeds ``u_D``.  ``sympy.physics.mechanics.KanesMethod``, given
``q``, ``u`` and the kinematic equations but no constraints, forms the generalised active and
inertia forces ``H = F_r + F_r*`` of every speed as if all were independent.  With ``u_D = W(q) u_I``,
``W = -A_D^-1 A_I``, Kane's equations of the constrained system are ``G = H_I + W(q)^T H_D = 0``.

Linearised about a steady motion ``(q0, u0)`` (``u0' = 0``, inputs zero) that satisfies the
constraints::

    dG = [1 | W0^T] (H_q dq + H_u du + H_u' du' + H_r r) + dW^T H_D(0)
    dW = sum_k dW/dq_k dq_k,     dW/dq_k = -A_D^-1 (dA_D/dq_k W0 + dA_I/dq_k)

with the perturbations tied to the independent ones by the linearised constraints::

    dq  = Q dq_I                 dq_D = -(df_c/dq_D)^-1 df_c/dq_I dq_I
    du  = S du_I + T dq_I        du_D = W0 du_I + P dq,   P = -A_D^-1 d(A u0)/dq
    dq' = N0 du + d(N u0)/dq dq
    du' = S du_I' + [0; P] dq'

This is the linearisation that ``sympy.physics.mechanics.Linearizer`` performs (Peterson, Gede &
Hubbard 2014, Multibody System Dynamics 31), but every derivative is taken at the operating point
(:class:`~bikemass.models.derive.jet.Jet`) instead of solving the constraints for a general
configuration first: minutes there for the Whipple bicycle (docs/models.md, "The derivation"),
seconds here.
"""

from dataclasses import dataclass, field

import sympy as sm
import sympy.physics.mechanics as me

from .jet import Jet

TIME = me.dynamicsymbols._t


@dataclass
class System:
    """A constrained multibody system and the steady motion to linearise about.

    Attributes
    ----------
    frame : sympy.physics.vector.ReferenceFrame
        The inertial frame.
    coordinates, speeds : list of dynamicsymbols
        ``q`` and ``u``.
    kinematics : dict
        ``{q_i: q_i'}``: the kinematic differential equations, ``q_i'`` in terms of ``q`` and ``u``.
    bodies : list of sympy.physics.mechanics.RigidBody
    loads : list of (Point or ReferenceFrame, Vector)
    inputs : list of dynamicsymbols
        Forces and torques of ``loads`` that are inputs of the linear model (zero at the point).
    holonomic : list of expressions in ``q``
        ``f_c(q) = 0``; ``dependent_coordinates`` are solved from them.
    nonholonomic : list of expressions in ``q`` and ``u``, linear in ``u``
        ``f_v(q, u) = 0``; with the derivatives of ``holonomic`` they fix ``dependent_speeds``.
    point : dict
        Every coordinate and speed at the steady motion (accelerations and inputs are zero).
    """

    frame: object
    coordinates: list
    speeds: list
    kinematics: dict
    bodies: list = field(default_factory=list)
    loads: list = field(default_factory=list)
    inputs: list = field(default_factory=list)
    holonomic: list = field(default_factory=list)
    dependent_coordinates: list = field(default_factory=list)
    nonholonomic: list = field(default_factory=list)
    dependent_speeds: list = field(default_factory=list)
    point: dict = field(default_factory=dict)

    def velocity(self, vector):
        """``vector``'s time derivative in the inertial frame with ``q'`` replaced by ``N(q) u``."""
        return vector.dt(self.frame).xreplace(self.coordinate_rates)

    @property
    def coordinate_rates(self):
        """``{q_i'(t): N(q) u}`` for substitution."""
        return {q.diff(TIME): rate for q, rate in self.kinematics.items()}


@dataclass
class Linearised:
    """Kane's equations of a :class:`System` linearised about its steady motion.

    ``M du_I' + C du_I + K dq_I + F r = 0`` and ``dq_I' = Kq dq_I + Ku du_I`` (sympy matrices; the
    rows of ``M, C, K, F`` follow ``speeds``, the columns of ``K`` and ``Kq`` ``coordinates``, those of
    ``F`` ``inputs``).  :meth:`linear` gives any other expression of ``q`` and ``u`` to first order.
    """

    coordinates: list
    speeds: list
    inputs: list
    M: sm.Matrix
    C: sm.Matrix
    K: sm.Matrix
    F: sm.Matrix
    Kq: sm.Matrix
    Ku: sm.Matrix
    _jet: Jet = field(repr=False)
    _plain: dict = field(repr=False)
    _Q: sm.Matrix = field(repr=False)
    _S: sm.Matrix = field(repr=False)
    _T: sm.Matrix = field(repr=False)
    _q: list = field(repr=False)
    _u: list = field(repr=False)

    def linear(self, expr):
        """``(row_q, row_u)``: ``expr(q, u)`` to first order is ``value + row_q dq_I + row_u du_I``."""
        e = sm.sympify(expr).xreplace(self._plain)
        gq = sm.Matrix([self._jet.gradient(e, self._q)])
        gu = sm.Matrix([self._jet.gradient(e, self._u)])
        return gq * self._Q + gu * self._T, gu * self._S

    def value(self, expr):
        """``expr(q, u)`` at the steady motion."""
        return self._jet.value(sm.sympify(expr).xreplace(self._plain))


def _plain_symbols(system):
    """``{dynamicsymbol, its derivative: plain Symbol}`` for the coordinates, speeds, accelerations, inputs."""
    plain = {}
    for s in system.speeds:
        plain[s.diff(TIME)] = sm.Symbol(f"{s.func}'")
    for s in (*system.coordinates, *system.speeds, *system.inputs):
        plain[s] = sm.Symbol(str(s.func))
    return plain


def generalised_forces(system):
    """``H_r = F_r + F_r*`` of every speed ``u_r`` as if all were independent (Kane & Levinson 1985,
    Eq. 4.4.1 and 4.11.6): ``F_r = sum R . v_r + T . w_r`` over the loads, ``F_r* = sum -m a . v_r -
    (I . alpha + w x I . w) . w_r`` over the bodies, ``v_r`` and ``w_r`` the partial velocities."""
    N, rates, u = system.frame, system.coordinate_rates, system.speeds
    H = [sm.S.Zero] * len(u)

    def add(vector, velocity):
        for r, ur in enumerate(u):
            H[r] += vector & velocity.diff(ur, N)

    for body in system.bodies:
        v = body.masscenter.vel(N).xreplace(rates)
        w = body.frame.ang_vel_in(N).xreplace(rates)
        inertia = body.central_inertia
        add(-body.mass * system.velocity(v), v)
        add(-(inertia & system.velocity(w)) - w.cross(inertia & w), w)
    for where, load in system.loads:
        if isinstance(where, me.Point):
            add(load, where.vel(N).xreplace(rates))
        else:
            add(load, where.ang_vel_in(N).xreplace(rates))
    return sm.Matrix(H)


def linearise(system):
    """:class:`Linearised` equations of ``system`` about ``system.point``."""
    plain = _plain_symbols(system)
    q = [plain[s] for s in system.coordinates]
    u = [plain[s] for s in system.speeds]
    ud = [plain[s.diff(TIME)] for s in system.speeds]
    r = [plain[s] for s in system.inputs]
    H = generalised_forces(system).xreplace(plain)
    if H.has(sm.Derivative):
        raise ValueError("the generalised forces hold coordinate rates the kinematics do not give")
    rates = system.coordinate_rates
    fv = [c.xreplace(rates) for c in system.nonholonomic]
    fv += [c.diff(TIME).xreplace(rates) for c in system.holonomic]
    fv = sm.Matrix(fv).xreplace(plain)
    fc = sm.Matrix(system.holonomic).xreplace(plain)
    qdot = sm.Matrix([system.kinematics[s] for s in system.coordinates]).xreplace(plain)

    point = {plain[k]: v for k, v in system.point.items()}
    point.update({z: sm.S.Zero for z in (*ud, *r)})
    jet = Jet(point, (*q, *u, *ud, *r))

    def grad(exprs, zs):
        return sm.Matrix([jet.gradient(e, zs) for e in exprs])

    for c in fv:
        if sm.simplify(jet.value(c)) != 0:
            raise ValueError(f"the operating point violates the constraint {c} = 0")

    dep_q = [plain[s] for s in system.dependent_coordinates]
    dep_u = [plain[s] for s in system.dependent_speeds]
    if len(dep_u) != len(fv) or len(dep_q) != len(fc):
        raise ValueError(f"{len(fv)} velocity constraints for {len(dep_u)} dependent speeds, "
                         f"{len(fc)} configuration constraints for {len(dep_q)} dependent coordinates")
    ind_q = [z for z in q if z not in dep_q]
    ind_u = [z for z in u if z not in dep_u]
    iq, iu = [q.index(z) for z in ind_q], [u.index(z) for z in ind_u]
    jq, ju = [q.index(z) for z in dep_q], [u.index(z) for z in dep_u]

    # linearised configuration constraints: dq = Q dq_I
    Q = sm.zeros(len(q), len(ind_q))
    for a, i in enumerate(iq):
        Q[i, a] = 1
    if dep_q:
        J = grad(fc, q)
        theta = -J[:, jq].LUsolve(J[:, iq])
        for a, i in enumerate(jq):
            Q[i, :] = theta[a, :]

    # velocity constraints: A(q) u = 0
    A = fv.jacobian(u)
    if A.has(*u):
        raise ValueError("a velocity constraint that is not linear in the speeds")
    A0 = A.xreplace(point)
    AD, AI = A0[:, ju], A0[:, iu]
    W0 = -AD.LUsolve(AI)
    dA = grad(list(A), q)                                   # row (i, j) of A, column k: dA_ij/dq_k
    P = -AD.LUsolve(grad(fv, q))                             # fv = A u, so d(A u0)/dq = d fv/dq at u0
    S = sm.zeros(len(u), len(ind_u))
    T = sm.zeros(len(u), len(ind_q))
    PQ = P * Q
    for a, i in enumerate(iu):
        S[i, a] = 1
    for a, i in enumerate(ju):
        S[i, :] = W0[a, :]
        T[i, :] = PQ[a, :]
    Pfull = sm.zeros(len(u), len(q))
    for a, i in enumerate(ju):
        Pfull[i, :] = P[a, :]

    # kinematics: dq' = N0 du + d(N u0)/dq dq
    N0, Nq = grad(qdot, u), grad(qdot, q)
    Ku_all, Kq_all = N0 * S, N0 * T + Nq * Q

    G = sm.zeros(len(ind_u), len(u))
    for a, i in enumerate(iu):
        G[a, i] = 1
    for a, i in enumerate(ju):
        G[:, i] = W0[a, :].T
    Hq, Hu, Hud, Hr = grad(H, q), grad(H, u), grad(H, ud), grad(H, r)
    H0D = sm.Matrix([jet.value(H[i]) for i in ju])
    M = G * Hud * S
    C = G * (Hu * S + Hud * Pfull * Ku_all)
    K = G * (Hq * Q + Hu * T + Hud * Pfull * Kq_all)
    cols = A.shape[1]
    for k in range(len(q)):
        dAk = sm.Matrix(A.shape[0], cols, list(dA[:, k]))
        dW = -AD.LUsolve(dAk[:, ju] * W0 + dAk[:, iu])
        K += (dW.T * H0D) * Q[k, :]
    F = G * Hr
    return Linearised([system.coordinates[i] for i in iq], [system.speeds[i] for i in iu], list(system.inputs),
                      M, C, K, F, Kq_all.extract(iq, list(range(len(ind_q)))),
                      Ku_all.extract(iq, list(range(len(ind_u)))), jet, plain, Q, S, T, q, u)
