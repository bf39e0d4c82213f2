"""The nonlinear simulator (bm.simulate(..., nonlinear=True), bikemass simulate --nonlinear) against an
independent reference, the linear model, and the IFToMM energy criterion.

The reference (:func:`reference_equations`, slow: ~20 s of sympy) is derived here separately from
bikemass's derivation: other frames (the rear frame's pitch measured to the steer axis, as Moore
2012 does, with his distances d1, d2, d3 of the benchmark's geometry), other generalised speeds
(every coordinate's rate; the rear wheel's rate independent, not the forward speed), sympy's own
``KanesMethod`` for the mass matrix and forcing, the constraints' time derivative formed from
the constraint vector, and the pitch integrated as a state (no Newton projection) at a relative
tolerance of 1e-12.  What both must share is only the benchmark's definition.

The IFToMM multibody library's "uncontrolled bicycle" problem: the benchmark from upright at 4 m/s
with a roll rate of 0.05 rad/s, at 4.6 m/s with 0.5 rad/s and at 8 m/s with 0.05 rad/s, for 20 s;
a solver passes when the energy drifts by less than 1e-3 %.
"""

import json
import math
import warnings

import numpy as np
import pytest

import bikemass as bm
from bikemass.cli.main import main
from bikemass.core.errors import BikemassWarning, InputError

sm = pytest.importorskip("sympy")
me = pytest.importorskip("sympy.physics.mechanics")
from scipy.integrate import solve_ivp  # noqa: E402

IFTOMM = ((4.0, 0.05), (4.6, 0.5), (8.0, 0.05))
"""(speed m/s, initial roll rate rad/s) of the IFToMM cases."""
COMPARED = ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "forward-speed")


