"""Numeric code of a derived model: one plain-numpy module per member combination.

The module's ``coefficients(...)`` takes every parameter (a float or an array; all broadcast
together) and returns ``E, A, B`` with the parameters' broadcast shape in front, so that a sweep
evaluates thousands of configurations in one call.  The expressions are written once, with their
common subexpressions (``sympy.cse``) computed once, in a function made twice: with numpy's
functions for arrays and with :mod:`math`'s for plain floats (one configuration: Python floats
are several times faster than numpy scalars).
"""

import re

import sympy as sm
from sympy.printing.pycode import PythonCodePrinter

from .build import Derived

FUNCTIONS = ("sin", "cos", "tan", "sqrt")
"""The functions the generated code may call (numpy's for arrays, math's for floats)."""

HEADER = '''"""The linear equations of motion of the bikemass model ``{name}``: GENERATED, do not edit.

Written by ``python -m bikemass.models.derive`` ({generator}, sympy {sympy}) from the derivation
in ``bikemass.models.derive`` (Kane's method with sympy.physics.mechanics, linearised about the
upright straight run at speed v).  Descriptor form, states and inputs as listed below::

    E x' = sum_k v**k A[k] x + sum_k v**k B[k] u
"""

import math

import numpy as np
'''


class _Printer(PythonCodePrinter):
    """Python code calling the functions by their bare names (``sin``, ``sqrt``: given by ``_make``)."""

    def _module_format(self, fqn, register=True):
        return fqn.rpartition(".")[2]


def _degree(matrices):
    """Index of the last nonzero coefficient matrix, plus one (at least one)."""
    nonzero = [k for k, m in enumerate(matrices) if any(e != 0 for e in m)]
    return (nonzero[-1] if nonzero else 0) + 1


def module_source(derived: Derived, generator="bikemass.models.derive"):
    """The Python source of the generated module of ``derived``."""
    printer = _Printer({"fully_qualified_modules": True, "standard": "python3"})
    names = [p for p, _, _ in derived.parameters]
    N, m = len(derived.states), len(derived.inputs)
    dA, dB = _degree(derived.A), _degree(derived.B)
    targets = [("E", (i, j), derived.E[i, j]) for i in range(N) for j in range(N)]
    targets += [("A", (k, i, j), derived.A[k][i, j]) for k in range(dA) for i in range(N) for j in range(N)]
    targets += [("B", (k, i, j), derived.B[k][i, j]) for k in range(dB) for i in range(N) for j in range(m)]
    targets = [t for t in targets if t[2] != 0]
    replacements, reduced = sm.cse([e for _, _, e in targets], symbols=sm.numbered_symbols("x"), order="none")
    lines = [HEADER.format(name=derived.name, generator=generator, sympy=sm.__version__), ""]
    lines += [f"NAME = {derived.name!r}", f"MEMBERS = {derived.members!r}",
              f"PARAMETERS = {derived.parameters!r}", '"""(name, SI unit, meaning) of every argument of coefficients, in order."""',
              f"STATES = {derived.states!r}", '"""(name, unit) of every state; the first N_DYNAMIC are dynamic."""',
              f"N_DYNAMIC = {derived.n_dynamic}", f"INPUTS = {derived.inputs!r}",
              f"FAMILIES = {derived.families!r}", '"""Mode families: (name, indices of their dynamic states)."""',
              f"COORDINATES = {derived.coordinates}",
              '"""How many dynamic mechanical coordinates q lead the states (then their rates q\')."""',
              f"SECOND_ORDER = {derived.second_order}", '"""Whether the dynamic states are exactly [q, q\']."""',
              "", ""]
    body = [f"    {symbol} = {printer.doprint(expr)}" for symbol, expr in replacements]
    body += [f"    E = np.zeros(shape + ({N}, {N}), dtype)", f"    A = np.zeros(shape + ({dA}, {N}, {N}), dtype)",
             f"    B = np.zeros(shape + ({dB}, {N}, {m}), dtype)"]
    body += [f"    {array}[..., {', '.join(map(str, index))}] = {printer.doprint(expr)}"
             for (array, index, _), expr in zip(targets, reduced)]
    functions = sorted(set(re.findall(r"\b([a-z]\w*)\(", "\n".join(body))) - {"zeros"})
    unknown = set(functions) - set(FUNCTIONS)
    if unknown:
        raise ValueError(f"the expressions call {sorted(unknown)}, which the generated code does not provide")
    lines.append(f"def _make({', '.join(functions)}):")
    lines.append(f'    """The coefficient function computing with these functions ({", ".join(functions)})."""')
    lines.append("")
    lines.append(f"    def coefficients(shape, dtype, {', '.join(names)}):")
    lines += ["    " + line for line in body]
    lines.append("        return E, A, B")
    lines.append("    return coefficients")
    lines += ["", ""]
    lines.append(f"_arrays = _make({', '.join(f'np.{f}' for f in functions)})")
    lines.append(f"_floats = _make({', '.join(f'math.{f}' for f in functions)})")
    lines += ["", ""]
    lines.append(f"def coefficients({', '.join(names)}):")
    lines.append(f'    """``(E, A, B)``: E (..., {N}, {N}), A (..., {dA}, {N}, {N}), B (..., {dB}, {N}, {m}), the leading')
    lines.append('    dimensions those of the parameters (floats or arrays, SI, see PARAMETERS) broadcast together;')
    lines.append('    complex where a parameter is (the complex step: exact derivatives)."""')
    lines.append(f"    args = ({', '.join(names)},)")
    lines.append("    if all(type(a) is float for a in args):")
    lines.append("        return _floats((), float, *args)")
    lines.append("    return _arrays(np.broadcast_shapes(*(np.shape(a) for a in args)), np.result_type(float, *args), *args)")
    return "\n".join(lines) + "\n"
