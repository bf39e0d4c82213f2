"""The nonlinear Whipple bicycle (bikemass.models.nonlinear) against published numbers and closed forms.

- Basu-Mandal, Chatterjee & Papadopoulos (2007, Proc. R. Soc. A 463, 1983-2003), Table 1: the
  benchmark bicycle's state derivatives at one general state (rolled 35 degrees, steered 13,
  turning), printed to 12-14 significant digits.  Their coordinates differ from bikemass's (the
  rear wheel centre instead of the rear contact, z up, x backward, lean from the horizontal, pitch
  of the steer axis, every angle the other way round); the conversion, a matter of signs and of
  the rear wheel's radius, is written out below.  The table prints 13 decimals; its inputs are
  rounded there, and that rounding, carried through the equations (finite differences: 0.3 to
  2.2e-12 on the accelerations), is larger than the table's own last digit.  Allowed: 5 units of
  the 13th decimal and 1e-12 relative (12 significant digits; measured: at most 3.2e-13, 1.4e-13).
- The static normal forces of the benchmark at rest: the weight shared by the moments of the
  masses about the contacts, a closed form independent of the equations of motion (1e-9 N).
- The derivation's shipped code against a fresh derivation (slow, like tests/test_models_derive.py).
"""

import math
import random
import types

import numpy as np
import pytest

import bikemass as bm
from bikemass.models.generated import nonlinear_whipple as shipped
from bikemass.models.nonlinear import NonlinearWhipple

# Basu-Mandal et al. (2007), Table 1 (benchmark bicycle; their names; rad, m, s).
STATE = {"x": 0.0, "y": 0.0, "z": 0.2440472102925, "theta": 0.0, "psi": 0.9501292851472,
         "phi": 3.1257073014894, "psif": 0.2311385135743, "betar": 0.0, "betaf": 0.0}
RATES = {"x": -2.8069345714545, "y": -0.1480982396001, "z": 0.1058778746261, "theta": 0.7830033527065,
         "psi": 0.6068425835418, "phi": -0.0119185528069, "psif": 0.4859824687093, "betar": 8.9129896614890,
         "betaf": 8.0133620584155}
ACCELERATIONS = {"x": -0.5041626315047, "y": -0.3449706619454, "z": -1.4604528332980, "theta": 0.8353281706379,
                 "psi": -7.8555281128244, "phi": 0.1205543897884, "psif": -4.6198904039403,
                 "betar": 1.8472554144217, "betaf": 2.4548072904550}
PRINTED_DECIMALS = 13
"""Every value of the table is printed with 13 decimals."""
ULP = 10.0 ** -PRINTED_DECIMALS
ALLOWED = 5 * ULP
"""The inputs' rounding carried through (see the module docstring)."""


@pytest.fixture(scope="module")
def bike():
    return NonlinearWhipple(bm.parameters("benchmark"))


@pytest.fixture(scope="module")
def basu(bike):
    """bikemass's state from the table's, and its rates and accelerations in the table's terms."""
    p = bike.parameters
    rr = p.rR
    roll = math.pi / 2 - STATE["psi"]                 # their lean is from the horizontal, the other way
    steer = -STATE["psif"]
    yaw = -STATE["theta"]
    # the rear contact's forward speed from the rear wheel centre's velocity (their x is backward)
    u_lon = -RATES["x"] - rr * RATES["theta"] * math.cos(STATE["psi"])
    state = np.array([0.0, 0.0, yaw, roll, 0.0, steer, 0.0, u_lon, -RATES["psi"], -RATES["psif"]])
    c = bike.configuration(state)
    u, ud = c.speeds, c.speed_rates
    # speeds: u_lon, u_lat, yaw, roll, pitch, rear wheel, steer, front wheel rates
    s3, c3, s4, c4 = math.sin(yaw), math.cos(yaw), math.sin(roll), math.cos(roll)
    y3, y4, a3, a4 = u[2], u[3], ud[2], ud[3]
    x1d = u[0] * c3 - u[1] * s3
    x2d = u[0] * s3 + u[1] * c3
    x1dd = ud[0] * c3 - u[0] * s3 * y3 - ud[1] * s3 - u[1] * c3 * y3
    x2dd = ud[0] * s3 + u[0] * c3 * y3 + ud[1] * c3 - u[1] * s3 * y3
    # the rear wheel centre: (x - rR sin(yaw) sin(roll), y + rR cos(yaw) sin(roll), -rR cos(roll))
    d_ss = c3 * y3 * s4 + s3 * c4 * y4
    d_cs = -s3 * y3 * s4 + c3 * c4 * y4
    dd_ss = (-s3 * y3 ** 2 + c3 * a3) * s4 + 2 * c3 * y3 * c4 * y4 + s3 * (-s4 * y4 ** 2 + c4 * a4)
    dd_cs = (-c3 * y3 ** 2 - s3 * a3) * s4 - 2 * s3 * y3 * c4 * y4 + c3 * (-s4 * y4 ** 2 + c4 * a4)
    rates = {"x": -(x1d - rr * d_ss), "y": x2d + rr * d_cs, "z": -rr * s4 * y4, "theta": -u[2], "psi": -u[3],
             "phi": -u[4], "psif": -u[6], "betar": -u[5], "betaf": -u[7]}
    accelerations = {"x": -(x1dd - rr * dd_ss), "y": x2dd + rr * dd_cs, "z": -rr * (a4 * s4 + y4 ** 2 * c4),
                     "theta": -ud[2], "psi": -ud[3], "phi": -ud[4], "psif": -ud[6], "betar": -ud[5],
                     "betaf": -ud[7]}
    pitch = math.pi - c.pitch                          # their pitch: the rear frame's from the ground, pi upright
    return {"pitch": pitch, "height": rr * c4, "rates": rates, "accelerations": accelerations}