def reference_equations(p):
    """Numeric functions of an independently derived nonlinear Whipple bicycle (see the module
    docstring): ``(mass_matrix(q), forcing(q, u), A(q), b(q, u), holonomic(q), energy(q, u))``."""
    q = me.dynamicsymbols("q1:9")
    u = me.dynamicsymbols("u1:9")
    q1, q2, q3, q4, q5, q6, q7, q8 = q
    t = me.dynamicsymbols._t
    lam, rR, rF, w, c, g = p.lam, p.rR, p.rF, p.w, p.c, p.g
    N = me.ReferenceFrame("N")
    A = N.orientnew("A", "Axis", (q3, N.z))
    B = A.orientnew("B", "Axis", (q4, A.x))
    C = B.orientnew("C", "Axis", (q5, B.y))              # C.z along the steer axis (q5 = lam upright)
    E = C.orientnew("E", "Axis", (q7, C.z))
    R = C.orientnew("R", "Axis", (q6, C.y))
    F = E.orientnew("F", "Axis", (q8, E.y))
    Cb = C.orientnew("Cb", "Axis", (-lam, C.y))          # the benchmark's axes on the rear frame
    Eb = E.orientnew("Eb", "Axis", (-lam, E.y))          # and on the front frame
    d1 = math.cos(lam) * (c + w - rR * math.tan(lam))
    d3 = -math.cos(lam) * (c - rF * math.tan(lam))
    d2 = (rR + d1 * math.sin(lam) - rF + d3 * math.sin(lam)) / math.cos(lam)
    origin = me.Point("O")
    origin.set_vel(N, 0)
    P = origin.locatenew("P", q1 * N.x + q2 * N.y)
    Rc = P.locatenew("Rc", -rR * B.z)
    Fc = Rc.locatenew("Fc", d1 * C.x + d2 * C.z + d3 * E.x)
    Bo = Rc.locatenew("Bo", p.xB * Cb.x + (p.zB + rR) * Cb.z)
    Ho = Fc.locatenew("Ho", (p.xH - w) * Eb.x + (p.zH + rF) * Eb.z)
    for point in (P, Rc, Fc, Bo, Ho):
        point.set_vel(N, point.pos_from(origin).dt(N))
    kd = {qi.diff(t): ui for qi, ui in zip(q, u)}
    bodies = [me.RigidBody("R", Rc, R, p.mR, (me.inertia(C, p.IRxx, p.IRyy, p.IRxx), Rc)),
              me.RigidBody("B", Bo, C, p.mB, (me.inertia(Cb, p.IBxx, p.IByy, p.IBzz, 0, 0, p.IBxz), Bo)),
              me.RigidBody("H", Ho, E, p.mH, (me.inertia(Eb, p.IHxx, p.IHyy, p.IHzz, 0, 0, p.IHxz), Ho)),
              me.RigidBody("F", Fc, F, p.mF, (me.inertia(E, p.IFxx, p.IFyy, p.IFxx), Fc))]
    T4, T7 = me.dynamicsymbols("T4 T7")
    loads = [(b.masscenter, b.mass * g * N.z) for b in bodies]
    loads += [(C, T4 * A.x - T7 * C.z), (E, T7 * C.z)]
    kane = me.KanesMethod(N, q_ind=q, u_ind=u, kd_eqs=[qi.diff(t) - ui for qi, ui in zip(q, u)])
    kane.kanes_equations(bodies, loads)
    tilt = A.z & E.y
    down = (A.z - tilt * E.y) / sm.sqrt(1 - tilt ** 2)
    vR = (Rc.vel(N) + R.ang_vel_in(N).cross(rR * B.z)).subs(kd)
    vF = (Fc.vel(N) + F.ang_vel_in(N).cross(rF * down)).subs(kd)
    constraints = sm.Matrix([vR & A.x, vR & A.y, vF & A.x, vF & A.y, vF & A.z])
    Amat = constraints.jacobian(u)
    b = (Amat * sm.Matrix(u)).jacobian(q) * sm.Matrix(u)
    holonomic = (Fc.pos_from(origin) + rF * down) & N.z
    heights = [-(body.masscenter.pos_from(origin) & N.z) for body in bodies]
    kinetic = sum(body.kinetic_energy(N) for body in bodies).subs(kd)
    energy = kinetic + sum(body.mass * g * h for body, h in zip(bodies, heights))
    qs, us = sm.symbols("q1:9"), sm.symbols("u1:9")
    plain = dict(zip(q, qs)) | dict(zip(u, us)) | {T4: 0, T7: 0}
    mass = kane.mass_matrix.xreplace(plain)
    forcing = kane.forcing.xreplace(plain)
    make = lambda args, expr: sm.lambdify(args, expr.xreplace(plain), "numpy", cse=True)  # noqa: E731
    return (sm.lambdify([qs], mass, "numpy", cse=True), sm.lambdify([qs, us], forcing, "numpy", cse=True),
            make([qs], Amat), make([qs, us], b), make([qs], sm.Matrix([holonomic])), make([qs, us], sm.Matrix([energy])))


INDEPENDENT = [3, 5, 6]          # u4 roll rate, u6 rear wheel rate, u7 steer rate
DEPENDENT = [0, 1, 2, 4, 7]


