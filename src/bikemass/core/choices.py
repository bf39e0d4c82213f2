"""Every named choice of bikemass, one enum each: the library and the command line both
take their values from here (the command line's ``choices=`` lists included).

Each member *is* its string (``Combine.EXACT == "exact"``), so plain strings work
everywhere an enum is expected.  :func:`check` turns a string into the member or
raises a ValueError naming the choices (and the closest one).  Only the standard
library and :mod:`bikemass.core.errors` are imported: ``bikemass --help`` builds its option
lists from these.
"""

import difflib
from enum import Enum

from .errors import InputError, short


class Choice(str, Enum):
    """Base of the choice enums: the member compares equal to (and prints as) its value."""

    def __str__(self):
        return self.value

    @classmethod
    def values(cls):
        """The allowed strings, in order."""
        return tuple(m.value for m in cls)


class Combine(Choice):
    """How the rider joins a frame body (Williams 2015, Eq. 3.6)."""

    EXACT = "exact"
    """Parallel-axis theorem (physically right; the default)."""
    THESIS = "thesis"
    """Central inertias added without parallel-axis terms, as printed in the thesis."""


class Method(Choice):
    """How a solid's mass properties are computed."""

    MESH = "mesh"
    """From its trimesh mesh (as a CAD program would; the default)."""
    EXACT = "exact"
    """Closed form."""


class Overlap(Choice):
    """How overlapping rider segments count."""

    SUM = "sum"
    """Each segment whole, overlaps counted twice (a CAD assembly, the thesis)."""
    UNION = "union"
    """Overlapping volume counted once (manifold3d booleans)."""


class Procedure(Choice):
    """How the 2x2 frame stiffness S is condensed from the beam model."""

    CONDENSED = "condensed"
    """Consistent Schur complement (the default)."""
    THESIS = "thesis"
    """Williams (2015) Eq. 3.31-3.34 unit rotations."""


class Beam(Choice):
    """Beam theory of the frame's finite elements."""

    TIMOSHENKO = "timoshenko"
    """Shear deformation and rotary inertia (the default)."""
    EULER_BERNOULLI = "euler-bernoulli"
    """Slender-beam theory."""


class Source(Choice):
    """Where a material's stiffness S comes from."""

    AUTO = "auto"
    """The bicycle's published S if it carries one, else the beam model (the default)."""
    PUBLISHED = "published"
    """Only the published S."""
    COMPUTED = "computed"
    """Only the beam model of the rear frame."""


class Support(Choice):
    """Boundary condition of the frame's modal analysis."""

    FREE = "free"
    FIX_REAR = "fix-rear"
    FIX_HEAD = "fix-head"
    FIX_BOTH = "fix-both"


class MaterialName(Choice):
    """The shipped frame materials by their short names (``frames/materials.yaml`` aliases)."""

    STEEL = "steel"
    TITANIUM = "titanium"
    ALUMINUM = "aluminum"


RIGID = "infinite"
"""The stiffness name of a rigid rear frame (also ``rigid``, ``None``)."""


class Grip(Choice):
    """Where a chain-posed rider's hands go (a ``contacts.grips`` key, or nowhere)."""

    TOPS = "tops"
    HOODS = "hoods"
    DROPS = "drops"
    AERO = "aero"
    NONE = "none"


class EigenPart(Choice):
    """What an eigenvalue comparison plot shows against speed."""

    REAL = "real"
    """Real parts (1/s)."""
    IMAG = "imag"
    """Imaginary parts (rad/s)."""
    FREQUENCY = "frequency"
    """Natural frequency ``|lambda|`` (rad/s)."""
    DAMPING = "damping"
    """Damping ratio ``-Re/|lambda|``."""


class Format(Choice):
    """Text formats of the command line's data output."""

    TABLE = "table"
    CSV = "csv"
    JSON = "json"
    YAML = "yaml"
    BICYCLEPARAMETERS = "bicycleparameters"
    """The BicycleParameters ``<Name>Benchmark.txt`` file (parameter sets only)."""


PARAMETER_FORMATS = (Format.YAML.value, Format.JSON.value, Format.TABLE.value, Format.CSV.value,
                     Format.BICYCLEPARAMETERS.value)
"""The formats a benchmark parameter set is written in (YAML first: the default)."""


def closest(value, choices):
    """`` (did you mean 'x'?)`` for the choice closest to ``value``, or an empty string."""
    match = difflib.get_close_matches(str(value), [str(c) for c in choices], n=1, cutoff=0.6)
    return f" (did you mean {match[0]!r}?)" if match else ""


def check(kind, value, what=None):
    """``value`` as a member of the :class:`Choice` subclass ``kind``.

    Raises
    ------
    InputError
        (a ValueError) If ``value`` is not one of ``kind.values()``; the message names them and the closest.
    """
    try:
        return kind(value)
    except (ValueError, TypeError):
        name = what or kind.__name__.lower()
        raise InputError(name, short(value), f"{name} must be one of {', '.join(kind.values())}, got {value!r}"
                         f"{closest(value, kind.values())}") from None
