"""The Meijaard et al. (2007) benchmark parameter set (SI, radians, benchmark frame).

Names follow the paper: ``w c lam g rR mR IRxx IRyy xB zB mB IBxx IByy IBzz
IBxz xH zH mH IHxx IHyy IHzz IHxz rF mF IFxx IFyy``.  B is the rear frame
(with rider), H the front frame (fork and handlebar), R and F the wheels.
"""

from dataclasses import asdict, dataclass, fields, replace

import numpy as np

from ..core.choices import closest
from ..core.display import Display, html_table
from ..core.errors import InputError
from ..core.tables import Table
from .names import NONNEGATIVE, POSITIVE, SIGNED  # noqa: F401 (their home was here; importers keep it)

DESCRIPTIONS = {
    "w": "wheelbase [m]", "c": "trail [m]", "lam": "steer-axis tilt [rad]",
    "g": "gravity [m/s^2]", "rR": "rear wheel radius [m]", "mR": "rear wheel mass [kg]",
    "IRxx": "rear wheel Ixx [kg m^2]", "IRyy": "rear wheel Iyy [kg m^2]",
    "xB": "rear frame CoM x [m]", "zB": "rear frame CoM z [m]", "mB": "rear frame mass [kg]",
    "IBxx": "rear frame Ixx [kg m^2]", "IByy": "rear frame Iyy [kg m^2]",
    "IBzz": "rear frame Izz [kg m^2]", "IBxz": "rear frame Ixz [kg m^2]",
    "xH": "front frame CoM x [m]", "zH": "front frame CoM z [m]", "mH": "front frame mass [kg]",
    "IHxx": "front frame Ixx [kg m^2]", "IHyy": "front frame Iyy [kg m^2]",
    "IHzz": "front frame Izz [kg m^2]", "IHxz": "front frame Ixz [kg m^2]",
    "rF": "front wheel radius [m]", "mF": "front wheel mass [kg]",
    "IFxx": "front wheel Ixx [kg m^2]", "IFyy": "front wheel Iyy [kg m^2]",
}


@dataclass(frozen=True, repr=False)
class BenchmarkParameters(Display):
    """One benchmark parameter set; every field SI (see :data:`DESCRIPTIONS`).

    See Also
    --------
    bikemass.parameters : The set of a bicycle with a rider.
    bikemass.PARAMETER_NAMES : The 26 names in the Meijaard order.

    Examples
    --------
    >>> import bikemass as bm
    >>> p = bm.parameters("benchmark")                # Meijaard et al. (2007), Table 1
    >>> print(p.w, p.c, p.mB, p.IBxz)
    1.02 0.08 85.0 2.4
    >>> heavier = p.replace(mB=95.0)                  # immutable: a changed copy
    >>> print(heavier.mB, p.mB)
    95.0 85.0
    >>> p.inertia("B").tolist()                    # kg m^2, about the rear frame's centre of mass
    [[9.2, 0.0, 2.4], [0.0, 11.0, 0.0], [2.4, 0.0, 2.8]]
    """

    w: float
    c: float
    lam: float
    g: float
    rR: float
    mR: float
    IRxx: float
    IRyy: float
    xB: float
    zB: float
    mB: float
    IBxx: float
    IByy: float
    IBzz: float
    IBxz: float
    xH: float
    zH: float
    mH: float
    IHxx: float
    IHyy: float
    IHzz: float
    IHxz: float
    rF: float
    mF: float
    IFxx: float
    IFyy: float

    def to_dict(self):
        """Plain ``{name: float}`` in the Meijaard order."""
        return {k: float(v) for k, v in asdict(self).items()}

    def tables(self):
        """``{"parameters": Table}``: one row per parameter: ``name``, ``value`` (SI), ``unit`` and
        ``description``, in :data:`NAMES` order."""
        units = parameter_units()
        names = list(self.to_dict())
        return {"parameters": Table({"name": names, "value": [float(getattr(self, n)) for n in names],
                                     "unit": [units[n] for n in names],
                                     "description": [DESCRIPTIONS[n][:DESCRIPTIONS[n].rindex("[")].strip()
                                                     for n in names]})}

    def replace(self, **changes):
        """A copy with some parameters changed (by their names, SI): InputError for a name that is
        not one of the 26; a value no bicycle has is warned about as in a parameter file
        (:func:`~bikemass.models.plausibility.check_parameter_file`), and one the model is not
        defined for is refused by every analysis."""
        # lazy: plausibility imports this module (its checks are of these parameters)
        from .plausibility import check_parameter_file
        for name in changes:
            if name not in NAMES:
                meant = [k for k, text in DESCRIPTIONS.items() if name.lower().replace("_", " ") in text.lower()]
                hint = closest(name, NAMES) or (f" ({name} is {' or '.join(meant[:3])})" if meant else "")
                raise InputError("replace", name, f"one of the 26 benchmark parameter names ({', '.join(NAMES)})"
                                 f"{hint}")
        changed = replace(self, **changes)
        try:
            check_parameter_file(changed, "replace")          # its warnings, as a file's
        except InputError:
            pass                                               # every analysis refuses it, naming the key
        return changed

    def display_rows(self):
        """``[(name, value, SI unit)]`` of the 26 parameters, in the Meijaard order."""
        units = parameter_units()
        return [(k, f"{float(v):.6g}", units[k]) for k, v in asdict(self).items()]

    def __repr__(self):
        values = ", ".join(f"{k}={float(v):.4g}" for k, v in asdict(self).items())
        return f"BenchmarkParameters({values}; SI)"

    def _repr_html_(self):
        """The 26 parameters with their units and meanings (Jupyter's rich display)."""
        return html_table("BenchmarkParameters (Meijaard et al. 2007)",
                          [(f"{k}: {DESCRIPTIONS[k][:DESCRIPTIONS[k].index(' [')]}", v, u)
                           for k, v, u in self.display_rows()])

    def inertia(self, body):
        """3x3 inertia tensor of ``body`` in 'RBHF' (wheels: Izz = Ixx by symmetry)."""
        d = self.to_dict()
        if body in "RF":
            return np.diag([d[f"I{body}xx"], d[f"I{body}yy"], d[f"I{body}xx"]])
        xx, yy, zz, xz = (d[f"I{body}{k}"] for k in ("xx", "yy", "zz", "xz"))
        return np.array([[xx, 0.0, xz], [0.0, yy, 0.0], [xz, 0.0, zz]])