def reference_run(functions, p, speed, roll_rate, times):
    """Integrate the reference from upright and straight: states ``q`` (8) and the independent
    speeds; returns rows of (roll, steer, roll rate, steer rate, forward speed) and the energy."""
    mass, forcing, Amat, bvec, _, energy = functions

    def speeds(q, ui):
        Aq = np.asarray(Amat(q), float)
        W = -np.linalg.solve(Aq[:, DEPENDENT], Aq[:, INDEPENDENT])
        u = np.zeros(8)
        u[INDEPENDENT] = ui
        u[DEPENDENT] = W @ ui
        return u, Aq, W

    def rhs(_, y):
        q, ui = y[:8], y[8:]
        u, Aq, W = speeds(q, ui)
        M = np.asarray(mass(q), float)
        f = np.asarray(forcing(q, u), float).ravel()
        s = np.zeros(8)
        s[DEPENDENT] = -np.linalg.solve(Aq[:, DEPENDENT], np.asarray(bvec(q, u), float).ravel())
        S = np.zeros((8, 3))
        S[INDEPENDENT, [0, 1, 2]] = 1
        S[DEPENDENT] = W
        ud = np.linalg.solve(S.T @ M @ S, S.T @ (f - M @ s))
        return np.concatenate((u, ud))

    q0 = np.zeros(8)
    q0[4] = p.lam                                  # upright, straight: the steer axis at lam
    y0 = np.concatenate((q0, [roll_rate, -speed / p.rR, 0.0]))
    sol = solve_ivp(rhs, (0, times[-1]), y0, method="DOP853", rtol=1e-12, atol=1e-13, t_eval=times)
    rows = []
    for y in sol.y.T:
        q, ui = y[:8], y[8:]
        u = speeds(q, ui)[0]
        rows.append([q[3], q[6], u[3], u[6], -p.rR * (u[4] + u[5])])
    return np.array(rows), float(np.asarray(energy(y0[:8], speeds(y0[:8], y0[8:])[0])).ravel()[0])


@pytest.fixture(scope="module")
def meijaard():
    return bm.parameters("benchmark")


@pytest.fixture(scope="module")
def reference(meijaard):
    return reference_equations(meijaard)


@pytest.mark.slow
@pytest.mark.parametrize("speed, roll_rate", IFTOMM)
def test_the_iftomm_cases_agree_with_an_independent_reference(meijaard, reference, speed, roll_rate, capsys):
    """``bikemass simulate benchmark --nonlinear --speed V --initial roll-rate=W --duration 5
    --format json``: roll and steer angles and rates and the forward speed at t = 1..5 s to 1e-6
    (absolute, in rad, rad/s and m/s; the reference integrates at 1e-12, bikemass at 1e-10, so
    1e-6 leaves the tolerances' error far behind and catches any difference of the equations;
    measured 1.4e-8 at most); the energy at the start to 1e-9 relative (measured 4e-16)."""
    times = np.arange(0.0, 5.0 + 1e-9, 1.0)
    expected, energy = reference_run(reference, meijaard, speed, roll_rate, times)
    code = main(["simulate", "benchmark", "--nonlinear", "--speed", str(speed), "--initial", f"roll-rate={roll_rate}",
                 "--duration", "5", "--format", "json"])
    states = json.loads(capsys.readouterr().out)["states"]
    assert code == 0
    got = np.column_stack([np.array(states[n])[::100] for n in COMPARED])
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-6)
    assert states["energy"][0] == pytest.approx(energy, rel=1e-9)


@pytest.mark.slow
@pytest.mark.parametrize("speed, roll_rate", IFTOMM)
def test_iftomm_energy_drift_is_below_one_thousandth_of_a_percent(meijaard, speed, roll_rate):
    """20 s of each IFToMM case: the energy (kinetic plus potential, the ground at zero height)
    stays within 1e-3 % of its start (the IFToMM criterion; measured 1e-12 to 5e-10 %)."""
    r = bm.simulate(meijaard, speed, initial={"roll-rate": roll_rate}, duration=20.0, step=0.01, nonlinear=True)
    assert r.stopped == "" and r.time[-1] == pytest.approx(20.0)
    e = r["energy"]
    assert np.max(np.abs(e - e[0])) / abs(e[0]) * 100 < 1e-3


def test_a_small_kick_equals_the_linear_model(meijaard):
    """A roll-rate kick of 5e-4 rad/s at 4.6 m/s: the nonlinear run equals the linear one to 1e-3
    of the kick's amplitude (the difference is of the order of the amplitude squared)."""
    kick = {"roll-rate": 5e-4}
    n = bm.simulate(meijaard, 4.6, initial=kick, duration=5.0, step=0.01, nonlinear=True)
    lin = bm.simulate(meijaard, 4.6, initial=kick, duration=5.0, step=0.01)
    for name in ("roll-angle", "steer-angle", "roll-rate", "steer-rate", "heading", "lateral"):
        scale = np.max(np.abs(lin[name]))
        np.testing.assert_allclose(n[name], lin[name], rtol=0, atol=1e-3 * scale, err_msg=name)


