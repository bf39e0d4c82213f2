"""Time 20 s of the nonlinear benchmark bicycle (4.6 m/s, roll rate 0.5 rad/s: the IFToMM case) by
bikemass beside the field's standard route, in this process.

Run by hand: ``python benchmarks/bench_nonlinear.py [--repeat 3] [--duration 20]``.  Target
(issue 33): ``bm.simulate(..., nonlinear=True)`` at most as slow as the peer.

The peer: the same equations (bikemass's derivation, :func:`bikemass.models.derive.nonlinear.
derive_nonlinear`: the generalised forces of every speed and the constraint matrix, its rate
``b = A' u`` differentiated symbolically here) turned into functions by ``sympy.lambdify`` (numpy, common subexpressions
on, the parameters as arguments), the constrained equations formed the same way, the pitch as an
integrated state, and scipy's ``solve_ivp`` with DOP853 at rtol 1e-9 (atol 1e-9) sampling every
0.01 s.  bikemass runs at its own, tighter relative tolerance (rtol 1e-10, atol 1e-9) and also solves
the pitch by Newton at every evaluation and computes the energy at every sample.  Sympy's
derivation and lambdify are not timed (the peer's set-up, done once); bikemass's set-up (binding
the generated code) is.  Each is timed ``--repeat`` times, alternating; the best of each counts.
Both runs' roll rates at the end are printed, to show they computed the same motion.
"""

import argparse
import time

import numpy as np
import sympy as sm
from scipy.integrate import solve_ivp

import bikemass as bm
from bikemass.models.derive.nonlinear import derive_nonlinear

SPEED, ROLL_RATE = 4.6, 0.5


def peer(parameters):
    """``run(duration)`` of the lambdify + DOP853 route (the set-up done here, untimed)."""
    d = derive_nonlinear()
    symbols = [sm.Symbol(name) for name, _, _ in d.parameters]
    values = [getattr(parameters, name) for name, _, _ in d.parameters]
    functions = {}
    config, (A,) = d.groups["constraints"][0], d.groups["constraints"][1].values()
    args, outputs = d.groups["dynamics"]
    speeds = args[3:11]
    rates = [speeds[d.speeds.index(n)] for n in ("u_phi", "u_theta", "u_delta")]
    b = sum((A.diff(q) * rate for q, rate in zip(config, rates)), sm.zeros(*A.shape)) * sm.Matrix(speeds)
    functions["constraints"] = sm.lambdify([*config, *symbols], [A], "numpy", cse=True)
    functions["dynamics"] = sm.lambdify([*args, *symbols], [outputs["M"], outputs["F"], b], "numpy", cse=True)
    constraints, dynamics = functions["constraints"], functions["dynamics"]
    ind, dep = [0, 1, 2], [3, 4, 5, 6, 7]            # the derivation's order: u_lon, roll, steer rates first
    # state: x, y, yaw, roll, pitch, rear wheel, steer, front wheel, then u_lon, roll rate, steer rate
    at = {name: i for i, name in enumerate(d.speeds)}
    rate_of = [at[n] for n in ("u_psi", "u_phi", "u_theta", "u_betaR", "u_delta", "u_betaF")]
    lon, lat = at["u_lon"], at["u_lat"]

    def rhs(_, y):
        roll, pitch, steer, yaw = y[3], y[4], y[6], y[2]
        A = np.asarray(constraints(roll, pitch, steer, *values)[0], float)
        W = -np.linalg.solve(A[:, dep], A[:, ind])
        u = np.zeros(8)
        u[ind] = y[8:]
        u[dep] = W @ y[8:]
        M, F, b = dynamics(roll, pitch, steer, *u, 0.0, 0.0, *values)
        M, F, b = np.asarray(M, float), np.asarray(F, float).ravel(), np.asarray(b, float).ravel()
        s = np.zeros(8)
        s[dep] = -np.linalg.solve(A[:, dep], b)
        S = np.zeros((8, 3))
        S[ind, [0, 1, 2]] = 1.0
        S[dep] = W
        ud = np.linalg.solve(S.T @ M @ S, S.T @ (F - M @ s))
        out = np.empty(11)
        out[0] = u[lon] * np.cos(yaw) - u[lat] * np.sin(yaw)
        out[1] = u[lon] * np.sin(yaw) + u[lat] * np.cos(yaw)
        out[2:8] = u[rate_of]
        out[8:] = ud
        return out

    def run(duration):
        y0 = np.zeros(11)
        y0[8], y0[9] = SPEED, ROLL_RATE
        t = np.arange(0.0, duration + 1e-9, 0.01)
        sol = solve_ivp(rhs, (0.0, duration), y0, method="DOP853", rtol=1e-9, atol=1e-9, t_eval=t)
        return sol.y[9, -1]

    return run


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--duration", type=float, default=20.0)
    args = parser.parse_args()
    p = bm.parameters("benchmark")
    t0 = time.perf_counter()
    route = peer(p)
    print(f"peer set-up (sympy derivation + lambdify, not timed below): {time.perf_counter() - t0:.1f} s")

    def ours(duration):
        r = bm.simulate(p, SPEED, initial={"roll-rate": ROLL_RATE}, duration=duration, step=0.01, nonlinear=True)
        return r["roll-rate"][-1]

    times = {"bikemass": [], "lambdify + DOP853": []}
    ends = {}
    for _ in range(args.repeat):
        for name, fn in (("bikemass", ours), ("lambdify + DOP853", route)):
            t0 = time.perf_counter()
            ends[name] = fn(args.duration)
            times[name].append(time.perf_counter() - t0)
    best = {k: min(v) for k, v in times.items()}
    for name, t in best.items():
        print(f"{name:>18}: {t:.3f} s for {args.duration:g} s simulated (best of {args.repeat}); "
              f"roll rate at the end {ends[name]:.9f} rad/s")
    print(f"ratio bikemass / peer: {best['bikemass'] / best['lambdify + DOP853']:.2f}")


if __name__ == "__main__":
    main()
