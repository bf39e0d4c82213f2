"""Tyre parameters of the ``tyre`` model: per wheel, lateral force per unit normal load from slip and camber.

A tyre file (YAML, read through the input gate; every coefficient carries its unit, ``1/rad`` or
``1/deg``, since tyre data are printed per degree as often as per radian)::

    front: {cornering_coefficient: 11.46 1/rad, camber_coefficient: 0.573 1/rad, relaxation_length: 0.175 m}
    rear:  {cornering_coefficient: 11.46 1/rad, camber_coefficient: 0.573 1/rad, relaxation_length: 0.175 m}

and optionally, per wheel, the moments about the ground normal: ``pneumatic_trail`` (a length) and
``twisting_coefficient`` (a moment per unit load per angle, ``m/rad`` or ``mm/deg``); both default to 0
(a measured pneumatic trail, and why it is not the default: :data:`MEASURED_TRAIL`, :data:`TRAIL_TYRES`).

Default (:data:`DEFAULT_TYRES`): 11.46 /rad, 0.573 /rad and 0.175 m on both wheels, the TU Delft
Bicycle Lab's values for the Batavus Browser's tyres (``mechmotum/bicycle-kickplate-model``,
``parameters.py``: "estimates from Andrew's dissertation"), i.e. from Dressel's measurements of
bicycle tyres (Dressel 2013, PhD thesis, University of Wisconsin-Milwaukee; Dressel & Rahman 2012,
Vehicle System Dynamics 50(8), "Measuring sideslip and camber characteristics of bicycle tyres"):
0.200 /deg and 0.0100 /deg, inside the ranges Dressel reports for 14 tyres (cornering 0.15 to
0.35 /deg, camber 0.0075 to 0.015 /deg, per unit load).
"""

import math
import os
from collections.abc import Mapping
from dataclasses import dataclass, field, fields

from ....core.config import Node, load_yaml
from ....core.errors import InputError
from ....core.gate import plain_input
from ...plausibility import warn

KEYS = ("cornering_coefficient", "camber_coefficient", "relaxation_length")
RELAXATION_RANGE = (1e-3, 10.0)
"""Relaxation lengths (m) outside this range are warned about (Dressel's bicycle tyres: 0.05 to
0.3 m)."""
CORNERING_RANGE = (1.0, 1e3)
"""Cornering coefficients (1/rad) outside this range are warned about (bicycle tyres: 8 to 17)."""
MAX_TRAIL = 0.1
"""Pneumatic trails (m) above this are warned about (a measured bicycle tyre's: 0.017 m, :data:`MEASURED_TRAIL`)."""
MAX_TWISTING = 0.1
"""Twisting torque coefficients (m/rad) above this are warned about (a measured tyre's camber moment: a few mm/rad)."""
MOMENT_KEYS = ("pneumatic_trail", "twisting_coefficient")
"""Optional keys: the tyre's moments about the ground normal (default 0, no moment)."""
_DIMENSIONS = {"cornering_coefficient": "inverse angle", "camber_coefficient": "inverse angle",
               "relaxation_length": "length"}


