"""The nonlinear Whipple bicycle: Kane's equations in full, written as numeric code.

The multibody system is the one the linear models are derived from
(:func:`~bikemass.models.derive.bicycle.assemble` with no member: the 26 benchmark parameters, the
frames and points of :mod:`~bikemass.models.derive.bicycle`), so that the nonlinear equations reduce
to the linear ones about the upright straight run.  Coordinates ``q`` (8)::

    x, y     rear contact (m)           psi  heading (yaw)     phi    roll
    theta    pitch (dependent)          betaR, betaF  wheel rotations   delta  steer

and speeds ``u`` (8): ``u_lon, u_lat`` (the rear contact's velocity along and across the heading)
and the rates of the other coordinates.  What is written out, as functions of the configuration
(``phi, theta, delta``: nothing depends on the position or heading, which the derivation checks):

- ``H = F_r + F_r*`` of every speed as if all were independent (Kane & Levinson 1985; the same
  :func:`~bikemass.models.derive.kane.generalised_forces` as the linear family), split as
  ``H = -M(q) u' + F(q, u, r)``;
- the velocity constraints ``A(q) u = 0`` (rolling without slip at both contacts, and the time
  derivative of the holonomic constraint) and ``b = A'(q, u) u`` so that ``A u' + b = 0``;
- the holonomic constraint ``f(q) = 0`` (the front contact on the ground) and its gradient;
- the kinetic and potential energy (the ground as zero height) and the heights of the frames'
  centres of mass.

Kane's equations of the constrained system, ``W^T`` projecting onto the independent speeds, are
then formed numerically (:mod:`bikemass.models.nonlinear`): the symbolic solution of the
constraints for the dependent speeds, which swells the expressions, is never formed.
"""

import random
from dataclasses import dataclass

import sympy as sm

from .bicycle import assemble
from .kane import TIME, generalised_forces

MODULE = "nonlinear_whipple"
"""The generated module's name (in :mod:`bikemass.models.generated`)."""
CONFIGURATION = ("phi", "theta", "delta")
"""The coordinates the written expressions depend on (roll, pitch, steer)."""


@dataclass(frozen=True)
class NonlinearDerived:
    """The nonlinear Whipple bicycle, symbolically (see the module docstring).

    ``parameters`` ((name, unit, meaning)); ``coordinates``, ``speeds``, ``inputs``: the names of
    ``q``, ``u`` and ``r`` in order; ``dependent``: indices of the dependent speeds; ``groups``:
    ``{function name: (argument symbols, {output name: sympy Matrix})}``.
    """

    parameters: tuple
    coordinates: tuple
    speeds: tuple
    inputs: tuple
    dependent: tuple
    groups: dict


