"""Names, files, mappings -> a loaded bicycle or rider: what ``bm.load_bicycle`` and
``bm.load_rider`` do, and what every command calls with its BIKE / POSE arguments.

A bicycle is a shipped name (``jamis``), a bicycle YAML file, a benchmark parameter
file, a mapping holding either (as the YAML would), a
:class:`~bikemass.models.parameters.BenchmarkParameters` set, or a :class:`Bicycle` already
loaded.  A rider is a shipped pose name, a pose file, a mapping in any pose form the
YAML accepts (placement, chain or lumped), a :class:`Rider`, or ``None``/``"none"``.
Bad input raises :class:`~bikemass.core.errors.InputError` (a ValueError) naming the
source (``<mapping>`` for Python values), the key and what was expected.
"""

import os
from collections.abc import Mapping

from ..bicycle import Bicycle
from ..bicycle.loader import bicycle_from_mapping, bicycle_from_parameters, load_bicycle as load_bicycle_file
from ..core.errors import wrong_type
from ..core.gate import MAPPING
from ..models.parameters import BenchmarkParameters
from ..rider import Rider, load_rider as load_pose_file, rider_from_mapping


def load_bicycle(bicycle, name=None, size=None):
    """A bicycle from a name, a file, a mapping or a parameter set.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        A shipped name (``"jamis"``, ``"benchmark"``; ``bikemass params --help`` lists
        them), a bicycle YAML file or benchmark parameter file (YAML/JSON with the 26
        Meijaard names, SI), a mapping with the content of either, or a parameter set.
        A :class:`~bikemass.bicycle.Bicycle` is returned as it is.
    name : str, optional
        Display name for a mapping or parameter set (default: its ``name`` key).
    size : str, optional
        The size of a size run (``sizes:``); a name may also say ``"BIKE@SIZE"``.

    Returns
    -------
    Bicycle
        Immutable; ``bicycle.parts`` hold every placed solid in the benchmark frame (m, kg).

    Raises
    ------
    InputError
        Unknown name (the closest shipped name is suggested) or bad content.
    """
    if isinstance(bicycle, Bicycle):
        return bicycle
    if isinstance(bicycle, BenchmarkParameters):
        return bicycle_from_parameters(bicycle, name or "parameters", name or "<parameters>")
    if isinstance(bicycle, Mapping):
        return bicycle_from_mapping(bicycle, name or MAPPING, size)
    if isinstance(bicycle, (str, os.PathLike)):
        return load_bicycle_file(os.fspath(bicycle), size)
    raise wrong_type("bicycle", bicycle, "a bicycle is a name, a file path, a mapping, a BenchmarkParameters "
                     "or a Bicycle")


def load_rider(rider, as_printed=False, name=None):
    """A rider from a pose name, a pose file or a mapping; ``None`` for no rider.

    Parameters
    ----------
    rider : str, os.PathLike, Mapping, Rider or None
        A shipped pose (``"relaxed"``; ``"relaxed-thesis"`` is the published Table 3-4
        rider), a pose YAML file, or a mapping in any pose form the YAML accepts:
        placement (``body`` + ``segments`` with ``location`` in m and ``angle`` such as
        ``"15 deg"``), chain (``body``, ``bike``, ``chain`` joint angles such as ``"30 deg"``;
        solved on the bicycle's contacts) or lumped segments (``mass`` kg, ``com`` m,
        ``inertia`` kg m^2).  Values may carry units as strings (``"1.2 m"``); angles must
        (a bare angle is refused, README "Units in YAML").  ``None`` or ``"none"``: no rider.
    as_printed : bool
        Use the values as printed in the thesis (``printed:`` keys) instead of the errata.
    name : str, optional
        Display name of a mapping's rider (default: its ``name`` key).

    Returns
    -------
    Rider or None
        Immutable; ``rider.properties()`` gives mass (kg), CoM (m), inertia (kg m^2).

    Raises
    ------
    InputError
        Unknown pose (the closest is suggested) or bad content.
    """
    if rider is None or (isinstance(rider, str) and rider == "none"):
        return None
    if isinstance(rider, Rider):
        return rider
    if isinstance(rider, Mapping):
        return rider_from_mapping(rider, name or MAPPING, as_printed)
    if isinstance(rider, (str, os.PathLike)):
        return load_pose_file(os.fspath(rider), as_printed=as_printed)
    raise wrong_type("rider", rider, "a rider is a pose name, a file path, a mapping, a Rider or None")
