"""The Whipple bicycle's ``M, C1, K0, K2`` from the generated model family: the run-time path.

The generated code of the model ``whipple`` (:func:`bikemass.models.family.generated`, written by
``python -m bikemass.models.derive`` from Kane's method) gives the descriptor form
``E x' = sum_k v**k A[k] x + ...`` with ``x = [q, q', ...]``; its second-order form (the rows of
the rates ``q'``) is ``M = E[q', q']``, ``C_k = -A[k][q', q']`` and ``K_k = -A[k][q', q]``
(:class:`~bikemass.models.linear.SecondOrder`), so the benchmark's matrices are ``C1 = C_1``,
``g K0 = K_0`` and ``K2 = K_2``.  The code is evaluated at ``g = 1``: ``K_0`` is linear in ``g``
and ``M``, ``C1``, ``K2`` do not depend on it, so that gives ``K0`` as Meijaard et al. (2007)
print it (without ``g``), and ``g K0`` is formed as the hand-written matrices form it.

Two things the generated code is not asked directly:

* **point wheels** (radius 0, which the parameter checks allow only without spin inertia: the
  two-mass-skate bicycle).  The generated code divides by the radii (a wheel's spin rate is
  ``v / r``).  A point wheel with neither spin inertia nor mass drops out of the equations whatever
  its radius, so the code is evaluated at a radius of 1 m; a point wheel with mass is a point mass
  at its contact point, with ``Izz = Ixx`` and no spin: it turns with its frame as if fixed to it,
  so its mass and inertia are first merged into the rear frame (B) or the front frame (H) by the
  parallel-axis theorem, then it is a massless point wheel.
* **only the entries**: the generated function is cut down (its syntax tree, once) to the
  assignments of the 16 entries of ``M, C1, K0, K2`` and the temporaries they use, returning
  them; run on Python floats it makes no array (the scalar fast path of
  :mod:`bikemass.analysis.engine.scalar`: about 2.5 us, against 7 us for the whole descriptor form),
  on arrays (a sweep's chunk) it makes only the entries, each of the varied parameters' shape,
  without the ``(B, 3, 6, 6)`` coefficient arrays.  The arithmetic is the generated code's, line
  for line.

The hand-written :func:`~bikemass.models.canonical.canonical_entries` (Meijaard et al. 2007,
Appendix A) is the test oracle of these functions (tests/test_whipple_generated.py: equal to a
few units of rounding on the benchmark, the thesis's sets, random parameter sets and point wheels,
and the complex step through both).
"""

import ast
import inspect
import math
from functools import lru_cache
from operator import attrgetter

import numpy as np

from .canonical import CanonicalMatrices


def _entries_function(code):
    """The source's ``coefficients`` function of the generated module ``code`` cut down to what the
    second-order form needs: a function of the parameters (in ``code.PARAMETERS``' order) returning
    the 16 entries ``M`` (4), ``C_1``, ``K_0``, ``K_2`` (4 each, rows first) as the generated code
    computes them (``C_k = -A[k][q', q']``, ``K_k = -A[k][q', q]``; 0.0 where it assigns nothing),
    with the temporaries only they use, no array made.  Returned as an ``ast.Module`` defining
    ``entries`` to be compiled with ``cos`` and ``sin`` in scope (math's or numpy's)."""
    tree = ast.parse(inspect.getsource(code))
    make = next(node for node in tree.body if isinstance(node, ast.FunctionDef) and node.name == "_make")
    inner = next(node for node in make.body if isinstance(node, ast.FunctionDef))
    n = code.COORDINATES
    rows = [(n + i, n + j) for i in range(2) for j in range(2)]
    wanted = [("E", r) for r in rows] + [("A", (1, *r)) for r in rows] + \
        [("A", (k, r[0], r[1] - n)) for k in (0, 2) for r in rows]
    slot = {key: k for k, key in enumerate(wanted)}
    outputs = [ast.Constant(0.0) for _ in wanted]
    body = []
    for node in inner.body:
        if not isinstance(node, ast.Assign):
            continue
        (target,) = node.targets
        if isinstance(target, ast.Name):
            if target.id not in ("E", "A", "B"):
                body.append(node)
            continue
        index = tuple(e.value for e in target.slice.elts[1:])               # E[..., i, j], A[..., k, i, j]
        k = slot.get((target.value.id, index))
        if k is not None:
            name = f"_out{k}"
            body.append(ast.Assign([ast.Name(name, ast.Store())], node.value))
            value = ast.Name(name, ast.Load())
            outputs[k] = value if target.value.id == "E" else ast.UnaryOp(ast.USub(), value)
    needed = {x.id for out in outputs for x in ast.walk(out) if isinstance(x, ast.Name)}
    kept = []
    for node in reversed(body):                                  # only what the outputs use
        if node.targets[0].id in needed:
            kept.append(node)
            needed |= {x.id for x in ast.walk(node.value) if isinstance(x, ast.Name)}
    params = [ast.arg(a.arg) for a in inner.args.args[2:]]        # without (shape, dtype)
    function = ast.FunctionDef("entries", ast.arguments([], params, None, [], [], None, []),
                               [*reversed(kept), ast.Return(ast.Tuple(outputs, ast.Load()))], [])
    return ast.fix_missing_locations(ast.Module([function], []))


