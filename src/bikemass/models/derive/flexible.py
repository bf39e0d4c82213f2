"""Kane's method for the Whipple bicycle with a twisting rear frame and a bending fork, linearised.

The model (argued in docs/models-flexible.md): the four bodies of Meijaard et al. (2007) -- rear frame B
(with the rider), rear wheel R, front frame H, front wheel F -- and two compliances, each a small rotation
about a line in the plane of symmetry:

* **frame twist** ``theta_r``: a massless head frame D (the head tube as the steer bearings see it) turns
  relative to B about the line through ``(xr, 0, zr)`` with direction ``(nrx, 0, nrz)``; H steers
  relative to D about the steer axis.  Torsional spring ``kr`` (N m/rad) between B and D.
* **fork bending** ``theta_f``: a massless hub frame E turns relative to H about the line through
  ``(xf, 0, zf)`` with direction ``(nfx, 0, nfz)``; F spins relative to E about its axle.  Spring ``kf``.

Coordinates are in the benchmark frame at the reference configuration (x forward, y right, z down,
origin the rear contact).  The tubes' own inertia in each compliance is the beam model's Ritz reduction
(:mod:`bikemass.fe.compliance`): the modal linear momentum ``L`` (kg m/rad), its moment about the origin
``(Jx, Jz)`` (kg m^2/rad) and the modal mass ``m`` (kg m^2/rad^2) of the deformation field relative to
its parent body (B for the frame, H for the fork).  In the linear equations these four numbers are all
that matters, so the field is represented exactly by a pair of particles: mass ``L^2/m`` at
``(Jz/L, 0, -Jx/L)`` displaced sideways by ``(m/L) theta`` in the parent's axes, and the same mass,
negative, fixed in the parent (the tubes' rigid mass is already in the parent's benchmark parameters).

The equations are linearised about the upright straight run at speed ``v`` by Kane's method to first
order: constrained partial velocities and inertia forces expanded about the reference motion (Kane &
Levinson 1985, ch. 6; the dependent speeds -- rear-contact velocity, yaw, pitch, front spin -- from the
five rolling constraints, the pitch's second-order dependence on the lateral coordinates through the
velocity constraint).  The result is::

    M q'' + v C1 q' + (K0 + v**2 K2) q = [T_phi, T_delta, 0, 0],   q = [phi, delta, theta_r, theta_f]

with ``K0`` including gravity ``g`` and the springs.  Run ``python -m bikemass.models.derive.flexible``
to regenerate :mod:`bikemass.models.generated.flexible_matrices`; it takes about a minute.
"""

import argparse
import sys
import textwrap
from pathlib import Path

import sympy as sm
import sympy.physics.mechanics as me
from sympy.printing.numpy import NumPyPrinter

RIGID = ("w", "c", "lam", "g", "rR", "mR", "IRxx", "IRyy", "xB", "zB", "mB", "IBxx", "IByy", "IBzz", "IBxz",
         "xH", "zH", "mH", "IHxx", "IHyy", "IHzz", "IHxz", "rF", "mF", "IFxx", "IFyy")
"""The 26 benchmark parameters (Meijaard et al. 2007, Table 1 order)."""
FRAME = ("xr", "zr", "nrx", "nrz", "kr", "Lr", "Jrx", "Jrz", "mr")
"""The frame twist: a point and the unit direction of its line, stiffness, modal L, J and mass."""
FORK = ("xf", "zf", "nfx", "nfz", "kf", "Lf", "Jfx", "Jfz", "mf")
"""The fork bending: the same for the fork's line (parent: the front frame)."""
PARAMETERS = RIGID + FRAME + FORK
COORDINATES = ("phi", "delta", "theta_r", "theta_f")
OUTPUTS = ("M", "C1", "K0", "K2")
HEADING = ("H0", "H1")
"""The heading (yaw of the rear frame): ``psi' = H0 . q' + v H1 . q`` (rows of length 4)."""


def _symbols():
    return {name: sm.Symbol(name, real=True) for name in PARAMETERS}


def _inertia(frame, xx, yy, zz, xz):
    return me.inertia(frame, xx, yy, zz, 0, 0, xz)


