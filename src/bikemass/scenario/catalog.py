"""Names, files, mappings -> seated riders, frame stiffness and charts: what ``bm.seated_rider``,
``bm.stiffness`` and ``bm.geometry_chart`` do, and what the scenario builder
(:mod:`bikemass.scenario.scenario`) calls with its rider and stiffness choices.  Bicycles and riders are anything :mod:`bikemass.scenario.loading` loads.
Bad input raises :class:`~bikemass.core.errors.InputError` (a ValueError) naming the
source (``<mapping>`` for Python values), the key and what was expected.
"""

import os
import warnings
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from ..bicycle.benchmark import refuse_second_rider
from ..bicycle.derived_chart import derived_chart
from ..core.choices import RIGID, Beam, Combine, Procedure, Source, check
from ..core.config import load_yaml
from ..core.errors import BikemassWarning, InputError
from ..core.frozen import freeze, readonly
from ..core.paths import closest_name
from ..mass.materials import Material, load_materials
from ..models.plausibility import check_stiffness, warn_stiffness
from ..rider import Rider
from ..rider.seating import SeatedRider, seat_rider
from .frame import frame_stiffness
from .loading import BicycleLike, RiderLike, load_bicycle, load_rider  # noqa: F401 (re-exported)

COMBINE_CHOICES = Combine.values()
"""Rider + rear frame: 'exact' = parallel-axis theorem; 'thesis' = inertias added (Eq. 3.6)."""


def seated_rider(bicycle: BicycleLike, rider: RiderLike, allow_off_contact: bool = False,
                 as_printed: bool = False) -> Rider | None:
    """The rider seated on the bicycle (:mod:`bikemass.rider.seating`), or ``None`` for no rider.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`load_bicycle` takes.
    rider : str, os.PathLike, Mapping, Rider or None
        Anything :func:`load_rider` takes.  A chain pose without ``bike:`` is solved on this
        bicycle; a shipped pose is used as written where it meets the contacts within 1 mm,
        else re-seated by its posture.
    allow_off_contact : bool
        Use the pose as written even off the contacts (the thesis's riders).
    as_printed : bool
        Read a pose with the thesis's printed values (``printed:`` keys), not the errata.

    Returns
    -------
    Rider or None
        The rider placed on this bicycle (benchmark frame, m).

    Raises
    ------
    InputError
        A contact further than 1 mm from the bicycle's (without ``allow_off_contact``), out
        of reach, a bicycle whose rear body already holds a rider (``rider_included``), or bad
        input.

    Warns
    -----
    BikemassWarning
        Gaps allowed by ``allow_off_contact``, and contacts that cannot be checked (a lumped
        rider has no contact points).

    See Also
    --------
    parameters : Seats the rider this way before combining it with the frame.
    pose_rider : A rider posed by joint angles.

    Examples
    --------
    >>> import bikemass as bm
    >>> rider = bm.seated_rider("cargo", "relaxed")
    >>> print(rider.name, f"{rider.properties().mass:.2f} kg")
    Relaxed 82.15 kg
    """
    if rider is None or (isinstance(rider, str) and rider == "none"):
        return None
    return seating(bicycle, rider, allow_off_contact, as_printed).rider


def seating(bicycle: BicycleLike, rider: RiderLike, allow_off_contact: bool = False,
            as_printed: bool = False) -> SeatedRider:
    """:func:`seated_rider` with how the rider was seated: the
    :class:`~bikemass.rider.seating.SeatedRider` (its ``how``: ``"as written"``, ``"solved"`` or
    ``"unchecked"``, and its contacts); its warning lines are warned here."""
    model = load_bicycle(bicycle)
    refuse_second_rider(model, rider)
    seated = seat_rider(rider, model, as_printed, allow_off_contact)
    for line in seated.warnings:
        warnings.warn(line, BikemassWarning, stacklevel=3)
    return seated


