"""The rear frame's beam model from Python: its structure, its equivalent stiffness S
(``bm.frame_stiffness``; :func:`bikemass.stiffness` also knows published values) and its
natural frequencies (``bm.frame_modes``)."""

import numbers
from typing import Protocol

import numpy as np

from ..core.choices import Beam, Procedure, Support, check
from ..core.errors import InputError
from ..core.frozen import readonly
from ..fe.defaults import DEFAULT_ELEMENT_SIZE, MAX_ELEMENTS
from ..fe.model import element_count, resolve_material
from ..mass.materials import Material
from ..mass.tubes import Structure
from .loading import BicycleLike, load_bicycle


class Modes(Protocol):
    """What :func:`frame_modes` returns, :class:`bikemass.fe.modes.Modes`: a protocol here, so that
    annotating it does not load the modal solver (scipy.sparse.linalg) with this module.

    Examples
    --------
    >>> import bikemass as bm
    >>> modes = bm.frame_modes("jamis", count=2, material="steel")
    >>> print(type(modes).__name__, len(modes.frequencies_hz))
    Modes 2
    """

    @property
    def frequencies_hz(self) -> np.ndarray: ...    # (n,) Hz, ascending

    @property
    def shapes(self) -> np.ndarray: ...            # (n_dof, n), mass-normalised


def frame_structure(bicycle: BicycleLike) -> Structure:
    """The structural rear frame of a bicycle: tubes, dropouts and head tube.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes.

    Returns
    -------
    Structure
        ``.tubes`` (centre lines, sections, materials), ``.dropouts``, ``.head_tube`` and
        ``.keypoints`` (m, benchmark frame).

    Raises
    ------
    InputError
        If the bicycle's file names no ``structure:`` (e.g. a parameter file).

    See Also
    --------
    frame_stiffness, frame_modes : What the beam model of the structure gives.

    Examples
    --------
    >>> import bikemass as bm
    >>> structure = bm.frame_structure("jamis")
    >>> print(len(structure.tubes), "tubes; clamped at", structure.dropouts, "; S at", structure.head_tube[1])
    9 tubes; clamped at ('dropout_left', 'dropout_right') ; S at head_bottom
    """
    model = load_bicycle(bicycle)
    if model.structure is None:
        raise InputError(model.source, "structure", "a bicycle whose frame names its structural tubes, "
                                                    "dropouts and head tube")
    return model.structure


def frame_stiffness(bicycle: BicycleLike, material: "str | Material | None" = None,
                    procedure: Procedure | str = Procedure.CONDENSED,
                    beam: Beam | str = Beam.TIMOSHENKO) -> np.ndarray:
    """The 2x2 stiffness S of a bicycle's rear frame from its beam finite elements.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes, with a rear-frame ``structure``.
    material : str or Material, optional
        Every tube in this material (a shipped name or a one-material YAML file);
        default: the frame's own materials.
    procedure : {"condensed", "thesis"}
        Consistent Schur complement (default) or the thesis's Eq. 3.31-3.34.
    beam : {"timoshenko", "euler-bernoulli"}
        Beam theory.

    Returns
    -------
    numpy.ndarray of shape (2, 2)
        S in N m/rad on (roll, steer) at the bottom head-tube keypoint, dropouts clamped; read-only.

    Raises
    ------
    InputError
        A bicycle without a structure, an unknown material, or a structure its dropouts do not
        hold.

    See Also
    --------
    stiffness : Published S where the bicycle carries one, else this.
    frame_modes : The same beam model's natural frequencies.

    Examples
    --------
    >>> import bikemass as bm
    >>> for material in ("steel", "aluminum"):
    ...     S = bm.frame_stiffness("jamis", material)
    ...     print(f"{material:8s} K_roll {S[0, 0]:7.1f} K_steer {S[1, 1]:7.1f} N m/rad")
    steel    K_roll  6702.3 K_steer  3634.7 N m/rad
    aluminum K_roll  2224.6 K_steer  1212.7 N m/rad
    """
    # lazy: the beam model's solver loads scipy.sparse (slower to import than numpy); only S needs it
    from ..fe.stiffness import equivalent_stiffness

    procedure, beam = check(Procedure, procedure), check(Beam, beam)
    structure, material = frame_structure(bicycle), _material(material)
    try:
        return readonly(equivalent_stiffness(structure, material, procedure.value, timoshenko=beam is Beam.TIMOSHENKO))
    except ValueError as exc:           # a structure its dropouts do not hold
        raise InputError(getattr(bicycle, "source", str(bicycle)), "structure", str(exc)) from None


def _real(value):
    """True for an int or float (not a bool)."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _material(material):
    if material is None or isinstance(material, Material):
        return material
    return resolve_material(str(material))


def frame_modes(bicycle: BicycleLike, support: Support | str = Support.FREE, count: int = 10,
                material: "str | Material | None" = None, element_size: float = DEFAULT_ELEMENT_SIZE,
                beam: Beam | str = Beam.TIMOSHENKO, max_elements: int = MAX_ELEMENTS) -> "Modes":
    """The lowest natural frequencies and mode shapes of a bicycle's rear frame.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        Anything :func:`bikemass.load_bicycle` takes, with a rear-frame ``structure``.
    support : {"free", "fix-rear", "fix-head", "fix-both"}
        Boundary condition; free-free skips the six rigid-body modes.
    count : int
        Number of modes (>= 1).
    material : str or Material, optional
        Every tube in this material (a shipped name or a one-material YAML file);
        default: the frame's own materials.  Geometry is unchanged.
    element_size : float
        Beam element length (m), > 0.
    beam : {"timoshenko", "euler-bernoulli"}
        Beam theory.
    max_elements : int
        Most beam elements the model may have (a tiny ``element_size`` is refused instead of
        exhausting the memory).

    Returns
    -------
    Modes
        ``.frequencies_hz`` (count,) ascending, ``.shapes`` (n_dof, count) mass-normalised,
        ``.mesh`` the beam mesh, ``.bc`` the support.

    Raises
    ------
    InputError
        A bicycle without a structure, an unknown support or material, a ``count`` or
        ``element_size`` out of range, or more than ``max_elements`` elements.

    See Also
    --------
    plot_frame_modes : Draw the mode shapes.
    frame_stiffness : The same beam model's static stiffness.

    Examples
    --------
    >>> import bikemass as bm
    >>> modes = bm.frame_modes("jamis", support="fix-rear", count=3)
    >>> print([f"{f:.2f} Hz" for f in modes.frequencies_hz])
    ['22.44 Hz', '35.81 Hz', '157.40 Hz']
    """
    # lazy: the modal solver loads scipy.linalg and scipy.sparse; only frame modes need it
    from ..fe.modes import frame_modes as solve

    support, beam = check(Support, support, "support"), check(Beam, beam)
    if not _real(count) or int(count) != count or count < 1:
        raise InputError("count", count, "a positive number of modes")
    if not _real(element_size) or not 0 < element_size < float("inf"):
        raise InputError("element_size", element_size, "a positive element length in m")
    structure, material = frame_structure(bicycle), _material(material)
    elements = element_count(structure, element_size)
    if elements > max_elements:
        raise InputError("element_size", element_size, f"a model of at most {max_elements} beam elements, got "
                         f"{elements} (raise max_elements)")
    try:
        return solve(structure, support.value, int(count), material, element_size,
                     timoshenko=beam is Beam.TIMOSHENKO)
    except ValueError as exc:
        raise InputError(str(bicycle), "(model)", str(exc)) from None