@dataclass(frozen=True)
class Tyre:
    """One tyre: lateral force ``N (C_alpha alpha + C_gamma gamma)`` lagging over ``relaxation_length``, and
    the moment about the ground normal ``-t_p F + N C_mgamma gamma`` (z down: positive turns the wheel to
    the right): the self-aligning moment of the force acting ``pneumatic_trail`` behind the contact, and
    the twisting torque of camber (``twisting_coefficient`` > 0 turns the wheel towards its lean).  Both
    default to zero (no moment)."""

    cornering_coefficient: float = field(metadata={"unit": "1/rad", "description": "d(F_y/N)/d(slip angle)"})
    camber_coefficient: float = field(metadata={"unit": "1/rad", "description": "d(F_y/N)/d(camber angle)"})
    relaxation_length: float = field(metadata={"unit": "m", "description": "distance rolled to build up the force"})
    pneumatic_trail: float = field(default=0.0, metadata={
        "unit": "m", "description": "distance behind the contact at which the lateral force acts (self-aligning moment)"})
    twisting_coefficient: float = field(default=0.0, metadata={
        "unit": "m/rad", "description": "d(M_z/N)/d(camber angle), towards the lean (twisting torque)"})

    def __post_init__(self):
        for f in fields(self):
            x = getattr(self, f.name)
            zero_ok = f.name in ("camber_coefficient", *MOMENT_KEYS)
            least = "a number >= 0" if zero_ok else "a positive number"
            if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x) or x < 0 or (
                    x == 0 and not zero_ok):
                raise InputError("tyre", f.name, f"{least} ({f.metadata['unit']}), got {x!r}")
            object.__setattr__(self, f.name, float(x))
        self._warn_absurd()

    def _warn_absurd(self):
        """Warn of coefficients no tyre has (:data:`RELAXATION_RANGE`, :data:`CORNERING_RANGE`, a
        camber coefficient above the cornering one): computed as given, but a relaxation length
        below about 1e-12 m or a cornering coefficient of 1e8 /rad also puts roots of 1e12 1/s
        and more beside the weave's, past what the critical speeds can be resolved from."""
        sigma, c_alpha, c_gamma = self.relaxation_length, self.cornering_coefficient, self.camber_coefficient
        if not RELAXATION_RANGE[0] <= sigma <= RELAXATION_RANGE[1]:
            warn(f"tyre: relaxation_length = {sigma:.6g} m is outside {RELAXATION_RANGE[0]:g}..{RELAXATION_RANGE[1]:g} m "
                 "(bicycle tyres: 0.05..0.3 m; the critical speeds of a much shorter one may be lost); "
                 "computed as given")
        if not CORNERING_RANGE[0] <= c_alpha <= CORNERING_RANGE[1]:
            warn(f"tyre: cornering_coefficient = {c_alpha:.6g} 1/rad is outside {CORNERING_RANGE[0]:g}.."
                 f"{CORNERING_RANGE[1]:g} 1/rad (bicycle tyres: 8..17 1/rad; the critical speeds of a much stiffer "
                 "one may be lost); computed as given")
        for name, value, unit, limit in (("pneumatic_trail", self.pneumatic_trail, "m", MAX_TRAIL),
                                         ("twisting_coefficient", self.twisting_coefficient, "m/rad", MAX_TWISTING)):
            if value > limit:
                warn(f"tyre: {name} = {value:.6g} {unit} is above {limit:g} {unit} (a measured bicycle tyre's pneumatic "
                     "trail: 0.017 m; its camber moment: a few mm/rad); computed as given")
        if c_gamma > c_alpha:
            warn(f"tyre: camber_coefficient = {c_gamma:.6g} 1/rad is more than the cornering_coefficient "
                 f"{c_alpha:.6g} 1/rad (bicycle tyres: about 0.05 of it); computed as given")


@dataclass(frozen=True)
class Tyres:
    """The front and rear tyres."""

    front: Tyre
    rear: Tyre

    def values(self):
        """``{name: float}`` of the generated code's tyre parameters."""
        f, r = self.front, self.rear
        out = {}
        for key, t in (("R", r), ("F", f)):
            out.update({f"Ca{key}": t.cornering_coefficient, f"Cg{key}": t.camber_coefficient,
                        f"sigma{key}": t.relaxation_length, f"tp{key}": t.pneumatic_trail,
                        f"Cmg{key}": t.twisting_coefficient})
        return out


DEFAULT_TYRE = Tyre(cornering_coefficient=11.46, camber_coefficient=0.573, relaxation_length=0.175)
"""The TU Delft Bicycle Lab's Browser tyre from Dressel's measurements (see the module docstring).
No moments: see :data:`MEASURED_TRAIL` for why the published pneumatic trail is not its default."""
DEFAULT_TYRES = Tyres(front=DEFAULT_TYRE, rear=DEFAULT_TYRE)