@lru_cache(maxsize=None)
def _code():
    """``(floats, arrays, layout)``: the generated code of ``whipple`` cut to the second-order entries
    (:func:`_entries_function`), computing in Python floats (math's cos, sin) and in arrays (numpy's),
    and its arguments' layout (a getter of them from a parameter set, their names, the places of
    ``g``, ``rR`` and ``rF``)."""
    from .generated import whipple as code      # lazy: its numpy code compiled only when first asked for
    compiled = compile(_entries_function(code), code.__file__, "exec")
    functions = []
    for scope in ({"cos": math.cos, "sin": math.sin}, {"cos": np.cos, "sin": np.sin}):
        exec(compiled, scope)                      # our own generated code, cut down: no outside input
        functions.append(scope["entries"])
    names = tuple(name for name, _, _ in code.PARAMETERS)
    where = tuple(names.index(name) for name in ("g", "rR", "rF"))
    return functions[0], functions[1], (attrgetter(*names), names, where)


_PLAIN = {float, int}
"""The types of a configuration computed in Python numbers (ints: a parameter written ``0``)."""


def _arguments(p, layout):
    """The generated code's arguments from the parameters ``p`` (any object with the 26 attributes):
    ``g`` set to 1, point wheels as described in the module docstring; and whether every argument
    is a Python number."""
    getter, names, (g, rR, rF) = layout
    args = list(getter(p))
    args[g] = 1.0
    plain = set(map(type, args)) <= _PLAIN
    if plain and args[rR] and args[rF]:
        return args, True
    if plain or np.any(np.real(args[rR]) == 0) or np.any(np.real(args[rF]) == 0):
        values = dict(zip(names, args))
        for wheel, frame, at in (("R", "B", 0.0), ("F", "H", None)):
            if np.any(np.real(values[f"r{wheel}"]) == 0):
                _point_wheel(values, wheel, frame, at)
        args = [values[name] for name in names]
    return args, set(map(type, args)) <= _PLAIN


def _point_wheel(values, wheel, frame, at):
    """Make the point wheels (radius 0) among the rows of ``values`` massless and of radius 1 m, their
    mass merged into ``frame`` at the wheel's contact point (x = 0 for the rear, ``w`` for the front;
    ``at``: that x, or ``None`` for ``w``)."""
    r, m, Ixx = values[f"r{wheel}"], values[f"m{wheel}"], values[f"I{wheel}xx"]
    point = np.real(r) == 0
    x0 = values["w"] if at is None else at
    mb, xb, zb = values[f"m{frame}"], values[f"x{frame}"], values[f"z{frame}"]
    with np.errstate(all="ignore"):
        mass = mb + m
        x = (mb * xb + m * x0) / mass
        z = mb * zb / mass                               # the wheel's centre is on the ground
        merged = {f"m{frame}": mass, f"x{frame}": x, f"z{frame}": z,
                  f"I{frame}xx": values[f"I{frame}xx"] + Ixx + mb * (zb - z) ** 2 + m * z ** 2,
                  f"I{frame}zz": values[f"I{frame}zz"] + Ixx + mb * (xb - x) ** 2 + m * (x0 - x) ** 2,
                  f"I{frame}xz": values[f"I{frame}xz"] - mb * (xb - x) * (zb - z) + m * (x0 - x) * z,
                  f"m{wheel}": 0 * m, f"I{wheel}xx": 0 * Ixx, f"r{wheel}": 1.0 + (r - np.real(r))}
    if type(r) is float or np.ndim(point) == 0:
        if point:
            values.update(merged)
        return
    for key, value in merged.items():
        values[key] = np.where(point, value, values[key])