NAMES = tuple(f.name for f in fields(BenchmarkParameters))
"""The 26 parameter names in the Meijaard order (:data:`bikemass.models.names.NAMES`, which the
plausibility checks read without importing this module)."""


def dimension(name):
    """The dimension (:mod:`bikemass.core.units`) of parameter ``name``."""
    if name == "lam":
        return "angle"
    if name == "g":
        return "acceleration"
    return {"I": "inertia", "m": "mass"}.get(name[0], "length")


def parameter_units():
    """``{name: SI unit}`` of the 26 parameters (from :data:`DESCRIPTIONS`)."""
    return {k: d[d.index("[") + 1:-1] for k, d in DESCRIPTIONS.items()}


SPEED_KEY = "v"
"""The speed BicycleParameters' parameter-set files hold beside the 26 names (m/s): not a bicycle
parameter, read as the file's speed."""


def sign_rule(name):
    """``(positive, nonnegative)`` for :meth:`~bikemass.config.Node.number` of parameter ``name``."""
    return name in POSITIVE, name in NONNEGATIVE


def from_node(node):
    """Build :class:`BenchmarkParameters` from a config :class:`~bikemass.core.config.Node` holding the 26
    names (and nothing else)."""
    node.check_keys(required=NAMES)
    values = {}
    for k in NAMES:
        positive, nonnegative = sign_rule(k)
        # lam is radians when bare: the definition of this format (Meijaard 2007, BicycleParameters).
        values[k] = node[k].number(dimension(k), positive=positive, nonnegative=nonnegative,
                                   bare_unit="rad" if k == "lam" else None)
    return BenchmarkParameters(**values)


def check_units(node, units=None):
    """A ``units`` block (as bikemass writes) may only state the SI units the values are read in: those of
    ``units`` (``{key: unit}``; default the 26 names', :func:`parameter_units`); other keys are not checked."""
    si = parameter_units() if units is None else units
    for key, unit in node.items():
        if key in si and unit.value != si[key]:
            unit.fail(f"{si[key]} (values are read in SI; give another unit per value, e.g. "
                      f"'{key}: \"<number> <unit>\"')")
