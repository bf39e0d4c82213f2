"""The rear frame's beam model from Python: its structure, its equivalent stiffness S
(``bm.frame_stiffness``; :func:`bikemass.stiffness` also knows published values) and its
natural frequencies (``bm.frame_modes``)."""

import numbers

from ..core.choices import Beam, Procedure, Support, check
from ..core.errors import InputError
from ..fe.defaults import DEFAULT_ELEMENT_SIZE, MAX_ELEMENTS
from ..fe.model import element_count, resolve_material
from ..mass.materials import Material
from .loading import load_bicycle


def frame_structure(bicycle):
    """The structural rear frame of a bicycle: tubes, dropouts and head tube.

    Parameters
    ----------
    bicycle
        Anything :func:`bikemass.load_bicycle` takes.

    Returns
    -------
    Structure
        ``.tubes``, ``.dropouts``, ``.head_tube`` and ``.keypoints`` (m).

    Raises
    ------
    InputError
        If the bicycle's file names no ``structure:`` (e.g. a parameter file).
    """
    model = load_bicycle(bicycle)
    if model.structure is None:
        raise InputError(model.source, "structure", "a bicycle whose frame names its structural tubes, "
                                                    "dropouts and head tube")
    return model.structure


def frame_stiffness(bicycle, material=None, procedure=Procedure.CONDENSED, beam=Beam.TIMOSHENKO):
    """The 2x2 stiffness S of a bicycle's rear frame from its beam finite elements.

    Parameters
    ----------
    bicycle
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
        S in N m/rad on (roll, steer) at the bottom head-tube keypoint, dropouts clamped.
    """
    # lazy: the beam model's solver loads scipy.sparse (slower to import than numpy); only S needs it
    from ..fe.stiffness import equivalent_stiffness

    procedure, beam = check(Procedure, procedure), check(Beam, beam)
    structure, material = frame_structure(bicycle), _material(material)
    try:
        return equivalent_stiffness(structure, material, procedure.value, timoshenko=beam is Beam.TIMOSHENKO)
    except ValueError as exc:           # a structure its dropouts do not hold
        raise InputError(getattr(bicycle, "source", str(bicycle)), "structure", str(exc)) from None


def _real(value):
    """True for an int or float (not a bool)."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _material(material):
    if material is None or isinstance(material, Material):
        return material
    return resolve_material(str(material))


def frame_modes(bicycle, support=Support.FREE, count=10, material=None, element_size=DEFAULT_ELEMENT_SIZE,
                beam=Beam.TIMOSHENKO, max_elements=MAX_ELEMENTS):
    """The lowest natural frequencies and mode shapes of a bicycle's rear frame.

    Parameters
    ----------
    bicycle
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
        ``.frequencies_hz`` (count,) ascending, ``.shapes`` (n_dof, count) mass-normalised.
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