def small_rotation(name, parent, axis, angle):
    """A frame turned from ``parent`` by the small ``angle`` about the unit ``axis`` (components in
    ``parent``), its direction cosines to first order: ``I + angle [axis x]``.

    First order is all Kane's linearised equations need here: partial velocities, accelerations and
    the constraints' coefficients are used to first order in the coordinates (the pitch, of second
    order, enters through the velocity constraint's first-order coefficient; see :class:`_Expansion`).
    The angular velocity is set by the caller.
    """
    ax, ay, az = axis
    skew = sm.Matrix([[0, -az, ay], [az, 0, -ax], [-ay, ax, 0]])
    frame = me.ReferenceFrame(name)
    frame.orient_explicit(parent, sm.eye(3) + angle * skew)
    return frame


def build(p):
    """The kinematics and bodies of the model with parameter symbols ``p``.

    Returns a dict: ``frames``, ``q`` (orientation coordinates, lateral ones first), ``u_ind`` and
    ``u_dep`` (speeds), ``constraints`` (five velocity constraints, linear in the speeds), ``height``
    (the front contact's height, zero on the ground), ``bodies`` (name, point, frame, mass, inertia),
    ``particles`` (point, mass), ``springs`` and ``inputs``.
    """
    t = me.dynamicsymbols._t
    phi, delta, thr, thf, theta, psi = me.dynamicsymbols("phi delta theta_r theta_f theta psi")
    u = me.dynamicsymbols("u_phi u_delta u_thr u_thf u_R u_1 u_2 u_psi u_theta u_F")
    uphi, udelta, uthr, uthf, uR, u1, u2, upsi, utheta, uF = u
    sl, cl = sm.sin(p["lam"]), sm.cos(p["lam"])

    N = me.ReferenceFrame("N")
    A = small_rotation("A", N, (0, 0, 1), 0)                # yaw frame (its angle never matters)
    Lf = small_rotation("L", A, (1, 0, 0), phi)             # roll: the rear wheel's plane
    B = small_rotation("B", Lf, (0, 1, 0), theta)           # pitch: the rear frame
    R = small_rotation("R", B, (0, 1, 0), 0)                # rear wheel (axisymmetric: spin angle unused)
    D = small_rotation("D", B, (p["nrx"], 0, p["nrz"]), thr)     # head frame (frame twist)
    H = small_rotation("H", D, (sl, 0, cl), delta)          # front frame
    E = small_rotation("E", H, (p["nfx"], 0, p["nfz"]), thf)     # hub frame (fork bending)
    F = small_rotation("F", E, (0, 1, 0), 0)                # front wheel
    nr = p["nrx"] * B.x + p["nrz"] * B.z
    steer = sl * D.x + cl * D.z
    nf = p["nfx"] * H.x + p["nfz"] * H.z
    A.set_ang_vel(N, upsi * N.z)
    Lf.set_ang_vel(A, uphi * A.x)
    B.set_ang_vel(Lf, utheta * Lf.y)
    R.set_ang_vel(B, uR * B.y)
    D.set_ang_vel(B, uthr * nr)
    H.set_ang_vel(D, udelta * steer)
    E.set_ang_vel(H, uthf * nf)
    F.set_ang_vel(E, uF * E.y)

    O = me.Point("O")
    O.set_vel(N, 0)
    PR = O.locatenew("P_R", me.dynamicsymbols("x") * N.x + me.dynamicsymbols("y") * N.y)
    PR.set_vel(N, u1 * A.x + u2 * A.y)
    R0 = PR.locatenew("R0", -p["rR"] * Lf.z)                 # rear axle
    R0.set_vel(Lf, 0)
    R0.v1pt_theory(PR, N, Lf)

    def fixed(name, base, frame, X, Z, Y=0, origin=(0, 0)):
        """A point fixed in ``frame`` at benchmark (X, Y, Z) in the reference configuration."""
        point = base.locatenew(name, (X - origin[0]) * frame.x + Y * frame.y + (Z - origin[1]) * frame.z)
        point.v2pt_theory(base, N, frame)
        return point

    rear_origin = (0, -p["rR"])                              # R0 in benchmark coordinates
    Bcm = fixed("B_cm", R0, B, p["xB"], p["zB"], origin=rear_origin)
    Zr = fixed("Z_r", R0, B, p["xr"], p["zr"], origin=rear_origin)
    S0 = fixed("S_0", Zr, D, p["w"] + p["c"], 0, origin=(p["xr"], p["zr"]))   # steer axis at the ground
    Hcm = fixed("H_cm", S0, H, p["xH"], p["zH"], origin=(p["w"] + p["c"], 0))
    Zf = fixed("Z_f", S0, H, p["xf"], p["zf"], origin=(p["w"] + p["c"], 0))
    F0 = fixed("F_0", Zf, E, p["w"], -p["rF"], origin=(p["xf"], p["zf"]))     # front axle
    F0.set_vel(F, 0)

    # the wheels' contact points: rear below the axle in the wheel plane; front the same for F's plane
    down = N.z - N.z.dot(E.y) * E.y
    PF = F0.locatenew("P_F", p["rF"] * down / sm.sqrt(down.dot(down)))
    slip_rear = R0.vel(N) + R.ang_vel_in(N).cross(PR.pos_from(R0))
    slip_front = F0.vel(N) + F.ang_vel_in(N).cross(PF.pos_from(F0))
    constraints = [slip_rear.dot(A.x), slip_rear.dot(A.y), slip_front.dot(A.x), slip_front.dot(A.y),
                   slip_front.dot(N.z)]
    height = PF.pos_from(PR).dot(N.z)

    # the Ritz fields of the tubes as particle pairs (see the module doc)
    particles = []
    for parent, base, origin, (L, Jx, Jz, m), coordinate, axis in (
            (B, R0, rear_origin, (p["Lr"], p["Jrx"], p["Jrz"], p["mr"]), thr, B.y),
            (H, S0, (p["w"] + p["c"], 0), (p["Lf"], p["Jfx"], p["Jfz"], p["mf"]), thf, H.y)):
        mass = L ** 2 / m
        at = fixed(f"rigid_{parent.name}", base, parent, Jz / L, -Jx / L, origin=origin)
        moved = at.locatenew(f"modal_{parent.name}", (m / L) * coordinate * axis)
        moved.set_vel(parent, (m / L) * (uthr if coordinate is thr else uthf) * axis)
        moved.v1pt_theory(at, N, parent)
        particles += [(moved, mass), (at, -mass)]

    bodies = [
        ("B", Bcm, B, p["mB"], _inertia(B, p["IBxx"], p["IByy"], p["IBzz"], p["IBxz"])),
        ("R", R0, R, p["mR"], _inertia(B, p["IRxx"], p["IRyy"], p["IRxx"], 0)),     # axisymmetric
        ("H", Hcm, H, p["mH"], _inertia(H, p["IHxx"], p["IHyy"], p["IHzz"], p["IHxz"])),
        ("F", F0, F, p["mF"], _inertia(E, p["IFxx"], p["IFyy"], p["IFxx"], 0)),
    ]
    return {
        "frames": {"N": N, "A": A, "L": Lf, "B": B, "R": R, "D": D, "H": H, "E": E, "F": F},
        "q": [phi, delta, thr, thf, theta, psi], "q_dot": {x.diff(t): y for x, y in (
            (phi, uphi), (delta, udelta), (thr, uthr), (thf, uthf), (theta, utheta), (psi, upsi))},
        "u_ind": [uphi, udelta, uthr, uthf, uR], "u_dep": [u1, u2, upsi, utheta, uF],
        "constraints": constraints, "height": height, "bodies": bodies, "particles": particles,
        "steer_axis": steer, "N": N, "t": t,
    }