def derive_nonlinear():
    """:class:`NonlinearDerived` of the Whipple bicycle (a few seconds)."""
    bike = assemble([])
    system = bike.system()
    N, origin = bike.frame, bike.points["O"]
    rates = system.coordinate_rates
    q = [sm.Symbol(str(s.func)) for s in system.coordinates]
    u = [sm.Symbol(str(s.func)) for s in system.speeds]
    ud = [sm.Symbol(f"{s.func}_dot") for s in system.speeds]
    r = [sm.Symbol(str(s.func)) for s in system.inputs]
    plain = {s.diff(TIME): z for s, z in zip(system.speeds, ud)}
    plain.update({s: z for s, z in zip((*system.coordinates, *system.speeds, *system.inputs), (*q, *u, *r))})
    heading = {q[system.coordinates.index(bike.heading)]: 0}        # nothing depends on it: checked below

    def written(expr):
        e = sm.sympify(expr).xreplace(plain)
        if e.has(sm.Derivative):
            raise ValueError("an expression holds coordinate rates the kinematics do not give")
        return e

    H = generalised_forces(system).applyfunc(written)
    M = -H.jacobian(ud)
    F = H.xreplace({z: 0 for z in ud})
    if M.has(*u, *r, *ud):
        raise ValueError("the generalised inertia forces are not linear in the accelerations")
    fv = [written(c.xreplace(rates)) for c in system.nonholonomic]
    fv += [written(c.diff(TIME).xreplace(rates)) for c in system.holonomic]
    fv = sm.Matrix(fv)
    A = fv.jacobian(u)
    if A.has(*u):
        raise ValueError("a velocity constraint that is not linear in the speeds")
    qdot = sm.Matrix([written(system.kinematics[s]) for s in system.coordinates])
    b = sm.Matrix([sum((A[i, j].diff(qk) * qdot[k] * u[j] for j in range(len(u)) for k, qk in enumerate(q)),
                       sm.S.Zero) for i in range(A.rows)])
    f = written(system.holonomic[0])
    config = [q[[str(s.func) for s in system.coordinates].index(n)] for n in CONFIGURATION]
    gradient = sm.Matrix([f]).jacobian(config)

    kinetic = sm.S.Zero
    potential = sm.S.Zero
    heights = []
    g = bike.p("g")
    for body in system.bodies:
        v = body.masscenter.vel(N).xreplace(rates)
        w = body.frame.ang_vel_in(N).xreplace(rates)
        kinetic += body.mass * (v & v) / 2 + (w & (body.central_inertia & w)) / 2
        height = -(body.masscenter.pos_from(origin) & N.z)
        potential += body.mass * g * height
        heights.append(height)
    kinetic, potential = written(kinetic), written(potential)
    heights = [written(h) for h in heights]

    free = set(config) | set(u) | set(r) | set(bike.parameters.values())
    groups = {
        "holonomic": (config, {"f": sm.Matrix([f]), "gradient": gradient}),
        "constraints": (config, {"A": A}),
        "dynamics": (config + u + r, {"M": M, "F": F, "b": b}),
        "energy": (config + u, {"energy": sm.Matrix([kinetic, potential])}),
        "heights": (config, {"heights": sm.Matrix(heights)}),
    }
    for name, (args, outputs) in groups.items():
        for key, matrix in outputs.items():
            matrix = matrix.xreplace(heading)
            outputs[key] = matrix
            extra = set().union(*(e.free_symbols for e in matrix)) - free
            if extra:
                raise ValueError(f"{name}/{key} depends on {sorted(map(str, extra))}")
    names = [str(s.func) for s in system.speeds]
    dependent = tuple(names.index(str(s.func)) for s in system.dependent_speeds)
    return NonlinearDerived(
        parameters=tuple((k, bike.units[k], bike.descriptions[k]) for k in bike.parameters),
        coordinates=tuple(str(s.func) for s in system.coordinates), speeds=tuple(names),
        inputs=tuple(name for name, _ in bike.input_names), dependent=dependent, groups=groups)


def _check_heading_free(matrix, heading, what, seed=33):
    """ValueError unless ``matrix`` is the same at two headings (every other symbol at a random value)."""
    (psi, _), = heading.items()
    symbols = sorted(set().union(*(e.free_symbols for e in matrix)) - {psi}, key=str)
    if psi not in set().union(*(e.free_symbols for e in matrix)):
        return
    rng = random.Random(seed)
    point = [rng.uniform(0.2, 1.2) for _ in symbols]
    f = sm.lambdify([psi, *symbols], list(matrix), "math", cse=True)
    a, b = f(0.0, *point), f(1.1, *point)
    scale = max(1.0, max(abs(float(x)) for x in a))
    if max(abs(float(x) - float(y)) for x, y in zip(a, b)) > 1e-9 * scale:
        raise ValueError(f"{what} depends on the heading")


PREFIX = {"holonomic": "f", "constraints": "a", "dynamics": "d", "energy": "e", "heights": "z"}
"""The names of each function's common subexpressions (distinct: the parameters' ones share a scope)."""

