"""The floor of a parameter-level sweep: the Whipple closed form for the weave and capsize speeds
and the first stable speed range in plain numpy, nothing else (no checks, no table, no files).

Written for the benchmarks from Meijaard et al. (2007), Appendix A (the matrices) and the
characteristic quartic ``det(M s^2 + v C1 s + g K0 + v^2 K2)``: a real root crosses at the
positive roots ``v^2`` of its constant term, a complex pair where the Hurwitz determinant
``a3 a2 a1 - a4 a1^2 - a3^2 a0`` vanishes with ``a1 / a3 > 0``; between crossings the sign
changes of the Routh column at a midpoint count the unstable roots.  It uses no bikemass code,
so the ratio of a bikemass run to it is what everything bikemass does beyond the arithmetic.
"""

import numpy as np


def matrices(p):
    """``M, C1, gK0, K2`` as (B, 2, 2) arrays of a dict of (B,) parameter arrays."""
    sl, cl = np.sin(p["lam"]), np.cos(p["lam"])
    mR, mB, mH, mF = p["mR"], p["mB"], p["mH"], p["mF"]
    w, c, rR, rF = p["w"], p["c"], p["rR"], p["rF"]
    xB, zB, xH, zH = p["xB"], p["zB"], p["xH"], p["zH"]
    mT = mR + mB + mH + mF
    xT = (xB * mB + xH * mH + w * mF) / mT
    zT = (-rR * mR + zB * mB + zH * mH - rF * mF) / mT
    ITxx = p["IRxx"] + p["IBxx"] + p["IHxx"] + p["IFxx"] + mR * rR ** 2 + mB * zB ** 2 + mH * zH ** 2 + mF * rF ** 2
    ITxz = p["IBxz"] + p["IHxz"] - mB * xB * zB - mH * xH * zH + mF * w * rF
    ITzz = p["IRxx"] + p["IBzz"] + p["IHzz"] + p["IFxx"] + mB * xB ** 2 + mH * xH ** 2 + mF * w ** 2
    mA = mH + mF
    xA, zA = (xH * mH + w * mF) / mA, (zH * mH - rF * mF) / mA
    IAxx = p["IHxx"] + p["IFxx"] + mH * (zH - zA) ** 2 + mF * (rF + zA) ** 2
    IAxz = p["IHxz"] - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA)
    IAzz = p["IHzz"] + p["IFxx"] + mH * (xH - xA) ** 2 + mF * (w - xA) ** 2
    uA = (xA - w - c) * cl - zA * sl
    IAll = mA * uA ** 2 + IAxx * sl ** 2 + 2 * IAxz * sl * cl + IAzz * cl ** 2
    IAlx = -mA * uA * zA + IAxx * sl + IAxz * cl
    IAlz = mA * uA * xA + IAxz * sl + IAzz * cl
    mu = c / w * cl
    SR, SF = p["IRyy"] / rR, p["IFyy"] / rF
    ST, SA = SR + SF, mA * uA + mu * mT * xT
    g = p["g"]
    zero = np.zeros_like(mT)

    def stack(a, b, c_, d):
        return np.stack([np.stack([a, b], -1), np.stack([c_, d], -1)], -2)
    M = stack(ITxx, IAlx + mu * ITxz, IAlx + mu * ITxz, IAll + 2 * mu * IAlz + mu ** 2 * ITzz)
    gK0 = g[..., None, None] * stack(mT * zT, -SA, -SA, -SA * sl)
    K2 = stack(zero, (ST - mT * zT) / w * cl, zero, (SA + SF * sl) / w * cl)
    C1 = stack(zero, mu * ST + SF * cl + ITxz / w * cl - mu * mT * zT, -(mu * ST + SF * cl),
               IAlz / w * cl + mu * (SA + ITzz / w * cl))
    return M, C1, gK0, K2