class _Expansion:
    """First-order expansions about the reference motion: every coordinate zero, the rear wheel spinning
    at ``-v/rR`` (about its axle, y to the right), the other speeds as the constraints give them.

    Works on plain symbols (the dynamic symbols replaced once): ``q`` the lateral coordinates,
    ``qh``, ``uh``, ``ah`` their first-order values, rates and accelerations.
    """

    def __init__(self, model, p, v):
        t = model["t"]
        self.N = model["N"]
        speeds = model["u_ind"] + model["u_dep"]
        plain = {x: sm.Symbol(x.name, real=True) for x in model["q"] + speeds}
        self.udot = [sm.Symbol(x.name + "_dot", real=True) for x in speeds]
        self._subs = {**{x.diff(t): d for x, d in zip(speeds, self.udot)},
                      **{q: plain[u] for q, u in model["q_dot"].items()}, **plain}
        self.q = [plain[x] for x in model["q"][:4]]
        self.all_q = [plain[x] for x in model["q"]]
        self.ui = [plain[x] for x in model["u_ind"]]
        self.ud = [plain[x] for x in model["u_dep"]]
        self.qh = sm.symbols("qh_phi qh_delta qh_thr qh_thf", real=True)
        self.uh = sm.symbols("uh_phi uh_delta uh_thr uh_thf", real=True)
        self.ah = sm.symbols("ah_phi ah_delta ah_thr ah_thf", real=True)
        self.u0 = [0, 0, 0, 0, -v / p["rR"]]
        self.q_zero = {x: 0 for x in self.all_q}
        self._eps = sm.Symbol("epsilon")
        self._constraint_matrices(sm.Matrix(model["constraints"]))

    def plain(self, expr):
        """``expr`` (scalar or matrix) with the dynamic symbols and their derivatives replaced."""
        return me.msubs(expr, self._subs)

    def matrix(self, vector):
        """The components of ``vector`` in N, in plain symbols."""
        return self.plain(vector.to_matrix(self.N))

    def _constraint_matrices(self, constraints):
        f = self.plain(constraints)
        Ai, Ad = f.jacobian(self.ui), f.jacobian(self.ud)
        Ad0, Ai0 = (X.subs(self.q_zero).applyfunc(sm.cancel) for X in (Ad, Ai))
        Ad0inv = Ad0.inv().applyfunc(sm.cancel)
        self.C0 = (-Ad0inv * Ai0).applyfunc(sm.cancel)      # u_dep = C(q) u_ind at the reference
        self.dC = []                                        # dC/dq_j at the reference
        for qj in self.q:
            dAi, dAd = (self._along(X, {qj: 1}).applyfunc(sm.cancel) for X in (Ai, Ad))
            self.dC.append((-Ad0inv * (dAi + dAd * self.C0)).applyfunc(sm.cancel))
        u0 = sm.Matrix(self.u0)
        self.ud0 = self.C0 * u0
        du, da = sm.zeros(len(self.ud), 1), sm.zeros(len(self.ud), 1)
        for j in range(4):
            du += self.C0[:, j] * self.uh[j] + self.dC[j] * u0 * self.qh[j]
            da += self.C0[:, j] * self.ah[j] + self.dC[j] * u0 * self.uh[j]
        self.du = list(self.uh) + [0] + list(du)          # first-order parts of every speed
        self.da = list(self.ah) + [0] + list(da)          # and of its derivative
        self.reference = {**self.q_zero, **dict(zip(self.ui, self.u0)), **dict(zip(self.ud, self.ud0)),
                          **{x: 0 for x in self.udot}}

    def _along(self, X, direction):
        """The derivative of ``X`` (scalar or matrix) at zero coordinates along ``direction``
        ({coordinate: rate}; the other coordinates held at zero)."""
        eps = self._eps
        moved = {x: eps * direction.get(x, 0) for x in self.all_q}
        return sm.sympify(X).xreplace(moved).diff(eps).xreplace({eps: 0})

    def first_order(self, expr):
        """The first-order part of the scalar ``expr`` (plain symbols): every variable set to its
        reference value plus ``eps`` times its first-order part, differentiated at ``eps = 0``."""
        eps = self._eps
        moved = {**{qj: eps * qh for qj, qh in zip(self.q, self.qh)},
                 **{x: self.reference[x] + eps * dx for x, dx in zip(self.ui + self.ud, self.du)},
                 **{x: eps * dx for x, dx in zip(self.udot, self.da)},
                 **{x: 0 for x in self.all_q[4:]}}
        return sm.expand(expr.xreplace(moved).diff(eps).xreplace({eps: 0}))

    def partial(self, vector, r):
        """Constrained partial velocity for the independent speed ``r`` of ``vector`` (a velocity, linear
        in the speeds): ``(at the reference, first-order part)``, components in N."""
        comps = self.matrix(vector)
        parts = [comps.diff(x) for x in self.ui + self.ud]
        base = parts[r] + sum((parts[5 + d] * self.C0[d, r] for d in range(5)), sm.zeros(3, 1))
        zero = base.xreplace(self.q_zero)
        first = self._along(base, dict(zip(self.q, self.qh)))
        for j, qh in enumerate(self.qh):
            first += sum((parts[5 + d].xreplace(self.q_zero) * self.dC[j][d, r] for d in range(5)),
                         sm.zeros(3, 1)) * qh
        return zero, first