def test_the_difference_from_linear_shrinks_with_the_amplitude_squared(meijaard):
    """Halving the kick quarters the nonlinear run's relative difference from the linear one, to 5 %:
    the lateral motion agrees to first order, and the bicycle's left-right symmetry removes the
    second-order terms from it (the forward speed changes at second order; roll and steer feel that
    at third), so the relative difference goes with the amplitude squared."""
    errors = []
    for kick in (0.04, 0.02):          # large enough for the difference to dwarf the tolerances
        n = bm.simulate(meijaard, 4.6, initial={"roll-rate": kick}, duration=3.0, nonlinear=True)
        lin = bm.simulate(meijaard, 4.6, initial={"roll-rate": kick}, duration=3.0)
        errors.append(np.max(np.abs(n["roll-rate"] - lin["roll-rate"])) / kick)
    assert errors[0] / errors[1] == pytest.approx(4.0, rel=0.05)


def test_a_fall_stops_the_run_with_one_line_and_keeps_the_samples(meijaard):
    """At 1 m/s the benchmark capsizes: the run stops at the fall, warns once, no NaN."""
    with pytest.warns(BikemassWarning, match="stopped at t = ") as caught:
        r = bm.simulate(meijaard, 1.0, initial={"roll-rate": 0.05}, duration=1000.0, step=0.01, nonlinear=True)
    assert len(caught) == 1 and "\n" not in str(caught[0].message)
    assert r.stopped and r.time[-1] < 1000.0 and len(r.time) > 10
    assert np.all(np.isfinite(r.values))
    last = r.values[-1]
    assert abs(last[0]) < math.radians(60.0) + 1e-9 and abs(last[1]) < math.pi / 2 + 1e-9


def test_at_rest_the_bicycle_falls_over(meijaard):
    """At 0 m/s with a small lean the bicycle falls (to 60 degrees of roll) instead of leaning to
    1e140 rad, like the linear model does."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = bm.simulate(meijaard, 0.0, initial={"roll-angle": 0.01}, duration=20.0, nonlinear=True)
    assert "fell" in r.stopped and len(caught) == 1
    assert np.all(np.isfinite(r.values)) and np.max(np.abs(r["roll-angle"])) < 1.05


def test_bad_input_is_refused(meijaard):
    with pytest.raises(InputError, match="forward speed is the speed"):
        bm.simulate(meijaard, 4.0, initial={"forward-speed": 1.0}, nonlinear=True)
    with pytest.raises(InputError, match="before a fall"):
        bm.simulate(meijaard, 4.0, initial={"roll-angle": 1.2}, nonlinear=True)
    with pytest.raises(InputError, match="rigid frame"):
        bm.simulate(meijaard, 4.0, stiffness=np.eye(2), nonlinear=True)
    with pytest.raises(InputError):
        bm.simulate(bm.linear_model(meijaard), 4.0, nonlinear=True)


def test_an_impulse_is_the_velocity_jump_of_the_linear_model(meijaard):
    """A steer-torque impulse of 0.01 N m s: the first sample's rates equal the linear model's jump
    B J (the mass matrix's inverse; the upright bicycle's, so to round-off)."""
    n = bm.simulate(meijaard, 4.6, inputs={"steer-torque": ("impulse", 0.01)}, duration=0.1, nonlinear=True)
    lin = bm.simulate(meijaard, 4.6, inputs={"steer-torque": ("impulse", 0.01)}, duration=0.1)
    for name in ("roll-rate", "steer-rate"):
        assert n[name][0] == pytest.approx(lin[name][0], rel=1e-12)
