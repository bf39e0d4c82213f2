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
from typing import TypeVar

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
    """How the rider joins a frame body (Williams 2015, Eq. 3.6).

    A member is its string, so ``"thesis"`` works wherever ``Combine.THESIS`` does.

    See Also
    --------
    bikemass.parameters : Takes it as ``combine=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.Combine.values()
    ('exact', 'thesis')
    >>> bm.Combine.THESIS == "thesis", str(bm.Combine.EXACT)
    (True, 'exact')
    >>> exact = bm.parameters("jamis", "relaxed")
    >>> thesis = bm.parameters("jamis", "relaxed", combine=bm.Combine.THESIS)
    >>> print(f"IBxx {exact.IBxx:.3f} vs {thesis.IBxx:.3f} kg m^2")
    IBxx 14.464 vs 12.281 kg m^2
    """

    EXACT = "exact"
    """Parallel-axis theorem (physically right; the default)."""
    THESIS = "thesis"
    """Central inertias added without parallel-axis terms, as printed in the thesis."""


class Method(Choice):
    """How a solid's mass properties are computed.

    See Also
    --------
    bikemass.parameters : Takes it as ``method=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> mesh = bm.parameters("jamis", method="mesh")
    >>> exact = bm.parameters("jamis", method=bm.Method.EXACT)
    >>> print(f"IFyy {mesh.IFyy:.8f} vs {exact.IFyy:.8f} kg m^2")   # the wheel's mesh is faceted
    IFyy 0.06960117 vs 0.06960113 kg m^2
    """

    MESH = "mesh"
    """From its trimesh mesh (as a CAD program would; the default)."""
    EXACT = "exact"
    """Closed form."""


class Overlap(Choice):
    """How overlapping rider segments count.

    See Also
    --------
    bikemass.Rider : ``rider.properties(overlap=...)``.

    Examples
    --------
    >>> import bikemass as bm
    >>> rider = bm.load_rider("relaxed")
    >>> whole = rider.properties(overlap=bm.Overlap.SUM).mass
    >>> once = rider.properties(overlap="union").mass
    >>> print(f"{whole:.2f} kg summed, {once:.2f} kg with overlaps counted once")
    82.15 kg summed, 81.94 kg with overlaps counted once
    """

    SUM = "sum"
    """Each segment whole, overlaps counted twice (a CAD assembly, the thesis)."""
    UNION = "union"
    """Overlapping volume counted once (manifold3d booleans)."""


class Procedure(Choice):
    """How the 2x2 frame stiffness S is condensed from the beam model.

    See Also
    --------
    bikemass.stiffness, bikemass.frame_stiffness : Take it as ``procedure=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> for procedure in bm.Procedure:
    ...     S = bm.frame_stiffness("jamis", "steel", procedure=procedure)
    ...     print(f"{procedure:9s} K_roll {S[0, 0]:.1f} N m/rad")
    condensed K_roll 6702.3 N m/rad
    thesis    K_roll 6552.5 N m/rad
    """

    CONDENSED = "condensed"
    """Consistent Schur complement (the default)."""
    THESIS = "thesis"
    """Williams (2015) Eq. 3.31-3.34 unit rotations."""


class Tuning(Choice):
    """How the rider model's gains are chosen at each speed (docs/handling.md, "The gains").

    See Also
    --------
    bikemass.handling : Takes it as ``tuning=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> for tuning in bm.Tuning:
    ...     g = bm.handling(bm.parameters("benchmark"), [5.0], tuning=tuning).gains[0]
    ...     print(f"{tuning:8s} k_delta {g.k_delta:.3f}, k_phi_dot {g.k_phi_dot:.4f}")
    hmh2012  k_delta 46.546, k_phi_dot -0.0522
    bmd2016  k_delta 46.552, k_phi_dot -0.0522
    """

    HMH2012 = "hmh2012"
    """Hess, Moore & Hubbard (2012): each inner loop's neuromuscular peak 10 dB above its valley (the default)."""
    BMD2016 = "bmd2016"
    """Moore, Hubbard & Hess (2016): one pole pair of each inner loop on the damping lines 0.1289 and 0.0855."""


class Beam(Choice):
    """Beam theory of the frame's finite elements.

    See Also
    --------
    bikemass.frame_stiffness, bikemass.frame_modes : Take it as ``beam=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> for beam in bm.Beam:
    ...     print(f"{beam:15s} K_steer {bm.frame_stiffness('jamis', 'steel', beam=beam)[1, 1]:.1f} N m/rad")
    timoshenko      K_steer 3634.7 N m/rad
    euler-bernoulli K_steer 3642.7 N m/rad
    """

    TIMOSHENKO = "timoshenko"
    """Shear deformation and rotary inertia (the default)."""
    EULER_BERNOULLI = "euler-bernoulli"
    """Slender-beam theory."""