def linear_equations(p, v):
    """``(M, C, K)`` (4x4 sympy matrices) of the linearised equations at speed symbol ``v``."""
    model = build(p)
    x = _Expansion(model, p, v)
    N = model["N"]
    gravity = sm.Matrix([0, 0, p["g"]])
    inertial = []                        # (point, frame or None, mass, first-order a, first-order torque)
    for name, point, frame, mass, inertia in model["bodies"]:
        omega = frame.ang_vel_in(N)
        torque = -(inertia.dot(frame.ang_acc_in(N)) + omega.cross(inertia.dot(omega)))
        inertial.append((point, frame, mass, x.matrix(point.acc(N)).applyfunc(x.first_order),
                         x.matrix(torque).applyfunc(x.first_order)))
    for point, mass in model["particles"]:
        inertial.append((point, None, mass, x.matrix(point.acc(N)).applyfunc(x.first_order), None))
    rows = []
    for r in range(4):
        total = 0
        for point, frame, mass, a1, t1 in inertial:
            v0, v1 = x.partial(point.vel(N), r)
            total += mass * (v1.T * gravity)[0] - mass * (v0.T * a1)[0]
            if frame is not None:
                w0, _ = x.partial(frame.ang_vel_in(N), r)
                total += (w0.T * t1)[0]
        rows.append(sm.expand(total))
    springs = {2: p["kr"] * x.qh[2], 3: p["kf"] * x.qh[3]}
    for r, force in springs.items():
        rows[r] -= force
    residual = sm.Matrix(rows)                               # = -(M a + C u + K q) (inputs aside)
    M = -residual.jacobian(x.ah)
    C = -residual.jacobian(x.uh)
    K = -residual.jacobian(x.qh)
    return M, C, K, x


