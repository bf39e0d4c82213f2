"""One member combination, derived: the linear model's states and its matrices as polynomials in speed.

:func:`derive` assembles the bicycle with the members on (:mod:`~bikemass.models.derive.bicycle`),
linearises Kane's equations about the upright straight run at speed ``v``
(:mod:`~bikemass.models.derive.kane`) and writes the result in descriptor form::

    E x' = sum_k v**k A[k] x + B u

with the states ``x`` in the order of the linear model: the dynamic coordinates (roll, steer, the
members' own), their rates, the members' further speeds (yaw rate, lateral velocity: a tyre lets the
wheels slip), the members' first-order states (tyre forces), then the kinematic states heading and
lateral position.  ``E`` does not depend on speed.  The cyclic coordinates (forward position, wheel
rotations) and the forward speed's own perturbation (it decouples from the lateral motion) are left
out; :func:`derive` checks that nothing kept depends on them.

Entries that vanish identically (``sin**2 + cos**2 - 1``, which the derivation does not simplify)
are found by evaluating at random parameter points with 40 digits and set to an exact zero.
"""

import random
from dataclasses import dataclass

import mpmath
import sympy as sm

from .bicycle import assemble
from .kane import linearise

DEGREE = 2
"""Highest power of the speed in the equations of motion (centrifugal terms, ``v**2``)."""
_INPUT_ORDER = {"roll_torque": 0, "steer_torque": 1}
_DIGITS = 40
_ZERO = mpmath.mpf(10) ** (-30)


@dataclass(frozen=True)
class Derived:
    """A member combination's linear model, symbolically.

    ``E`` (N, N), ``A`` and ``B`` (lists of ``DEGREE + 1`` matrices, coefficients of ``v**k``) as
    sympy matrices over the parameters ``parameters`` ((name, unit, description), the order of the
    generated function's arguments).  ``states`` and ``inputs`` are (name, unit); the first
    ``n_dynamic`` states are dynamic; ``families`` maps a family name to state indices;
    ``coordinates`` counts the dynamic mechanical coordinates (states ``[q, q']`` first) and
    ``second_order`` says whether the dynamic states are exactly ``[q, q']``.
    """

    name: str
    members: tuple
    parameters: tuple
    states: tuple
    n_dynamic: int
    inputs: tuple
    families: tuple
    coordinates: int
    second_order: bool
    E: sm.Matrix
    A: tuple
    B: tuple


def _order(dynamic):
    """Dynamic coordinates: the bicycle's (roll, steer) first, then the members' in the order they came."""
    return sorted(dynamic, key=lambda c: c.family != "bicycle")


class _ZeroTest:
    """Is an expression identically zero?  Evaluated at random points of its symbols (40 digits)."""

    def __init__(self, seed=2007):
        self._rng = random.Random(seed)
        self._points = {}

    def _value(self, symbol, k):
        key = (symbol, k)
        if key not in self._points:
            self._points[key] = mpmath.mpf(self._rng.uniform(0.3, 1.3))
        return self._points[key]

    def __call__(self, expr):
        expr = sm.sympify(expr)
        if expr == 0:
            return True
        symbols = sorted(expr.free_symbols, key=str)
        f = sm.lambdify(symbols, expr, "mpmath")
        with mpmath.workdps(_DIGITS):
            return all(abs(f(*(self._value(s, k) for s in symbols))) < _ZERO for k in range(3))


def _coefficients(expr, v, is_zero):
    """``[c_0, ..., c_DEGREE]`` with ``expr = sum_k c_k v**k``; ValueError if ``expr`` is not such a polynomial."""
    out, term = [], expr
    for k in range(DEGREE + 1):
        c = term.xreplace({v: 0}) / sm.factorial(k)
        out.append(sm.S.Zero if is_zero(c) else c)
        term = term.diff(v)
    if not is_zero(expr - sum(c * v ** k for k, c in enumerate(out))):
        raise ValueError(f"not a polynomial of degree {DEGREE} in the speed: {expr}")
    return out


