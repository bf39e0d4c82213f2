"""The ``flexible`` member's parameters: the rear frame's twist and the fork's bending, each reduced from
the beam model of its tubes to one rotation about an axis, with its stiffness and its tubes' inertia
(docs/models-flexible.md).

From Python::

    bike = bm.load_bicycle("jamis")
    params = bm.parameters(bike, bm.load_rider("relaxed"))
    flexible = compliances(bike, "steel")                  # the beam models, reduced
    model = build("flexible", params, compliances=flexible)    # bikemass.models.family.build

Any combination with the member takes them the same way (``"tyre+flexible"``, ``"rider-lean+flexible"``,
...).  An infinitely stiff compliance (``None``) holds its coordinate at zero: ``compliances(bike,
"steel").rigid()`` gives back the bicycle without the member, to round-off.
"""

from dataclasses import dataclass, fields, replace


from ....core.errors import InputError
from ...plausibility import warn
from ...compliance import Compliance, compliance_from_node

COORDINATES = {"frame": "frame-twist", "fork": "fork-bending"}
"""Each compliance's coordinate (the state's name in the linear model)."""
_KEYS = {"frame": "r", "fork": "f"}
_PLACEHOLDER = Compliance("held", (0.0, 0.0), (1.0, 0.0), 1e4, 0.0, (0.0, 0.0), 0.0)
"""Values for a compliance held rigid (its coordinate is removed, so they enter nothing)."""


STEER_DAMPING = 0.34
"""Default viscous damping of the steering bearings (N m s/rad): 0.34 +/- 0.04, identified from the damped
steer oscillations of the Davis instrumented bicycle (front wheel off the ground, springs on the bars;
Moore 2012, PhD dissertation "Human Control of a Bicycle", UC Davis, ch. "Davis Instrumented
Bicycle", "Bearing Friction"; docs/models-flexible.md, "Damping")."""


MAX_STEER_DAMPING = 1e3
"""Steering-bearing dampings (N m s/rad) above this are warned about."""