HEADER = '''"""The nonlinear equations of motion of the Whipple bicycle: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive nonlinear`` (sympy {sympy}) from the derivation in
``bikemass.models.derive.nonlinear`` (Kane's method with sympy.physics.mechanics).  :func:`bind`
takes the 26 benchmark parameters (SI, see PARAMETERS) and returns the functions of the
configuration (roll ``phi``, pitch ``theta``, steer ``delta``), the speeds ``u`` (SPEEDS) and the
inputs (INPUTS) listed in FUNCTIONS::

    H = -M(q) u' + F(q, u, r)      generalised forces of every speed as if all were independent
    A(q) u = 0,  A u' + b = 0      rolling without slip, front contact on the ground (rate)
    f(q) = 0                       front contact on the ground
"""

import math

import numpy as np

sin, cos, sqrt = math.sin, math.cos, math.sqrt
'''


def module_source_nonlinear(derived):
    """The Python source of the generated module of :class:`NonlinearDerived` ``derived``."""
    from sympy.printing.pycode import PythonCodePrinter

    class Printer(PythonCodePrinter):
        def _module_format(self, fqn, register=True):
            return fqn.rpartition(".")[2]

    printer = Printer({"fully_qualified_modules": True, "standard": "python3"})
    names = [n for n, _, _ in derived.parameters]
    params = {sm.Symbol(n) for n in names}
    bound, functions, docs = [], [], []
    for group, (args, outputs) in derived.groups.items():
        flat = [(key, m.shape, list(m)) for key, m in outputs.items()]
        exprs = [e for _, _, es in flat for e in es]
        replacements, reduced = sm.cse(exprs, symbols=sm.numbered_symbols(PREFIX[group]), order="none")
        known = set(params)
        body = []
        for symbol, expr in replacements:
            if expr.free_symbols <= known:
                bound.append(f"    {symbol} = {printer.doprint(expr)}")
                known.add(symbol)
            else:
                body.append(f"        {symbol} = {printer.doprint(expr)}")
        results, k = [], 0
        for key, shape, es in flat:
            values = [printer.doprint(e) if e != 0 else "0.0" for e in reduced[k:k + len(es)]]
            k += len(es)
            if shape[1] == 1 and key in ("f",):
                results.append(values[0])
            elif shape[0] == 1 or shape[1] == 1:
                results.append("(" + ", ".join(values) + ",)")
            else:
                rows = [", ".join(values[i * shape[1]:(i + 1) * shape[1]]) for i in range(shape[0])]
                results.append("np.array([" + ", ".join(f"[{row}]" for row in rows) + "])")
        arglist = ", ".join(str(a) for a in args)
        functions.append(f"    def {group}({arglist}):")
        functions.append(f'        """{", ".join(outputs)} ({", ".join(f"{a}x{b}" for _, (a, b), _ in flat)})."""')
        functions += body
        functions.append(f"        return {', '.join(results)}")
        functions.append("")
        docs.append((group, tuple(str(a) for a in args), tuple(outputs)))
    lines = [HEADER.format(sympy=sm.__version__), ""]
    lines += [f"PARAMETERS = {derived.parameters!r}", '"""(name, SI unit, meaning) of the arguments of bind, in order."""',
              f"COORDINATES = {derived.coordinates!r}", f"SPEEDS = {derived.speeds!r}",
              f"DEPENDENT = {derived.dependent!r}",
              '"""Indices in SPEEDS of the speeds the rows of A fix (the others are independent)."""',
              f"INPUTS = {derived.inputs!r}", f"FUNCTIONS = {tuple(docs)!r}",
              '"""(name, arguments, outputs) of the functions bind returns, in order."""', "", ""]
    lines.append(f"def bind({', '.join(names)}):")
    lines.append('    """The functions of FUNCTIONS for one parameter set (floats, SI)."""')
    lines += bound
    lines.append("")
    lines += functions
    lines.append(f"    return {', '.join(g for g, _, _ in docs)}")
    return "\n".join(lines) + "\n"