def stiffness(bicycle: BicycleLike, which: "str | os.PathLike | Material | ArrayLike | None",
              source: Source | str = Source.AUTO, procedure: Procedure | str = Procedure.CONDENSED,
              beam: Beam | str = Beam.TIMOSHENKO) -> np.ndarray | None:
    """The 2x2 rear-frame stiffness S (N m/rad) on roll and steer at the head tube.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`load_bicycle` takes (needed for a material name).
    which : str, os.PathLike, Material, array_like of shape (2, 2) or None
        ``"infinite"``/``"rigid"``/``None``: a rigid frame (returns ``None``); a material
        (``"steel"``, ``"titanium"``, ``"aluminum"``, any key or alias of
        ``frames/materials.yaml``, or a :class:`~bikemass.mass.materials.Material`): the
        bicycle's published S for it if it carries one, else the beam finite elements of
        its rear frame in that material (see ``source``); a 2x2 symmetric positive definite
        array (N m/rad); or a YAML file with key ``S``.
    source : {"auto", "published", "computed"}
        For a material: published S if any, else computed (``auto``), or only one of them.
    procedure : {"condensed", "thesis"}
        How S is condensed from the beam model (Schur complement, or the thesis's
        Eq. 3.31-3.34).
    beam : {"timoshenko", "euler-bernoulli"}
        Beam theory of the finite elements.

    Returns
    -------
    numpy.ndarray of shape (2, 2), or None
        S in N m/rad (rows and columns: roll, steer), ``None`` for a rigid frame; read-only.

    Raises
    ------
    InputError
        Unknown material or file, a bicycle with neither a published S nor a rear-frame
        structure, or a matrix that is not symmetric positive definite.

    See Also
    --------
    frame_stiffness : S from the beam model alone.
    stability : Takes S as ``stiffness=``.

    Examples
    --------
    >>> import bikemass as bm
    >>> S = bm.stiffness("jamis", "steel")                 # the beam model of its rear frame
    >>> print(S.shape, f"K_roll {S[0, 0]:.1f}, K_steer {S[1, 1]:.1f}, K_coupling {S[0, 1]:.1f} N m/rad")
    (2, 2) K_roll 6702.3, K_steer 3634.7, K_coupling 1237.0 N m/rad
    >>> bm.stiffness("jamis", "infinite") is None
    True
    """
    source, procedure, beam = check(Source, source), check(Procedure, procedure), check(Beam, beam)
    if which is None or (isinstance(which, str) and which in (RIGID, "rigid")):
        return None
    if not isinstance(which, (str, os.PathLike, Material)):
        return readonly(stiffness_matrix(which))
    materials = load_materials()
    if isinstance(which, Material):
        return _material_stiffness(load_bicycle(bicycle), which, source, procedure, beam)
    material = materials.get(os.fspath(which))
    if material is not None:
        return _material_stiffness(load_bicycle(bicycle), material, source, procedure, beam)
    path = os.fspath(which)
    if not os.path.lexists(path):          # an existing non-file reaches the input gate, which says what it is
        names = sorted(materials)
        raise InputError(path, "(stiffness)", f"{RIGID}, a material ({', '.join(names)}), a 2x2 matrix or "
                                              f"a YAML file with S{closest_name(path, [RIGID, *names])}")
    node = load_yaml(path)
    node.check_keys(required=("S",), optional=("units", "source", "name"))
    return readonly(check_stiffness(node["S"]))


def _material_stiffness(model, material, source, procedure, beam):
    S = None if source is Source.COMPUTED else model.published_stiffness(material)
    if S is None and source is not Source.PUBLISHED and model.structure is not None:
        S = frame_stiffness(model, material, procedure, beam)
    if S is None:
        wanted = {Source.AUTO: f"a published stiffness for {material.key} or a rear-frame structure for "
                               "the beam model (it has neither)",
                  Source.PUBLISHED: f"a published stiffness for {material.key}",
                  Source.COMPUTED: "a rear-frame structure for the beam model"}[source]
        raise InputError(model.source, "stiffness", wanted)
    return readonly(S)


def _positive_definite(S):
    return bool(np.allclose(S, S.T, rtol=1e-12, atol=0) and np.all(np.linalg.eigvalsh((S + S.T) / 2) > 0))


def stiffness_matrix(values):
    """``values`` as a 2x2 float array (N m/rad); InputError unless symmetric positive definite."""
    try:
        S = np.array(values, dtype=float)
    except (TypeError, ValueError, OverflowError):
        S = None
    if S is None or S.shape != (2, 2) or not np.all(np.isfinite(S)) or not _positive_definite(S):
        raise InputError("stiffness", "(matrix)", "a symmetric positive definite 2x2 stiffness matrix "
                                                  f"in N m/rad, got {values!r}")
    warn_stiffness(S, "stiffness")
    return S


def geometry_chart(bicycle: BicycleLike, size: str | None = None) -> Mapping:
    """The derived geometry chart of a bicycle: what a manufacturer's chart lists.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`load_bicycle` takes.
    size : str, optional
        One size of a size run (``sizes:``).

    Returns
    -------
    Mapping
        Read-only ``{name: value}`` in :data:`~bikemass.bicycle.derived_chart.CHART_ORDER`: lengths in m
        (``wheelbase``, ``trail``, ``stack``, ``reach``, ...), angles in deg
        (``head_tube_angle``, ``seat_tube_angle``).

    Raises
    ------
    InputError
        Bad bicycle or unknown size.

    See Also
    --------
    plot_chart : The same dimensions drawn on the frame.

    Examples
    --------
    >>> import bikemass as bm
    >>> chart = bm.geometry_chart("bmc-roadmachine", size="56")    # the maker's chart: 590 / 388 mm
    >>> print(f"stack {chart['stack']:.3f} m, reach {chart['reach']:.3f} m, trail {chart['trail']:.4f} m")
    stack 0.590 m, reach 0.388 m, trail 0.0628 m
    """
    return freeze(derived_chart(load_bicycle(bicycle, size=size)))