def derive(members):
    """:class:`Derived` model of the Whipple bicycle with ``members`` (sequence of
    :class:`~bikemass.models.derive.bicycle.Member`, in the canonical order) on."""
    bike = assemble(members)
    linear = linearise(bike.system())
    extras = [x for m in members for x in m.states(bike, linear)]
    v, is_zero = bike.speed, _ZeroTest()

    dynamic = _order(bike.dynamic)
    kinematic = [(bike.heading, "heading", "rad"), (bike.lateral, "lateral", "m")]
    speeds = [*[c.u for c in dynamic], *[u for u, *_ in bike.extra_speeds]]
    coordinates = [c.q for c in dynamic]
    states = [*[(c.name, c.unit) for c in dynamic], *[(c.rate, f"{c.unit}/s") for c in dynamic],
              *[(name, unit) for _, name, unit, _ in bike.extra_speeds], *[(x.name, x.unit) for x in extras],
              *[(name, unit) for _, name, unit in kinematic]]
    n_dynamic = len(states) - len(kinematic)
    column = {**{q: i for i, q in enumerate(coordinates)},
              **{u: len(coordinates) + i for i, u in enumerate(speeds)},
              **{x.input: len(coordinates) + len(speeds) + i for i, x in enumerate(extras)},
              **{q: n_dynamic + i for i, (q, _, _) in enumerate(kinematic)}}
    N = len(states)
    forces = {x.input for x in extras}
    torques = sorted((r for r in linear.inputs if r not in forces), key=lambda r: _INPUT_ORDER.get(str(r.func), 2))
    E, A, B = sm.zeros(N, N), sm.zeros(N, N), sm.zeros(N, len(torques))

    def place(row, coefficients, symbols, what):
        for s, value in zip(symbols, coefficients):
            if s in column:
                A[row, column[s]] += value
            elif not is_zero(value):
                raise ValueError(f"{states[row][0]} depends on {s}, which the linear model leaves out ({what})")

    qi = {q: i for i, q in enumerate(linear.coordinates)}
    ui = {u: i for i, u in enumerate(linear.speeds)}
    kinematic_rows = [(c.q, i) for i, c in enumerate(dynamic)] + [(q, n_dynamic + k) for k, (q, _, _) in enumerate(kinematic)]
    for q, row in kinematic_rows:
        E[row, row] = 1
        place(row, linear.Kq.row(qi[q]), linear.coordinates, "kinematics")
        place(row, linear.Ku.row(qi[q]), linear.speeds, "kinematics")
    for k, u in enumerate(speeds):
        row, eq = len(coordinates) + k, ui[u]
        for s, value in zip(linear.speeds, linear.M.row(eq)):
            if s in column:
                E[row, column[s]] = -value
            elif not is_zero(value):
                raise ValueError(f"{states[row][0]} is coupled by inertia to {s}, which the model leaves out")
        place(row, linear.C.row(eq), linear.speeds, "damping")
        place(row, linear.K.row(eq), linear.coordinates, "stiffness")
        for j, r in enumerate(linear.inputs):
            if r in torques:
                B[row, torques.index(r)] = linear.F[eq, j]
            else:
                A[row, column[r]] += linear.F[eq, j]
    for k, x in enumerate(extras):
        row = len(coordinates) + len(speeds) + k
        E[row, row] = x.tau
        place(row, x.row_q, linear.coordinates, x.name)
        place(row, x.row_u, linear.speeds, x.name)
        A[row, row] += x.self_term

    lam = bike.p("lam")
    tidy = {sm.sin(lam) ** 2: 1 - sm.cos(lam) ** 2}       # the steer frame's turn by lam and back
    E = E.applyfunc(lambda e: sm.S.Zero if is_zero(e) else e.subs(tidy))
    if E.has(v):
        raise ValueError("the mass matrix depends on the speed")
    Ak = [sm.zeros(N, N) for _ in range(DEGREE + 1)]
    Bk = [sm.zeros(N, len(torques)) for _ in range(DEGREE + 1)]
    for target, source in ((Ak, A), (Bk, B)):
        for i in range(source.rows):
            for j in range(source.cols):
                for k, c in enumerate(_coefficients(source[i, j], v, is_zero)):
                    target[k][i, j] = c.subs(tidy)

    families = {}
    for i, c in enumerate(dynamic):
        families.setdefault(c.family, []).extend([i, len(dynamic) + i])
    for i, (_, _, _, family) in enumerate(bike.extra_speeds):
        families.setdefault(family, []).append(2 * len(dynamic) + i)
    for i, x in enumerate(extras):
        families.setdefault(x.family, []).append(len(coordinates) + len(speeds) + i)
    names = [m.name for m in members]
    return Derived(name="+".join(names) or "whipple", members=tuple(names),
                   parameters=tuple((k, bike.units[k], bike.descriptions[k]) for k in bike.parameters),
                   states=tuple(states), n_dynamic=n_dynamic,
                   inputs=tuple(bike.input_names[bike.inputs.index(r)] for r in torques),
                   families=tuple((f, tuple(sorted(ix))) for f, ix in families.items()),
                   coordinates=len(coordinates), second_order=not bike.extra_speeds and not extras,
                   E=E, A=tuple(Ak), B=tuple(Bk))