class Source(Choice):
    """Where a material's stiffness S comes from.

    See Also
    --------
    bikemass.stiffness : Takes it as ``source=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> published = bm.stiffness("jamis-thesis", "steel", source="published")    # Williams (2015), Table 3-12
    >>> print(f"K_roll {published[0, 0]:.1f} N m/rad")
    K_roll 6538.4 N m/rad
    """

    AUTO = "auto"
    """The bicycle's published S if it carries one, else the beam model (the default)."""
    PUBLISHED = "published"
    """Only the published S."""
    COMPUTED = "computed"
    """Only the beam model of the rear frame."""


class Support(Choice):
    """Boundary condition of the frame's modal analysis.

    See Also
    --------
    bikemass.frame_modes : Takes it as ``support=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.Support.values()
    ('free', 'fix-rear', 'fix-head', 'fix-both')
    >>> f = bm.frame_modes("jamis", support=bm.Support.FIX_BOTH, count=1).frequencies_hz[0]
    >>> print(f"{f:.1f} Hz")
    174.9 Hz
    """

    FREE = "free"
    FIX_REAR = "fix-rear"
    FIX_HEAD = "fix-head"
    FIX_BOTH = "fix-both"


class MaterialName(Choice):
    """The shipped frame materials by their short names (``frames/materials.yaml`` aliases).

    See Also
    --------
    bikemass.stiffness : Takes a material by name.

    Examples
    --------
    >>> import bikemass as bm
    >>> [str(m) for m in bm.MaterialName]
    ['steel', 'titanium', 'aluminum']
    """

    STEEL = "steel"
    TITANIUM = "titanium"
    ALUMINUM = "aluminum"


RIGID = "infinite"
"""The stiffness name of a rigid rear frame (also ``rigid``, ``None``)."""


class Grip(Choice):
    """Where a chain-posed rider's hands go (a ``contacts.grips`` key, or nowhere).

    See Also
    --------
    bikemass.pose_rider : Takes it as ``hands=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> str(bm.pose_rider("jamis", hands=bm.Grip.DROPS).hands)
    'drops'
    >>> bm.pose_rider("jamis", hands="drop")
    Traceback (most recent call last):
    ...
    bikemass.core.errors.InputError: hands: 'drop': ...(did you mean 'drops'?)
    """

    TOPS = "tops"
    HOODS = "hoods"
    DROPS = "drops"
    AERO = "aero"
    NONE = "none"


class EigenPart(Choice):
    """What an eigenvalue comparison plot showed against speed.

    No function of this version takes it: the comparison plot it chose for is gone (eigenvalues
    are drawn by :func:`bikemass.plot_eigenvalues`, many results by
    :func:`bikemass.plot_critical_speeds`); it stays importable for code that names it.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.EigenPart.values()
    ('real', 'imag', 'frequency', 'damping')
    """

    REAL = "real"
    """Real parts (1/s)."""
    IMAG = "imag"
    """Imaginary parts (rad/s)."""
    FREQUENCY = "frequency"
    """Natural frequency ``|lambda|`` (rad/s)."""
    DAMPING = "damping"
    """Damping ratio ``-Re/|lambda|``."""


class Format(Choice):
    """Text formats of the command line's data output.

    Examples
    --------
    >>> import bikemass as bm
    >>> bm.Format.values()
    ('table', 'csv', 'json', 'yaml', 'bicycleparameters', 'bicycleparameters-yaml')
    """

    TABLE = "table"
    CSV = "csv"
    JSON = "json"
    YAML = "yaml"
    BICYCLEPARAMETERS = "bicycleparameters"
    """The BicycleParameters ``<Name>Benchmark.txt`` file (parameter sets only)."""
    BICYCLEPARAMETERS_YAML = "bicycleparameters-yaml"
    """BicycleParameters' ``ParameterSet.to_yaml`` file: ``Meijaard2007``, or ``MooreRiderLean2012`` for
    the rider-lean model (parameter sets only)."""


PARAMETER_FORMATS = (Format.YAML.value, Format.JSON.value, Format.TABLE.value, Format.CSV.value,
                     Format.BICYCLEPARAMETERS.value, Format.BICYCLEPARAMETERS_YAML.value)
"""The formats a benchmark parameter set is written in (YAML first: the default)."""


def closest(value, choices):
    """`` (did you mean 'x'?)`` for the choice closest to ``value``, or an empty string."""
    match = difflib.get_close_matches(str(value), [str(c) for c in choices], n=1, cutoff=0.6)
    return f" (did you mean {match[0]!r}?)" if match else ""


C = TypeVar("C", bound="Choice")
"""A :class:`Choice` subclass (what :func:`check` returns a member of)."""


def check(kind: type[C], value: object, what: str | None = None) -> C:
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
