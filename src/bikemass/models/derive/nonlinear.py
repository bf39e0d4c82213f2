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
  derivative of the holonomic constraint), also as a function of complex arguments: ``b = A' u``
  (``A u' + b = 0``) is the derivative of ``A(q + h q') u`` in ``h``, which the numeric code takes
  by a complex step (exact to round-off, and a third of the cost of writing ``b`` out);
- the holonomic constraint ``f(q) = 0`` (the front contact on the ground) and its gradient;
- the kinetic and potential energy (the ground as zero height) and the heights of the frames'
  centres of mass.

Kane's equations of the constrained system, ``W^T`` projecting onto the independent speeds, are
then formed numerically (:mod:`bikemass.models.nonlinear`): the symbolic solution of the
constraints for the dependent speeds, which swells the expressions, is never formed.
"""

import random
import re
from dataclasses import dataclass

import sympy as sm

from .bicycle import assemble
from .kane import TIME, generalised_forces

MODULE = "nonlinear_whipple"
"""The generated module's name (in :mod:`bikemass.models.generated`)."""
INDEPENDENT = ("u_lon", "u_phi", "u_delta")
"""The independent speeds: the rear contact's forward speed, the roll rate and the steer rate.  The
generated code takes and returns the speeds in the order: these, then the dependent ones (pitch
rate, rear wheel rate, lateral speed, front wheel rate, yaw rate: the order the constraints fix
them in), so that the numeric code needs no reordering."""
CONFIGURATION = ("phi", "theta", "delta")
"""The coordinates the written expressions depend on (roll, pitch, steer)."""