def flat_entries(p):
    """The 16 entries of :func:`second_order_entries` as one flat tuple, each matrix row by row:
    ``M00 M01 M10 M11, C1.., K0.., K2..`` (the scalar fast path's form: no nesting to unpack)."""
    floats, arrays, layout = _code()
    args, plain = _arguments(p, layout)
    return (floats if plain else arrays)(*args)


def second_order_entries(p):
    """The entries of ``M, C1, K0, K2`` as nested ``((a, b), (c, d))`` rows, from the generated code:
    the same contract as :func:`~bikemass.models.canonical.canonical_entries` (its oracle).

    Parameters
    ----------
    p : BenchmarkParameters
        Any object with the 26 attributes of :data:`~bikemass.models.parameters.NAMES` (SI): Python
        floats (one configuration: Python floats out, no array made), arrays of one shape (B,) (a
        sweep's chunk: entries of shape (B,), or floats where no varied parameter enters), complex
        values (the complex step: complex entries).

    Returns
    -------
    tuple
        ``(M, C1, K0, K2)``: ``M`` in kg m^2, ``C1`` in kg m^2 (per m/s), ``K0`` in kg m (times g:
        N m/rad), ``K2`` in kg (times v^2: N m/rad).

    Examples
    --------
    >>> from bikemass.models.parameters import benchmark_parameters
    >>> M, C1, K0, K2 = second_order_entries(benchmark_parameters())
    >>> round(M[0][0], 10), round(K0[0][1], 10)      # Meijaard et al. (2007), Eq. A19-A20
    (80.81722, -2.319807917)
    """
    floats, arrays, layout = _code()
    args, plain = _arguments(p, layout)
    m0, m1, m2, m3, c0, c1, c2, c3, k0, k1, k2, k3, s0, s1, s2, s3 = (floats if plain else arrays)(*args)
    M = ((m0, m1), (m2, m3))
    C1 = ((c0, c1), (c2, c3))
    K0 = ((k0, k1), (k2, k3))
    K2 = ((s0, s1), (s2, s3))
    return M, C1, K0, K2


def whipple_matrices(p):
    """:class:`~bikemass.models.canonical.CanonicalMatrices` (``M, C1, K0, K2`` and ``g``) of a parameter
    set from the generated code (:func:`second_order_entries`); arrays of one shape (B,) give stacked
    (B, 2, 2) matrices, complex values complex ones.

    Examples
    --------
    >>> from bikemass.models.parameters import benchmark_parameters
    >>> whipple_matrices(benchmark_parameters()).K2.round(8).tolist()
    [[0.0, 76.59734589], [0.0, 2.65431524]]
    """
    M, C1, K0, K2 = second_order_entries(p)
    return CanonicalMatrices(M=_matrix(M), C1=_matrix(C1), K0=_matrix(K0), K2=_matrix(K2), g=p.g)


def _matrix(rows):
    """A 2x2 matrix from entries that may be arrays of one shape (B,): shape (2, 2) or (B, 2, 2)."""
    if all(type(x) is float for row in rows for x in row):
        a = np.array(rows)
    else:
        entries = np.broadcast_arrays(*(np.asarray(x) for row in rows for x in row))
        a = np.stack(entries, axis=-1).reshape(*entries[0].shape, 2, 2)
    a.setflags(write=False)                     # a new array nobody else holds: read-only without a copy
    return a

