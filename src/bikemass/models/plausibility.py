"""Physical plausibility: errors where the model is undefined, warnings where the input is legal
but unusual.

Errors (:class:`~bikemass.core.errors.InputError`, naming the file and key): a steer-axis tilt
``lam`` outside (-pi/2, pi/2), an inertia tensor that is not symmetric, not positive
semi-definite or violates the triangle inequality (a parameter set's bodies only warn:
the linear model is defined for them), a stiffness matrix that is not
symmetric or not positive definite.  Warnings (:class:`~bikemass.core.errors.BikemassWarning`,
one line each): a steer axis leaning forward (``lam < 0``), negative trail, a trail longer than the wheelbase, a wheel radius beyond any
wheel, a wheelbase beyond any bicycle's, wheels that overlap, a centre of mass below the
ground (z > 0) or far from the bicycle, a rider far from the bicycle or of a mass no rider
has, masses beyond any bicycle; gravity, a steer-axis tilt, a body's radius of gyration or a
frame stiffness no bicycle has (:func:`warn_absurd`, :func:`warn_stiffness`).  The thresholds
are stated below.
"""

import math
import numbers
import warnings

import numpy as np

from ..core.errors import BikemassWarning, InputError, short
from ..core.real import finite_real
from .names import NAMES, NONNEGATIVE, POSITIVE

RELATIVE_TOLERANCE = 1e-9
"""Asymmetry, negative moments and triangle excess below this fraction of the largest moment pass."""
MAX_MASS = 500.0
"""A total mass above this (kg) is warned about: no bicycle with rider weighs that much."""
RIDER_REACH = 1.0
"""A rider's centre of mass more than this (m) ahead of the front or behind the rear contact,
or more than 3 m above the ground, is warned about."""
RIDER_HEIGHT = 3.0
"""Highest plausible rider centre of mass above the ground (m)."""
MAX_WHEEL_RADIUS = 1.5
"""A wheel radius above this (m) is warned about (a high-wheeler's front wheel is about 0.75 m)."""
MAX_WHEELBASE = 2.5
"""A wheelbase above this (m) is warned about (a long-tail or long-john cargo bicycle has up to about
2.3 m, a tandem about 1.8 m)."""
RIDER_MASS = (10.0, 300.0)
"""Rider masses (kg) outside this range are warned about (a small child to the heaviest adults)."""


GRAVITY = (1.0, 30.0)
"""Accelerations of gravity (m/s^2) outside this range are warned about (the Moon's 1.62 to
Jupiter's 24.8)."""
MAX_TILT = 1.3
"""A steer-axis tilt ``|lam|`` above this (rad, 74 deg from vertical) is warned about: the steer
axis nearly horizontal (a chopper's is about 0.7 rad)."""
MAX_GYRATION = 5.0
"""A body's radius of gyration ``sqrt(largest principal moment / mass)`` above this (m) is warned
about: a body with such a moment for its mass reaches beyond any bicycle (a mass of 1e-12 kg
with a fork's inertia)."""
STIFFNESS_RANGE = (10.0, 1e10)
"""Frame stiffness eigenvalues (N m/rad) outside this range are warned about (measured frames:
1e3 to 1e5)."""


def warn(message):
    """Issue one :class:`BikemassWarning` (shown as one line by the command line)."""
    warnings.warn(message, BikemassWarning, stacklevel=3)


def inertia_problem(tensor):
    """Why the 3x3 ``tensor`` (kg m^2) is not an inertia tensor, or ``None`` if it is one."""
    tensor = np.asarray(tensor, float)
    scale = max(np.abs(tensor).max(), 1e-300) * RELATIVE_TOLERANCE
    if np.abs(tensor - tensor.T).max() > scale:
        return "a symmetric inertia tensor (kg m^2)"
    moments = np.linalg.eigvalsh(tensor)
    if moments[0] < -scale:
        return (f"an inertia tensor with principal moments >= 0 (positive semi-definite), got "
                f"{moments[0]:.6g} kg m^2")
    if moments[2] > moments[0] + moments[1] + scale:
        return (f"an inertia tensor obeying the triangle inequality (largest principal moment "
                f"{moments[2]:.6g} <= {moments[0]:.6g} + {moments[1]:.6g} kg m^2)")
    return None


def check_inertia(tensor, node, key=None):
    """``tensor`` if it is an inertia tensor, else fail at ``node`` (or its ``key``)."""
    problem = inertia_problem(tensor)
    if problem:
        node.fail(problem, key)
    return np.asarray(tensor, float)