def test_basu_mandal_table_1_configuration(basu):
    """The pitch solved from the holonomic constraint, and the rear wheel centre's height."""
    assert basu["pitch"] == pytest.approx(STATE["phi"], abs=ULP)         # measured 5.1e-14
    assert basu["height"] == pytest.approx(STATE["z"], abs=ULP)


@pytest.mark.parametrize("name", sorted(RATES))
def test_basu_mandal_table_1_speeds(basu, name):
    """The dependent speeds (yaw, pitch, wheel rates, the centre's velocity) from the independent ones."""
    assert basu["rates"][name] == pytest.approx(RATES[name], abs=ALLOWED, rel=0)       # measured <= 1.4e-13


@pytest.mark.parametrize("name", sorted(ACCELERATIONS))
def test_basu_mandal_table_1_accelerations(basu, name):
    """Every second derivative of Table 1, to the 13 decimals it prints."""
    assert basu["accelerations"][name] == pytest.approx(ACCELERATIONS[name], abs=ALLOWED, rel=0)
    assert basu["accelerations"][name] == pytest.approx(ACCELERATIONS[name], rel=1e-12, abs=0)


def test_static_normal_forces_are_the_closed_form(bike):
    """At rest upright (and rolling straight at 5 m/s), the front wheel carries the moment of the
    weights about the rear contact over the wheelbase; the rear, the rest of the weight (the
    vertical force balance; the model's multiplier gives the front's)."""
    p = bike.parameters
    masses = {"mR": (p.mR, 0.0), "mB": (p.mB, p.xB), "mH": (p.mH, p.xH), "mF": (p.mF, p.w)}
    front = p.g * sum(m * x for m, x in masses.values()) / p.w
    rear = p.g * sum(m for m, _ in masses.values()) - front
    assert front == pytest.approx(309.3035294117647, rel=1e-12)     # 9.81 * 32.16 / 1.02 N
    assert rear == pytest.approx(612.8364705882353, rel=1e-12)      # 9.81 * 94 N - front
    for speed in (0.0, 5.0):
        state = np.zeros(10)
        state[7] = speed
        forces = bike.constraint_forces(state)
        assert -forces[4] == pytest.approx(front, abs=1e-9)
        np.testing.assert_allclose(forces[:4], 0.0, atol=1e-9)       # no friction needed


def test_no_singularity_at_zero_steer(bike):
    """The dependent speeds are well defined upright and straight and at zero steer while rolled."""
    for roll in (0.0, 0.3, -0.6):
        theta = bike.pitch(roll, 0.0)
        A = bike._constraints(roll, theta, 0.0)
        assert np.linalg.cond(A[:, 3:]) < 1e3           # the generated order: the dependent speeds last
        r = bike.rates(np.array([0, 0, 0, roll, 0, 0.0, 0, 4.0, 0.1, -0.2]))
        assert np.all(np.isfinite(r))


def test_straight_run_is_steady(bike):
    """Upright, straight at 5 m/s: every acceleration vanishes, the wheels turn at -v/r (closed form)."""
    state = np.zeros(10)
    state[7] = 5.0
    c = bike.configuration(state)
    np.testing.assert_allclose(c.accelerations, 0.0, atol=1e-12)
    p = bike.parameters
    assert c.speeds[5] == pytest.approx(-5.0 / p.rR, rel=1e-14)
    assert c.speeds[7] == pytest.approx(-5.0 / p.rF, rel=1e-14)


def _fresh_module():
    sm = pytest.importorskip("sympy")  # noqa: F841  (the derivation needs it)
    from bikemass.models.derive.nonlinear import derive_nonlinear, module_source_nonlinear

    module = types.ModuleType("fresh_nonlinear_whipple")
    exec(compile(module_source_nonlinear(derive_nonlinear()), "<fresh>", "exec"), module.__dict__)
    return module


@pytest.mark.slow
def test_generated_code_matches_a_fresh_derivation():
    """The shipped code against the derivation run again (about 25 s): the same functions, the
    same values (1e-12 relative) at seeded random configurations, speeds and parameters."""
    fresh = _fresh_module()
    assert fresh.PARAMETERS == shipped.PARAMETERS and fresh.SPEEDS == shipped.SPEEDS
    assert fresh.DEPENDENT == shipped.DEPENDENT and fresh.FUNCTIONS == shipped.FUNCTIONS
    rng = random.Random(33)
    base = bm.parameters("benchmark").to_dict()
    for _ in range(3):
        values = [base[name] * rng.uniform(0.8, 1.2) for name, _, _ in shipped.PARAMETERS]
        a, b = fresh.bind(*values), shipped.bind(*values)
        for (name, args, _), f, g in zip(shipped.FUNCTIONS, a, b):
            point = [rng.uniform(-0.5, 0.5) for _ in args]
            for x, y in zip(f(*point), g(*point)):
                x, y = np.asarray(x, float), np.asarray(y, float)
                np.testing.assert_allclose(y, x, rtol=1e-12, atol=1e-12 * max(1.0, np.max(np.abs(x))),
                                           err_msg=name)