def coefficients(p):
    """``{"M", "C1", "K0", "K2", "H0", "H1"}``: the equations' matrices as coefficients of powers of ``v``,
    and the heading's rate (:data:`HEADING`).

    Raises AssertionError if ``M`` depends on ``v``, ``C`` is not ``v C1`` or ``K`` not ``K0 + v**2 K2``.
    """
    v = sm.Symbol("v", real=True)
    M, C, K, x = linear_equations(p, v)
    M, C, K = (X.applyfunc(lambda e: sm.expand(e)) for X in (M, C, K))
    assert all(sm.Poly(e, v).degree() <= 0 for e in M if e != 0), "M depends on v"
    C1 = C.applyfunc(lambda e: sm.expand(e / v))
    assert all(not e.has(v) for e in C1), "C is not linear in v"
    K0 = K.applyfunc(lambda e: e.subs(v, 0))
    K2 = K.applyfunc(lambda e: sm.expand((e - e.subs(v, 0)) / v ** 2))
    assert all(not e.has(v) for e in K2), "K is not K0 + v**2 K2"
    yaw = x.ud.index(next(u for u in x.ud if u.name == "u_psi"))
    H0 = sm.Matrix([[sm.cancel(x.C0[yaw, j]) for j in range(4)]])
    u0 = sm.Matrix(x.u0)
    H1 = sm.Matrix([[sm.cancel((x.dC[j] * u0)[yaw] / v) for j in range(4)]])
    assert not any(e.has(v) for e in H1), "the heading's rate is not linear in v"
    return {"M": M, "C1": C1, "K0": K0, "K2": K2, "H0": H0, "H1": H1}