def check_stiffness(node):
    """The 2x2 matrix at ``node`` (N m/rad): symmetric and positive definite, else an error."""
    S = node.matrix("stiffness", (2, 2))
    if abs(S[0, 1] - S[1, 0]) > RELATIVE_TOLERANCE * np.abs(S).max():
        node.fail(f"a symmetric matrix (equal off-diagonal terms), got {S[0, 1]:.6g} and {S[1, 0]:.6g}")
    if not np.all(np.linalg.eigvalsh(S) > 0):
        node.fail("a positive definite 2x2 stiffness matrix (N m/rad)")
    warn_stiffness(S, node.source)
    return S


def check_parameter_file(params, source, prefix=""):
    """Errors and warnings for a benchmark parameter set read from ``source`` (YAML, JSON,
    BicycleParameters text or parameter-set file alike; ``prefix`` goes before each key named,
    e.g. ``values.``): the errors of :func:`check_parameters`, a wheel inertia breaking the
    triangle inequality and a frame inertia breaking it, each a warning naming the key (no rigid
    body has such moments, but the linear model is defined: ``IByy`` and ``IHyy`` do not enter
    it, a wheel's ``Iyy`` only as spin momentum; optimised published sets carry such values)."""
    check_parameters(params, source, prefix)
    warn_absurd(params, source, prefix)
    for body in "RF":
        xx, yy = getattr(params, f"I{body}xx"), getattr(params, f"I{body}yy")
        if yy > 2 * xx * (1 + RELATIVE_TOLERANCE):
            warn(f"{source}: {prefix}I{body}yy = {yy:.6g} kg m^2 breaks the triangle inequality of a wheel "
                 f"(I{body}yy <= 2 I{body}xx = {2 * xx:.6g}): no rigid wheel has it; computed as given")
    for body in "BH":
        moments = np.linalg.eigvalsh(params.inertia(body))
        scale = max(moments[2], 1e-300) * RELATIVE_TOLERANCE
        if moments[2] > moments[0] + moments[1] + scale:
            # the in-plane block is positive semi-definite (checked above), so Iyy is the moment off
            warn(f"{source}: {prefix}I{body}yy: the {body} inertia breaks the triangle inequality (largest "
                 f"principal moment {moments[2]:.6g} > {moments[0]:.6g} + {moments[1]:.6g} kg m^2, with "
                 f"I{body}yy = {getattr(params, f'I{body}yy'):.6g}); I{body}yy does not enter the linear model, "
                 "which is computed")


def warn_absurd(params, source, prefix=""):
    """Warnings for values the model computes but no bicycle has: gravity outside
    :data:`GRAVITY`, a steer axis tilted more than :data:`MAX_TILT`, a body (or a wheel with
    mass) whose radius of gyration exceeds :data:`MAX_GYRATION`."""
    if not GRAVITY[0] <= params.g <= GRAVITY[1]:
        warn(f"{source}: {prefix}g = {params.g:.6g} m/s^2 is outside {GRAVITY[0]:g}..{GRAVITY[1]:g} m/s^2 "
             "(Earth's is 9.81); computed as given")
    if abs(params.lam) > MAX_TILT:
        warn(f"{source}: {prefix}lam = {params.lam:.6g} rad tilts the steer axis more than {MAX_TILT:g} rad from "
             "vertical (nearly horizontal; bicycles have 0.1..0.7 rad); computed as given")
    for body in "BHRF":
        mass = getattr(params, f"m{body}")
        if mass <= 0:
            continue
        largest = float(np.linalg.eigvalsh(params.inertia(body))[-1])
        if largest > mass * MAX_GYRATION ** 2:
            warn(f"{source}: {prefix}m{body} = {mass:.6g} kg with a largest moment of inertia of {largest:.6g} "
                 f"kg m^2: a radius of gyration of {math.sqrt(largest / mass):.3g} m, more than {MAX_GYRATION:g} m "
                 "(no bicycle's body reaches that far); computed as given")


def warn_stiffness(S, source):
    """Warn if the 2x2 frame stiffness ``S`` (N m/rad) has an eigenvalue outside :data:`STIFFNESS_RANGE`."""
    low, high = np.linalg.eigvalsh((np.asarray(S, float) + np.asarray(S, float).T) / 2)
    if low < STIFFNESS_RANGE[0] or high > STIFFNESS_RANGE[1]:
        warn(f"{source}: a frame stiffness S with eigenvalues {low:.3g} and {high:.3g} N m/rad, outside "
             f"{STIFFNESS_RANGE[0]:g}..{STIFFNESS_RANGE[1]:g} (measured frames: 1e3..1e5); computed as given")