@dataclass(frozen=True)
class Compliances:
    """The rear frame's twist and the fork's bending (:class:`~bikemass.models.compliance.Compliance`);
    ``None`` is infinitely stiff (the coordinate held at zero).  ``steer_damping`` (N m s/rad) is the
    viscous damping of the steering bearing: a torque ``-steer_damping * steer rate`` between the front
    frame and the head tube (0 when not given: :func:`bikemass.fe.flexible.compliances` gives the
    default :data:`STEER_DAMPING`)."""

    frame: Compliance = None
    fork: Compliance = None
    steer_damping: float = 0.0

    def __post_init__(self):
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "steer_damping":
                if isinstance(value, bool) or not isinstance(value, (int, float)) or not value >= 0 or (
                        value == float("inf")):
                    raise InputError("compliances", f.name, f"a finite number >= 0 (N m s/rad), got {value!r}")
                object.__setattr__(self, f.name, float(value))
                if value > MAX_STEER_DAMPING:
                    warn(f"compliances: steer_damping = {value:.6g} N m s/rad is above {MAX_STEER_DAMPING:g} N m s/rad "
                         "(a steering damper's: 0..10 N m s/rad); computed as given")
            elif value is not None and not isinstance(value, Compliance):
                raise InputError("compliances", f.name, f"a Compliance or None, got {type(value).__name__}")

    def values(self, benchmark=None):
        """``{name: float}`` of the member's parameters (:mod:`bikemass.models.derive.flexible`): each
        axis, stiffness, and the particle that carries its tubes' modal inertia exactly (mass ``L**2/m``
        at ``(Jz/L, -Jx/L)``, sideways ``m/L`` per radian; none for tubes without inertia); each
        compliance's viscous damping ``2 zeta sqrt(k J)`` from its damping ratio ``zeta``, stiffness
        ``k`` and clamped inertia ``J`` (:meth:`clamped_inertias`, from the ``benchmark`` parameters, a
        mapping with the 26 names; without them the compliances are undamped); the steering bearing's
        damping ``cs``."""
        inertia = self.clamped_inertias(benchmark) if benchmark is not None else {}
        out = {"cs": self.steer_damping}
        for which, key in _KEYS.items():
            c = getattr(self, which) or _PLACEHOLDER
            J = inertia.get(which, 0.0)
            out[f"c{key}"] = 2.0 * c.damping_ratio * (c.stiffness * J) ** 0.5 if J > 0 else 0.0
            out[f"x{key}"], out[f"z{key}"] = c.point
            out[f"n{key}x"], out[f"n{key}z"] = c.direction
            out[f"k{key}"] = c.stiffness
            L, (Jx, Jz), m = c.modal_momentum, c.modal_moment, c.modal_mass     # (checked by the Compliance)
            out[f"mt{key}"], out[f"xt{key}"], out[f"zt{key}"], out[f"dt{key}"] = (
                (L ** 2 / m, Jz / L, -Jx / L, m / L) if L != 0 else (0.0, 0.0, 0.0, 0.0))
        return out

    def clamped_inertias(self, benchmark):
        """``{"frame" or "fork": J}`` (kg m^2/rad^2): the inertia each compliance's coordinate moves with its
        parent body clamped (the frame's twist: the front frame, the front wheel and the frame tubes' modal
        mass; the fork's bending: the front wheel and the fork tubes' modal mass), from the ``benchmark``
        parameters (a mapping with ``w, rF, xH, zH, mH, IHxx, IHyy, IHzz, IHxz, mF, IFxx, IFyy``): the
        compliance's own vibration is at ``sqrt(k / J)``, as a bench test of the part clamped measures it."""
        b = benchmark
        wheel = (b["mF"], (b["w"], -b["rF"]), ((b["IFxx"], 0.0), (0.0, b["IFxx"])))
        front = (b["mH"], (b["xH"], b["zH"]), ((b["IHxx"], b["IHxz"]), (b["IHxz"], b["IHzz"])))
        out = {}
        for which, carried in (("frame", (front, wheel)), ("fork", (wheel,))):
            c = getattr(self, which)
            if c is None:
                continue
            (px, pz), (nx, nz) = c.point, c.direction
            J = c.modal_mass
            for mass, (x, z), ((Ixx, Ixz), (_, Izz)) in carried:
                rx, rz = x - px, z - pz
                along = rx * nx + rz * nz
                J += mass * (rx * rx + rz * rz - along * along) + nx * nx * Ixx + 2 * nx * nz * Ixz + nz * nz * Izz
            out[which] = float(J)
        return out

    @property
    def held(self):
        """The coordinates held at zero (the infinitely stiff compliances)."""
        return tuple(COORDINATES[w] for w in COORDINATES if getattr(self, w) is None)

    def rigid(self):
        """Both infinitely stiff, and no steering damper: the bicycle without the member."""
        return Compliances()

    def undamped(self):
        """The same compliances with no structural damping and no steering damper."""
        return replace(self, steer_damping=0.0, **{w: replace(c, damping_ratio=0.0) for w in COORDINATES
                                                    if (c := getattr(self, w))})

    def scaled(self, stiffness=1.0, inertia=1.0):
        """Both with their stiffness and their tubes' inertia multiplied by factors."""
        return replace(self, **{w: c.scaled(stiffness, inertia) for w in COORDINATES if (c := getattr(self, w))})

    def massless(self):
        """Both with tubes of no inertia (what rides on them keeps its own)."""
        return self.scaled(inertia=0.0)

    def to_dict(self):
        """``{"frame": ..., "fork": ...}``: each compliance's plain values (SI,
        :meth:`~bikemass.models.compliance.Compliance.units`), ``"rigid"`` for one held rigid: the
        ``flexible:`` block of a parameter file (:func:`compliances_from_node` reads it back), and
        ``steer_damping`` (N m s/rad)."""
        return {**{w: (c.to_dict() if (c := getattr(self, w)) is not None else "rigid") for w in COORDINATES},
                "steer_damping": self.steer_damping}


def compliances_from_node(node):
    """:class:`Compliances` of a parameter file's ``flexible:`` block (a config
    :class:`~bikemass.core.config.Node`): ``frame:`` and ``fork:``, each a compliance's fields
    (:class:`~bikemass.models.compliance.Compliance`, SI or with units) or ``rigid``, and the steering
    bearing's ``steer_damping`` (N m s/rad; 0 without it)."""
    node.check_keys(optional=(*COORDINATES, "steer_damping", "source", "note"))
    if not any(node.has(which) for which in COORDINATES):      # an empty block: nothing flexible, said nowhere
        node.fail(f"{' and '.join(f'{c}:' for c in COORDINATES)}, each a compliance or rigid (at least one given)")
    out = {}
    for which in COORDINATES:
        child = node.get(which, "rigid")
        out[which] = None if child.value in ("rigid", "infinite", None) else compliance_from_node(child)
    if node.has("steer_damping"):
        out["steer_damping"] = node["steer_damping"].number("damping", nonnegative=True)
    return Compliances(**out)