HEADER = '''"""Generated by ``python -m bikemass.models.derive.flexible`` (do not edit): the linearised equations
of the Whipple bicycle with a twisting rear frame and a bending fork, by Kane's method
(:mod:`bikemass.models.derive.flexible`, docs/models-flexible.md)::

    M q'' + v C1 q' + (K0 + v**2 K2) q = [T_phi, T_delta, 0, 0],   q = [phi, delta, theta_r, theta_f]
    psi' = H0 . q' + v H1 . q                                      (the rear frame's heading)

The functions take the parameters as numbers or as numpy arrays of one shape (elementwise).
"""

import numpy

PARAMETERS = (
{parameters})
"""The parameters the functions read, in order (SI; docs/models-flexible.md)."""


def _shape(p):
    return numpy.broadcast_shapes(*(numpy.shape(p[k]) for k in PARAMETERS))
'''

MATRICES_DOC = '''    """``(M, C1, K0, K2)``, each of shape ``(*shape, 4, 4)``, of the parameters ``p`` (a mapping from
    every name of :data:`PARAMETERS` to a number or an array, all of one ``shape``).

    ``M`` kg m^2, ``C1`` kg m^2 (times v), ``K0`` N m/rad (gravity and springs), ``K2`` kg (times v**2);
    rows and columns roll, steer, frame twist, fork bending (rad).
    """'''
HEADING_DOC = '''    """``(H0, H1)``, each of shape ``(*shape, 4)``: the heading's rate ``psi' = H0 . q' + v H1 . q``
    (``H0`` dimensionless, ``H1`` 1/m)."""'''


def _function(name, doc, blocks, printer):
    """The source of one generated function returning ``blocks`` (a list of sympy matrices of one shape)."""
    rows, cols = blocks[0].shape
    flat = [b[i, j] for b in blocks for i in range(rows) for j in range(cols)]
    replacements, reduced = sm.cse(flat, symbols=sm.numbered_symbols("x"))
    used = set().union(*(e.free_symbols for e in flat))
    lines = [f"def {name}(p):", doc]
    lines += [f"    {k} = p[{k!r}]" for k in PARAMETERS if sm.Symbol(k, real=True) in used]
    lines += [f"    {symbol} = {printer.doprint(expr)}" for symbol, expr in replacements]
    shape = f"(*_shape(p), {rows}, {cols})" if rows > 1 else f"(*_shape(p), {cols})"
    lines.append(f"    out = numpy.zeros(({len(blocks)}, {shape[1:]})")
    for index, expr in enumerate(reduced):
        if expr != 0:
            k, i, j = index // (rows * cols), index // cols % rows, index % cols
            lines.append(f"    out[{k}, ..., {i}, {j}] = {printer.doprint(expr)}" if rows > 1 else
                         f"    out[{k}, ..., {j}] = {printer.doprint(expr)}")
    lines.append(f"    return {', '.join(f'out[{k}]' for k in range(len(blocks)))}")
    return "\n".join(lines)


def generate(out=None, mats=None):
    """Derive the equations (or take ``mats``, :func:`coefficients`' result) and write the numpy module
    to ``out``; returns the module's text."""
    mats = coefficients(_symbols()) if mats is None else mats
    printer = NumPyPrinter({"fully_qualified_modules": True})
    names = textwrap.fill(", ".join(repr(k) for k in PARAMETERS) + ",", 100, initial_indent="    ",
                          subsequent_indent="    ")
    text = "\n\n\n".join([HEADER.format(parameters=names).rstrip("\n"),
                           _function("matrices", MATRICES_DOC, [mats[k] for k in OUTPUTS], printer),
                           _function("heading", HEADING_DOC, [mats[k] for k in HEADING], printer)]) + "\n"
    if out is not None:
        Path(out).write_text(text)
    return text


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default = Path(__file__).resolve().parents[1] / "generated" / "flexible_matrices.py"
    parser.add_argument("-o", "--out", default=str(default), help="the generated module (default: %(default)s)")
    args = parser.parse_args(argv)
    generate(args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