def check_parameters(params, source, prefix=""):
    """``params`` (:class:`~bikemass.models.parameters.BenchmarkParameters`) if the model is defined for
    them, else InputError naming ``source`` and the parameter (``prefix`` + name): finite values;
    ``w``, ``g``, ``mB``, ``mH`` positive; wheel radii, wheel masses and moments of inertia
    ``>= 0`` (zero is the point-wheel, point-mass limit); a massless wheel without inertia, a
    point wheel (radius 0) without spin inertia; ``lam`` in (-pi/2, pi/2); the B and H inertia
    tensors positive semi-definite.  For parameter sets read from files and changed after they
    were read (sweep configurations, uncertainty draws); plain arithmetic, a few microseconds.
    The triangle inequality is not asked for here: a measured near-planar frame sits on its
    boundary and a small spread crosses it."""
    values = {key: getattr(params, key) for key in NAMES}
    for key, value in values.items():
        if isinstance(value, bool) or not isinstance(value, numbers.Real):
            raise InputError(source, prefix + key, f"a number, got {short(value)}")
        if not finite_real(value):
            raise InputError(source, prefix + key, f"a finite number, got {short(value)}")
        value = values[key] = float(value)
        if value <= 0 and key in POSITIVE:
            raise InputError(source, prefix + key, f"a positive number, got {value:.6g}")
        if value < 0 and key in NONNEGATIVE:
            raise InputError(source, prefix + key, f"a number >= 0, got {value:.6g}")
    if not -math.pi / 2 < values["lam"] < math.pi / 2:
        raise InputError(source, prefix + "lam", f"a steer-axis tilt in (-pi/2, pi/2) rad (the steer axis not "
                                                 f"horizontal), got {values['lam']:.6g}")
    for body in "RF":
        mass, radius = values[f"m{body}"], values[f"r{body}"]
        for moment in ("xx", "yy"):
            if mass == 0 and values[f"I{body}{moment}"] > 0:
                raise InputError(source, f"{prefix}I{body}{moment}", f"0 for a massless wheel (m{body} = 0), "
                                 f"got {values[f'I{body}{moment}']:.6g} kg m^2")
        if radius == 0 and values[f"I{body}yy"] > 0:
            raise InputError(source, f"{prefix}I{body}yy", f"0 for a point wheel (r{body} = 0: no spin momentum), "
                             f"got {values[f'I{body}yy']:.6g} kg m^2")
    for body in "BH":
        xx, zz, xz = values[f"I{body}xx"], values[f"I{body}zz"], values[f"I{body}xz"]
        scale = max(xx, zz, abs(xz))
        if xx * zz - xz * xz < -RELATIVE_TOLERANCE * (scale * scale):      # not ** 2: no OverflowError
            raise InputError(source, f"{prefix}I{body}xz", f"an inertia tensor with principal moments >= 0 (I{body}xz^2 <= "
                             f"I{body}xx I{body}zz), got I{body}xx {xx:.6g}, I{body}zz {zz:.6g}, I{body}xz {xz:.6g} kg m^2")
    return params


def refused_parameters(columns, rows):
    """(B,) bool: the rows of stacked parameter sets that :func:`check_parameters` refuses.

    Parameters
    ----------
    columns : dict
        ``{name: (B,) float64 array or float}`` for each of the 26 names (SI; a float is the
        same in every row; values that are not real numbers have no place here: the caller
        sends those rows to :func:`check_parameters`).
    rows : int
        B, the number of rows.

    Returns
    -------
    numpy.ndarray of bool, shape (B,)
        True where :func:`check_parameters` raises: its tests, in the same order-free float64
        arithmetic, so a row is refused here exactly when that function refuses it (which then
        says why).
    """
    refused = np.zeros(rows, dtype=bool)
    v = {key: np.asarray(columns[key], dtype=float) for key in NAMES}
    for key in NAMES:
        refused |= ~np.isfinite(v[key])
        if key in POSITIVE:
            refused |= v[key] <= 0
        elif key in NONNEGATIVE:
            refused |= v[key] < 0
    refused |= ~((-math.pi / 2 < v["lam"]) & (v["lam"] < math.pi / 2))
    for body in "RF":
        massless = v[f"m{body}"] == 0
        refused |= massless & ((v[f"I{body}xx"] > 0) | (v[f"I{body}yy"] > 0))
        refused |= (v[f"r{body}"] == 0) & (v[f"I{body}yy"] > 0)
    for body in "BH":
        xx, zz, xz = v[f"I{body}xx"], v[f"I{body}zz"], v[f"I{body}xz"]
        scale = np.maximum(np.maximum(xx, zz), np.abs(xz))
        with np.errstate(invalid="ignore", over="ignore"):
            refused |= xx * zz - xz * xz < -RELATIVE_TOLERANCE * (scale * scale)
    return refused