MEASURED_TRAIL = 0.0166
"""Pneumatic trail (m) of a measured bicycle tyre: the Schwalbe Energizer Plus 47-622 (28 x 1.75) at
400 kPa, Dell'Orto, Mastinu, Happee & Moore (2024), "Measurement of lateral characteristics and
identification of Magic Formula parameters of city and cargo bicycle tyres", Vehicle System Dynamics,
doi:10.1080/00423114.2024.2338143; their Pacejka-89 coefficients as the TU Delft lab's
``mechmotum/bicycle-kickplate-model`` (``tire_data.py``, ``SchwalbeT03_400kPa``) carries them,
linearised at zero slip and camber: ``t_p = -(dM_z/d alpha) / (dF_y/d alpha)``, 16.5 to 16.6 mm for
loads of 300 to 600 N (a right-handed axis system gives ``M_z = -t_p F_y`` whichever way its z axis
points, so the sign needs no convention: positive, the force acts behind the contact and the moment
turns the wheel towards its velocity, opposing the slip).  The same fit's camber moment,
``dM_z/d gamma``, is -7 to +6 mm/rad per unit load over those loads and changes sign at about 450 N:
no published twisting coefficient with a defensible sign was found, and it stays 0.

Not a default: with this trail and no twisting torque the default tyres turn the benchmark bicycle
unstable at every speed (its capsize root crosses at 2.97 m/s and stays unstable;
``docs/models.md``), the opposite of Bulsink, Doria, Lovato & Schwab (2015), who find measured tyre
moments stabilise capsize, mainly through the twisting torque that is missing here."""
TRAIL_TYRE = Tyre(cornering_coefficient=11.46, camber_coefficient=0.573, relaxation_length=0.175,
                  pneumatic_trail=MEASURED_TRAIL)
"""The default tyre with the measured pneumatic trail :data:`MEASURED_TRAIL` (no twisting torque)."""
TRAIL_TYRES = Tyres(front=TRAIL_TYRE, rear=TRAIL_TYRE)


def _tyre(node):
    node.check_keys(required=KEYS, optional=("note", *MOMENT_KEYS))
    moments = {}
    if node.has("pneumatic_trail"):
        moments["pneumatic_trail"] = node["pneumatic_trail"].number("length", nonnegative=True)
    if node.has("twisting_coefficient"):
        moments["twisting_coefficient"] = node["twisting_coefficient"].number("length per angle", nonnegative=True)
    return Tyre(cornering_coefficient=node["cornering_coefficient"].number("inverse angle", positive=True),
                camber_coefficient=node["camber_coefficient"].number("inverse angle", nonnegative=True),
                relaxation_length=node["relaxation_length"].number("length", positive=True), **moments)


def tyres_from_node(node):
    """:class:`Tyres` of a config :class:`~bikemass.core.config.Node` (``front:`` and ``rear:``)."""
    node.check_keys(required=("front", "rear"), optional=("name", "source", "description"))
    return Tyres(front=_tyre(node["front"]), rear=_tyre(node["rear"]))


def load_tyres(path):
    """:class:`Tyres` of a tyre file; bad input is an :class:`~bikemass.core.errors.InputError` naming the
    file and the key."""
    return tyres_from_node(load_yaml(path))


def tyres_from_mapping(mapping, source="tyres"):
    """:class:`Tyres` of a Python mapping in the tyre file's form (errors name ``source``)."""
    node = Node(plain_input(mapping, source), source, "")
    node.mapping()
    return tyres_from_node(node)


def as_tyres(given=None, source="tyres"):
    """:class:`Tyres` of ``given``: a :class:`Tyres` as it is, a tyre file (a path), a mapping in the
    file's form, or ``None`` for :data:`DEFAULT_TYRES`; :class:`~bikemass.core.errors.InputError` otherwise."""
    if given is None:
        return DEFAULT_TYRES
    if isinstance(given, Tyres):
        return given
    if isinstance(given, Mapping):
        return tyres_from_mapping(given, source)
    if isinstance(given, (str, os.PathLike)):
        return load_tyres(os.fspath(given))
    raise InputError(source, "(argument)", f"Tyres, a tyre YAML file or a mapping in its form, not {type(given).__name__}")