@dataclass(frozen=True)
class NonlinearDerived:
    """The nonlinear Whipple bicycle, symbolically (see the module docstring).

    ``parameters`` ((name, unit, meaning)); ``coordinates``, ``speeds``, ``inputs``: the names of
    ``q``, ``u`` (:data:`INDEPENDENT` first) and ``r`` in order; ``dependent``: indices of the
    dependent speeds in ``speeds``; ``groups``:
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
    names = [str(s.func) for s in system.speeds]
    order = [names.index(n) for n in INDEPENDENT] + [names.index(str(s.func)) for s in system.dependent_speeds]
    ordered = [u[i] for i in order]
    M, F, A = M.extract(order, order), F.extract(order, [0]), A.extract(list(range(A.rows)), order)
    M = _symmetric(M.xreplace(heading), [*config, *bike.parameters.values()])
    groups = {
        "holonomic": (config, {"f": sm.Matrix([f]), "gradient": gradient}),
        "constraints": (config, {"A": A}),
        "dynamics": (config + ordered + r, {"M": M, "F": F}),
        "energy": (config + ordered, {"energy": sm.Matrix([kinetic, potential])}),
        "heights": (config, {"heights": sm.Matrix(heights)}),
    }
    for name, (_args, outputs) in groups.items():
        for key, matrix in outputs.items():
            matrix = matrix.xreplace(heading)
            outputs[key] = matrix
            extra = set().union(*(e.free_symbols for e in matrix)) - free
            if extra:
                raise ValueError(f"{name}/{key} depends on {sorted(map(str, extra))}")
    return NonlinearDerived(
        parameters=tuple((k, bike.units[k], bike.descriptions[k]) for k in bike.parameters),
        coordinates=tuple(str(s.func) for s in system.coordinates), speeds=tuple(names[i] for i in order),
        inputs=tuple(name for name, _ in bike.input_names), dependent=tuple(range(len(INDEPENDENT), len(u))),
        groups=groups)


ARRAYS = ("holonomic", "constraints", "energy")
"""The functions also written for arrays of configurations (every output a flat tuple of arrays,
row by row): the outputs of a run, evaluated at every sample at once."""
COMPLEX = ("constraints",)
"""The functions also written for complex arguments (the complex step of ``b``)."""
PREFIX = {"holonomic": "f", "constraints": "a", "dynamics": "d", "energy": "e", "heights": "z"}
"""The names of each function's common subexpressions (distinct: the parameters' ones share a scope)."""

HEADER = '''"""The nonlinear equations of motion of the Whipple bicycle: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive nonlinear`` (sympy {sympy}) from the derivation in
``bikemass.models.derive.nonlinear`` (Kane's method with sympy.physics.mechanics).  :func:`bind`
takes the 26 benchmark parameters (SI, see PARAMETERS) and returns the functions of the
configuration (roll ``phi``, pitch ``theta``, steer ``delta``), the speeds ``u`` (SPEEDS) and the
inputs (INPUTS) listed in FUNCTIONS::

    H = -M(q) u' + F(q, u, r)      generalised forces of every speed as if all were independent
    A(q) u = 0                     rolling without slip, front contact on the ground (rate);
                                   constraints_complex: the same for complex arguments
    f(q) = 0                       front contact on the ground
"""

import cmath
import math

import numpy as np

sin, cos, sqrt = math.sin, math.cos, math.sqrt
csin, ccos, csqrt = cmath.sin, cmath.cos, cmath.sqrt
'''


def _symmetric(M, symbols, seed=33):
    """``M`` with its lower triangle the upper one's (the same expressions: the code computes each
    once), after checking at a random point (30 digits) that it is symmetric."""
    rng = random.Random(seed)
    point = {s: sm.Float(rng.uniform(0.2, 1.2), 30) for s in symbols}
    for i in range(M.rows):
        for j in range(i + 1, M.cols):
            difference = (M[i, j] - M[j, i]).xreplace(point).evalf(30)
            if abs(difference) > 1e-20:
                raise ValueError(f"the mass matrix is not symmetric at ({i}, {j}): {difference}")
    return sm.Matrix(M.rows, M.cols, lambda i, j: M[min(i, j), max(i, j)])


def module_source_nonlinear(derived):
    """The Python source of the generated module of :class:`NonlinearDerived` ``derived``."""
    # lazy: the printer only when code is written
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
        results, arrays, k = [], [], 0
        for key, shape, es in flat:
            values = [printer.doprint(e) if e != 0 else "0.0" for e in reduced[k:k + len(es)]]
            k += len(es)
            arrays.append("(" + ", ".join(f"{v} + zero" for v in values) + ",)")
            if shape[1] == 1 and key in ("f",):
                results.append(values[0])
            elif shape[0] == 1 or shape[1] == 1:
                results.append("(" + ", ".join(values) + ",)")
            else:
                rows = [", ".join(values[i * shape[1]:(i + 1) * shape[1]]) for i in range(shape[0])]
                results.append("np.array([" + ", ".join(f"[{row}]" for row in rows) + "])")
        arglist = ", ".join(str(a) for a in args)
        variants = [(group, body, results)]
        if group in COMPLEX:
            plain = lambda line: re.sub(r"\b(sin|cos|sqrt)\(", r"c\1(", line)  # noqa: E731
            variants.append((f"{group}_complex", [plain(b) for b in body], [plain(r) for r in results]))
        if group in ARRAYS:
            numpy = lambda line: re.sub(r"\b(sin|cos|sqrt)\(", r"np.\1(", line)  # noqa: E731
            variants.append((f"{group}_arrays", ["        zero = np.zeros(np.shape(phi))"] + [numpy(b) for b in body],
                             [numpy(r) for r in arrays]))
        for name, lines_, returned in variants:
            functions.append(f"    def {name}({arglist}):")
            functions.append(f'        """{", ".join(outputs)} ({", ".join(f"{a}x{b}" for _, (a, b), _ in flat)})."""')
            functions += lines_
            functions.append(f"        return {', '.join(returned)}")
            functions.append("")
            docs.append((name, tuple(str(a) for a in args), tuple(outputs)))
    lines = [HEADER.format(sympy=sm.__version__), ""]
    lines += [f"PARAMETERS = {derived.parameters!r}", '"""(name, SI unit, meaning) of the arguments of bind, in order."""',
              f"COORDINATES = {derived.coordinates!r}", f"SPEEDS = {derived.speeds!r}",
              '"""The speeds, in the order the functions take and return them: the independent first."""',
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
