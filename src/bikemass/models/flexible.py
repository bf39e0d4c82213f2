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


from ..core.errors import InputError
from .compliance import Compliance, compliance_from_node

COORDINATES = {"frame": "frame-twist", "fork": "fork-bending"}
"""Each compliance's coordinate (the state's name in the linear model)."""
_KEYS = {"frame": "r", "fork": "f"}
_PLACEHOLDER = Compliance("held", (0.0, 0.0), (1.0, 0.0), 1.0, 0.0, (0.0, 0.0), 0.0)
"""Values for a compliance held rigid (its coordinate is removed, so they enter nothing)."""


@dataclass(frozen=True)
class Compliances:
    """The rear frame's twist and the fork's bending (:class:`~bikemass.models.compliance.Compliance`);
    ``None`` is infinitely stiff (the coordinate held at zero)."""

    frame: Compliance = None
    fork: Compliance = None

    def __post_init__(self):
        for f in fields(self):
            value = getattr(self, f.name)
            if value is not None and not isinstance(value, Compliance):
                raise InputError("compliances", f.name, f"a Compliance or None, got {type(value).__name__}")

    def values(self):
        """``{name: float}`` of the member's parameters (:mod:`bikemass.models.derive.flexible`): each
        axis, stiffness, and the particle that carries its tubes' modal inertia exactly (mass ``L**2/m``
        at ``(Jz/L, -Jx/L)``, sideways ``m/L`` per radian; none for tubes without inertia)."""
        out = {}
        for which, key in _KEYS.items():
            c = getattr(self, which) or _PLACEHOLDER
            out[f"x{key}"], out[f"z{key}"] = c.point
            out[f"n{key}x"], out[f"n{key}z"] = c.direction
            out[f"k{key}"] = c.stiffness
            L, (Jx, Jz), m = c.modal_momentum, c.modal_moment, c.modal_mass
            if (L == 0) != (m == 0) or (L == 0 and (Jx != 0 or Jz != 0)):
                raise InputError(f"compliance {c.name}", "modal_momentum", "a nonzero lateral momentum and modal "
                                 "mass together, or none of L, J and m (a field is carried by one particle)")
            out[f"mt{key}"], out[f"xt{key}"], out[f"zt{key}"], out[f"dt{key}"] = (
                (L ** 2 / m, Jz / L, -Jx / L, m / L) if L != 0 else (0.0, 0.0, 0.0, 0.0))
        return out

    @property
    def held(self):
        """The coordinates held at zero (the infinitely stiff compliances)."""
        return tuple(COORDINATES[w] for w in COORDINATES if getattr(self, w) is None)

    def rigid(self):
        """Both infinitely stiff."""
        return Compliances()

    def scaled(self, stiffness=1.0, inertia=1.0):
        """Both with their stiffness and their tubes' inertia multiplied by factors."""
        return replace(self, **{w: c.scaled(stiffness, inertia) for w in COORDINATES if (c := getattr(self, w))})

    def massless(self):
        """Both with tubes of no inertia (what rides on them keeps its own)."""
        return self.scaled(inertia=0.0)

    def to_dict(self):
        """``{"frame": ..., "fork": ...}``: each compliance's plain values (SI,
        :meth:`~bikemass.models.compliance.Compliance.units`), ``"rigid"`` for one held rigid: the
        ``flexible:`` block of a parameter file (:func:`compliances_from_node` reads it back)."""
        return {w: (c.to_dict() if (c := getattr(self, w)) is not None else "rigid") for w in COORDINATES}


def compliances_from_node(node):
    """:class:`Compliances` of a parameter file's ``flexible:`` block (a config
    :class:`~bikemass.core.config.Node`): ``frame:`` and ``fork:``, each a compliance's fields
    (:class:`~bikemass.models.compliance.Compliance`, SI or with units) or ``rigid``."""
    node.check_keys(optional=(*COORDINATES, "source", "note"))
    out = {}
    for which in COORDINATES:
        child = node.get(which, "rigid")
        out[which] = None if child.value in ("rigid", "infinite", None) else compliance_from_node(child)
    return Compliances(**out)


