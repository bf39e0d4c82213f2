"""The flexible model's compliances from the beam models of a bicycle's own tubes: the rear frame's
twist (:mod:`bikemass.fe.twist`) and the fork's bending (:mod:`bikemass.fe.fork`), each a
:class:`~bikemass.models.compliance.Compliance` (docs/models-flexible.md)."""

import numpy as np

from ..core.errors import InputError
from ..mass.materials import Material
from ..models.members.flexible.parameters import STEER_DAMPING, Compliances
from .fork import fork_bending, fork_structure
from .model import resolve_material
from .stiffness import head_tube_axis
from .twist import frame_twist


def compliances(bicycle, material=None, frame=True, fork=True, timoshenko=True):
    """The :class:`Compliances` of a bicycle from the beam models of its rear frame and its fork.

    Parameters
    ----------
    bicycle : Bicycle
        With a rear-frame ``structure`` (:func:`bikemass.load_bicycle`); the fork is its front-frame
        tubes ``fork*``/``steerer`` or the default fork (:mod:`bikemass.fe.fork`).
    material : str, Material or None
        Every frame and fork tube in this material (a name of ``frames/materials.yaml`` or a
        one-material file); ``None`` keeps each tube's own.  The mass properties of the parameter set
        are not touched (as the thesis kept the steel frames' for every material).
    frame, fork : bool
        Whether the rear frame twists and the fork bends (``False``: held rigid).
    timoshenko : bool
        Timoshenko beams (default) or Euler-Bernoulli.

    Returns
    -------
    Compliances
        The twist about an axis at right angles to the steer axis, and the fork's bending axis, each
        with its stiffness (N m/rad) and its tubes' modal inertia, loaded as the front contact loads
        them (:mod:`bikemass.fe.twist`), the default structural damping ratio of each and the default
        steering-bearing damping (docs/models-flexible.md, "Damping").

    Raises
    ------
    InputError
        A bicycle without a rear-frame structure (a parameter file, the published ``*-thesis`` bodies).
    """
    if isinstance(material, str):
        material = resolve_material(material)
    if material is not None and not isinstance(material, Material):
        raise InputError("material", "(flexible)", f"a material name or a Material, got {type(material).__name__}")
    if bicycle.structure is None:
        raise InputError(bicycle.source, "structure", "a bicycle whose frame names its structural tubes, dropouts "
                                                      "and head tube (the flexible model's beam models need them)")
    contact = np.array([bicycle.geometry.wheelbase, 0.0, 0.0])
    axis = head_tube_axis(bicycle.structure)
    twist = frame_twist(bicycle.structure, contact, material, timoshenko) if frame else None
    bending = fork_bending(fork_structure(bicycle, material), contact, axis, timoshenko) if fork else None
    return Compliances(twist, bending, steer_damping=STEER_DAMPING)