def _positive_roots(a, b, c, vmax, extra=None):
    """(B, 2): the v in (0, vmax] with v^2 a root of a u^2 + b u + c (and ``extra(u) > 0``), else nan."""
    with np.errstate(divide="ignore", invalid="ignore"):
        disc = b * b - 4 * a * c
        root = np.sqrt(np.where(disc >= 0, disc, np.nan))
        quadratic = np.stack([(-b - root) / (2 * a), (-b + root) / (2 * a)], -1)
        linear = np.stack([-c / b, np.full_like(b, np.nan)], -1)
        u = np.where((a == 0)[..., None], linear, quadratic)
        ok = (u > 0) & (u <= vmax * vmax)
        if extra is not None:
            ok &= extra(u)
        return np.where(ok, np.sqrt(np.where(ok, u, 0)), np.nan)


def critical(p, vmax=30.0):
    """``(weave, capsize, stable_from, stable_to)`` (m/s, nan where none in (0, vmax]) of a dict
    of (B,) parameter arrays."""
    M, C1, K, K2 = matrices(p)

    def det(x):
        return x[..., 0, 0] * x[..., 1, 1] - x[..., 0, 1] * x[..., 1, 0]

    def dot(x, y):
        return x[..., 0, 0] * y[..., 1, 1] + y[..., 0, 0] * x[..., 1, 1] - x[..., 0, 1] * y[..., 1, 0] \
            - y[..., 0, 1] * x[..., 1, 0]
    a4, al, a20, a21 = det(M), dot(M, C1), dot(M, K), dot(M, K2) + det(C1)
    be, ga, d0, d1, d2 = dot(C1, K), dot(C1, K2), det(K), dot(K, K2), det(K2)
    real = _positive_roots(d2, d1, d0, vmax)
    h2 = al * a21 * ga - a4 * ga ** 2 - al ** 2 * d2
    h1 = al * (a20 * ga + a21 * be) - 2 * a4 * be * ga - al ** 2 * d1
    h0 = al * a20 * be - a4 * be ** 2 - al ** 2 * d0
    osc = _positive_roots(h2, h1, h0, vmax, lambda u: (be[..., None] + u * ga[..., None]) / al[..., None] > 0)
    with np.errstate(invalid="ignore"):
        weave, capsize = np.nanmin(np.where(np.isnan(osc), np.inf, osc), -1), np.nanmin(np.where(np.isnan(real), np.inf, real), -1)
    cuts = np.sort(np.concatenate([real, osc], -1), -1)
    ends = np.concatenate([np.zeros((len(cuts), 1)), np.where(np.isnan(cuts), vmax, cuts), np.full((len(cuts), 1), vmax)], -1)
    lo, hi = ends[:, :-1], ends[:, 1:]
    v = (lo + hi) / 2
    column = [a4[:, None] + 0 * v, v * al[:, None], a20[:, None] + v * v * a21[:, None],
              v * (be[:, None] + v * v * ga[:, None]), d0[:, None] + v * v * d1[:, None] + v ** 4 * d2[:, None]]
    A4, A3, A2, A1, A0 = column
    with np.errstate(divide="ignore", invalid="ignore"):
        b1 = (A3 * A2 - A4 * A1) / A3
        c1 = (b1 * A1 - A3 * A0) / b1
    signs = np.sign(np.stack([A4, A3, b1, c1, A0], -1))
    stable = (np.sum(signs[..., 1:] != signs[..., :-1], -1) == 0) & (hi > lo) & np.all(signs != 0, -1)
    first = np.argmax(stable, -1)
    rows = np.arange(len(cuts))
    has = stable[rows, first]
    running = stable | (hi <= lo)
    after = np.arange(stable.shape[1])[None, :] >= first[:, None]
    stop = np.min(np.where(after & ~running, lo, vmax), -1)
    nan = np.nan
    return (np.where(np.isinf(weave), nan, weave), np.where(np.isinf(capsize), nan, capsize),
            np.where(has, lo[rows, first], nan), np.where(has, stop, nan))