def warn_parameters(params, source):
    """Warnings for a legal but unusual benchmark parameter set read from or built for ``source``."""
    if params.lam < 0:
        warn(f"{source}: steer-axis tilt lam = {params.lam:.4g} rad is negative (the steer axis leans forward "
             "of vertical)")
    if params.c < 0:
        warn(f"{source}: negative trail c = {params.c:.4g} m (the front contact is ahead of where the "
             "steer axis meets the ground)")
    masses = {"B": params.mB, "H": params.mH}
    for body, z in (("B", params.zB), ("H", params.zH)):
        if z > 0:
            warn(f"{source}: centre of mass z{body} = {z:.4g} m is below the ground (z points down)")
    if abs(params.c) > params.w:
        warn(f"{source}: trail c = {params.c:.4g} m is longer than the wheelbase w = {params.w:.4g} m")
    for wheel, r in (("rR", params.rR), ("rF", params.rF)):
        if r > MAX_WHEEL_RADIUS:
            warn(f"{source}: wheel radius {wheel} = {r:.4g} m is more than {MAX_WHEEL_RADIUS:g} m")
    if params.w > MAX_WHEELBASE:
        warn(f"{source}: wheelbase w = {params.w:.4g} m is more than {MAX_WHEELBASE:g} m (a long cargo bicycle's)")
    if params.w < params.rR + params.rF:
        warn(f"{source}: the wheels overlap: wheelbase w = {params.w:.4g} m is less than rR + rF = "
             f"{params.rR + params.rF:.4g} m")
    for body, x, z in (("B", params.xB, params.zB), ("H", params.xH, params.zH)):
        if not (-RIDER_REACH <= x <= params.w + RIDER_REACH and z >= -RIDER_HEIGHT):
            warn(f"{source}: centre of mass [x{body}, z{body}] = [{x:.4g}, {z:.4g}] m is far from the bicycle "
                 f"(more than {RIDER_REACH:g} m beyond a wheel contact, or above {RIDER_HEIGHT:g} m)")
    total = params.mR + params.mF + sum(masses.values())
    if total > MAX_MASS:
        warn(f"{source}: total mass {total:.4g} kg is more than {MAX_MASS:g} kg")


def warn_rider(rider_com, geometry, source, rider_name, mass=None):
    """Warn if the rider's centre of mass (m, benchmark frame) is far from the bicycle or below the
    ground, or the rider's ``mass`` (kg) is outside :data:`RIDER_MASS`."""
    if mass is not None and not RIDER_MASS[0] <= mass <= RIDER_MASS[1]:
        warn(f"{source}: rider {rider_name} weighs {mass:.4g} kg, outside {RIDER_MASS[0]:g}..{RIDER_MASS[1]:g} kg")
    x, y, z = rider_com
    if z > 0:
        warn(f"{source}: rider {rider_name}'s centre of mass is below the ground (z = {z:.4g} m)")
    elif not (-RIDER_REACH <= x <= geometry.wheelbase + RIDER_REACH and z >= -RIDER_HEIGHT
              and abs(y) <= RIDER_REACH):
        warn(f"{source}: rider {rider_name}'s centre of mass [{x:.4g}, {y:.4g}, {z:.4g}] m is far from "
             f"the bicycle (more than {RIDER_REACH:g} m beyond a wheel contact, or above {RIDER_HEIGHT:g} m)")


EN15194_FRONT_SHARE = 0.25
"""EN 15194 (electrically power assisted cycles), like EN 14764 and ISO 4210 for other bicycles:
with the rider seated, at least 25 % of the weight of bicycle and rider on the front wheel."""


def front_load(params):
    """``(share, front mass)``: the fraction of the total weight on the front wheel and the mass (kg)
    it carries, the bicycle standing on level ground: moments about the rear contact give the front
    contact's load ``m_T g x_T / w``, with ``m_T = mR + mB + mH + mF`` and the total centre of mass
    ``x_T = (mB xB + mH xH + mF w) / m_T`` (the rear wheel's at x = 0).

    Examples
    --------
    >>> import bikemass as bm
    >>> from bikemass.models.plausibility import front_load
    >>> share, kg = front_load(bm.parameters("benchmark"))
    >>> print(f"{share:.4f} of {kg / share:.0f} kg")
    0.3354 of 94 kg
    """
    total = params.mR + params.mB + params.mH + params.mF
    moment = params.mB * params.xB + params.mH * params.xH + params.mF * params.w
    share = moment / (total * params.w)
    return float(share), float(share * total)


def front_load_problem(params, source):
    """The warning line where a bicycle with its rider seated puts less than
    :data:`EN15194_FRONT_SHARE` of the weight on the front wheel (EN 15194's rule); else None."""
    share, kg = front_load(params)
    if share >= EN15194_FRONT_SHARE:
        return None
    return (f"{source}: front wheel load {share * 100:.1f} % of bicycle and rider ({kg:.1f} kg), below the "
            f"{EN15194_FRONT_SHARE * 100:.0f} % EN 15194 asks with the rider seated: the front wheel may lift "
            "or slide (steep climbs, hard acceleration)")
