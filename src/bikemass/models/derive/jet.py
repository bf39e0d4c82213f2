"""First derivatives of sympy expressions at one point, by forward-mode differentiation.

The linearised equations of motion need the first derivatives of the generalised forces (about
10^5 operations for the Whipple bicycle) with respect to every coordinate, speed and acceleration,
at the upright straight run.  ``sympy.diff`` followed by substitution builds every derivative in
full before the operating point collapses it (``sin(0) = 0``): minutes.  :class:`Jet` instead
walks the expression once, bottom up, carrying each sub-expression's value at the point and its
gradient, remembered per sub-expression (sympy shares equal sub-trees, so a direction cosine met a
thousand times is differentiated once): seconds, and the values stay small because the point is
substituted as soon as a leaf is reached.
"""

import sympy as sm


class Jet:
    """Value and gradient of expressions at ``point`` with respect to ``variables``.

    Parameters
    ----------
    point : dict of Symbol to expression
        The value of every variable (and of any other symbol to substitute) at the point.
    variables : iterable of Symbol
        The symbols to differentiate with respect to.
    """

    def __init__(self, point, variables):
        self.point = dict(point)
        self.variables = frozenset(variables)
        missing = self.variables - set(self.point)
        if missing:
            raise ValueError(f"no value at the point for {sorted(map(str, missing))}")
        self._memo = {}

    def __call__(self, expr):
        """``(value, {variable: derivative})`` of ``expr`` at the point (zero derivatives left out)."""
        expr = sm.sympify(expr)
        hit = self._memo.get(expr)
        if hit is None:
            hit = self._memo[expr] = self._evaluate(expr)
        return hit

    def value(self, expr):
        """``expr`` at the point."""
        return self(expr)[0]

    def gradient(self, expr, variables):
        """``[d expr / d z for z in variables]`` at the point."""
        grad = self(expr)[1]
        return [grad.get(z, sm.S.Zero) for z in variables]

    def _evaluate(self, e):
        if e.is_Symbol:
            return (self.point.get(e, e), {e: sm.S.One} if e in self.variables else {})
        if not (e.free_symbols & self.variables):
            return (e.xreplace(self.point), {})
        if e.is_Add:
            parts = [self(a) for a in e.args]
            grad = {}
            for _, g in parts:
                for z, d in g.items():
                    grad[z] = grad.get(z, sm.S.Zero) + d
            return (sm.Add(*(v for v, _ in parts)), _nonzero(grad))
        if e.is_Mul:
            parts = [self(a) for a in e.args]
            values = [v for v, _ in parts]
            grad = {}
            for i, (_, g) in enumerate(parts):
                if g:
                    others = sm.Mul(*values[:i], *values[i + 1:])
                    for z, d in g.items():
                        grad[z] = grad.get(z, sm.S.Zero) + others * d
            return (sm.Mul(*values), _nonzero(grad))
        if e.is_Pow:
            base, exponent = e.args
            if exponent.free_symbols & self.variables:
                raise NotImplementedError(f"a variable in an exponent: {e}")
            b, g = self(base)
            factor = exponent * b ** (exponent - 1)
            return (b ** exponent, _nonzero({z: factor * d for z, d in g.items()}))
        if isinstance(e, sm.Function) and len(e.args) == 1:
            a, g = self(e.args[0])
            x = sm.Dummy()
            factor = e.func(x).fdiff().xreplace({x: a})
            return (e.func(a), _nonzero({z: factor * d for z, d in g.items()}))
        raise NotImplementedError(f"cannot differentiate {type(e).__name__}: {e}")


def _nonzero(grad):
    return {z: d for z, d in grad.items() if d != 0}
