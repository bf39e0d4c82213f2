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

BicycleLike = Bicycle | BenchmarkParameters | Mapping | str | os.PathLike
"""What every function taking a bicycle accepts (:func:`load_bicycle`)."""
RiderLike = Rider | Mapping | str | os.PathLike | None
"""What every function taking a rider accepts (:func:`load_rider`)."""


def load_bicycle(bicycle: BicycleLike, name: str | None = None, size: str | None = None) -> Bicycle:
    """A bicycle from a name, a file, a mapping or a parameter set.

    Parameters
    ----------
    bicycle : str, os.PathLike, Mapping, BenchmarkParameters or Bicycle
        A shipped name (``"jamis"``, ``"benchmark"``; ``bikemass params --help`` lists
        them), a bicycle YAML file or benchmark parameter file (YAML/JSON with the 26
        Meijaard names, SI), a mapping with the content of either, or a parameter set.
        A :class:`~bikemass.Bicycle` is returned as it is.
    name : str, optional
        Display name for a mapping or parameter set (default: its ``name`` key).
    size : str, optional
        The size of a size run (``sizes:``); a name may also say ``"BIKE@SIZE"``.

    Returns
    -------
    Bicycle
        Immutable; ``bicycle.parts`` hold every placed solid in the benchmark frame (m, kg),
        ``bicycle.geometry`` the wheelbase, trail, head angle, ... (m, rad).

    Raises
    ------
    InputError
        Unknown name (the closest shipped name is suggested) or bad content: the message names
        the file (``<mapping>`` for a Python value), the key and what was expected.
    InputTypeError
        ``bicycle`` of none of the types above (an :class:`InputError` and a ``TypeError``).

    See Also
    --------
    load_rider : The rider to seat on it.
    parameters : The benchmark parameter set of a bicycle with a rider.
    plot_side_view : Draw it.

    Examples
    --------
    >>> import bikemass as bm
    >>> bike = bm.load_bicycle("jamis")
    >>> print(bike.name, f"wheelbase {bike.geometry.wheelbase:.3f} m, {len(bike.tubes)} tubes")
    Jamis Satellite (geometry) wheelbase 0.988 m, 21 tubes

    A parameter set is a bicycle too (its wheels and frames are drawn from the 26 values):

    >>> bm.load_bicycle(bm.parameters("benchmark"), name="Meijaard 2007").name
    'Meijaard 2007'
    """
    for key, value in (("name", name), ("size", size)):
        if value is not None and not isinstance(value, str):
            raise wrong_type(key, value, f"a {key} is a string")
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


def load_rider(rider: RiderLike, as_printed: bool = False, name: str | None = None) -> Rider | None:
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
        Immutable; ``rider.properties()`` gives mass (kg), CoM (m, benchmark frame), inertia
        (kg m^2, about the CoM).

    Raises
    ------
    InputError
        Unknown pose (the closest is suggested) or bad content, naming the file, the key and
        what was expected.

    See Also
    --------
    pose_rider : A rider posed by joint angles on a bicycle's contacts.
    seated_rider : The rider seated on a bicycle's saddle, grips and pedals.

    Examples
    --------
    >>> import bikemass as bm
    >>> rider = bm.load_rider("relaxed")
    >>> props = rider.properties()
    >>> print(f"{props.mass:.2f} kg, CoM height {-props.com[2]:.3f} m")
    82.15 kg, CoM height 1.217 m
    >>> bm.load_rider("none") is None
    True
    >>> bm.load_rider("relaxd")
    Traceback (most recent call last):
    ...
    bikemass.core.errors.InputError: relaxd: ...did you mean 'relaxed'?)
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
