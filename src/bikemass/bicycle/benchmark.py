"""A bicycle (+ rider) -> the Meijaard et al. (2007) benchmark parameter set.

Rider parts whose ``body`` is ``front_frame`` (e.g. hands on the bars) join the
front frame, the others the rear frame.  ``combine``:

* ``exact``: every part of a frame body and of the rider combined with the
  parallel-axis theorem (physically right; the default);
* ``thesis``: Williams (2015) Eq. 3.4-3.6 as printed: the frame body and the
  rider's part on that body are each reduced to their own CoM inertia and these
  two inertias are simply added (no parallel-axis terms); masses summed, CoM
  mass-weighted.  This reproduces the thesis's stability tables.
"""

import numpy as np

from ..core.errors import InputError
from ..mass.inertia import combine as combine_exact, combine_without_parallel_axis
from ..mass.parts import body_properties
from ..models.parameters import BenchmarkParameters
from ..models.plausibility import warn_parameters, warn_rider

COMBINE_CHOICES = ("exact", "thesis")


def bicycle_parameters(bicycle, rider=None, combine="exact", method="mesh"):
    """:class:`~bikemass.models.parameters.BenchmarkParameters` of ``bicycle`` with ``rider`` (or none).

    ``method``: ``mesh`` (trimesh meshes of the solids) or ``exact`` (closed form).
    A bicycle read from a parameter file without a rider returns that file's values exactly.
    """
    if combine not in COMBINE_CHOICES:
        raise InputError("combine", combine, f"combine must be one of {', '.join(COMBINE_CHOICES)}, got {combine!r}")
    if rider is None and bicycle.published is not None:
        warn_parameters(bicycle.published, bicycle.source)
        return bicycle.published
    return parameters_from_bodies(bicycle, combined_bodies(bicycle, rider, combine, method))


def parameters_from_bodies(bicycle, bodies):
    """:class:`~bikemass.models.parameters.BenchmarkParameters` of ``bicycle``'s geometry and the four
    combined ``bodies`` (``{body: MassProperties}``, see :func:`combined_bodies`)."""
    g = bicycle.geometry
    R, B, H, F = (bodies[b] for b in ("rear_wheel", "rear_frame", "front_frame", "front_wheel"))
    _check_wheel(R, g.rear_axle, "rear", bicycle.source)
    _check_wheel(F, g.front_axle, "front", bicycle.source)
    params = BenchmarkParameters(
        w=g.wheelbase, c=g.trail, lam=g.lam, g=g.gravity,
        rR=g.rear_wheel_radius, mR=R.mass, IRxx=R.inertia[0, 0], IRyy=R.inertia[1, 1],
        xB=B.com[0], zB=B.com[2], mB=B.mass,
        IBxx=B.inertia[0, 0], IByy=B.inertia[1, 1], IBzz=B.inertia[2, 2], IBxz=B.inertia[0, 2],
        xH=H.com[0], zH=H.com[2], mH=H.mass,
        IHxx=H.inertia[0, 0], IHyy=H.inertia[1, 1], IHzz=H.inertia[2, 2], IHxz=H.inertia[0, 2],
        rF=g.front_wheel_radius, mF=F.mass, IFxx=F.inertia[0, 0], IFyy=F.inertia[1, 1])
    warn_parameters(params, bicycle.source)
    return params


def refuse_second_rider(bicycle, rider):
    """InputError if ``rider`` is not None and ``bicycle``'s rear body already holds one."""
    if rider is not None and bicycle.rider_included:
        raise InputError(bicycle.source, "rider_included",
                         "no rider added: this bicycle's rear body already includes one (use --rider none)")


def combined_bodies(bicycle, rider=None, combine="exact", method="mesh", bicycle_bodies=None):
    """``{body: MassProperties}`` of the four bodies with the rider's parts merged (see module doc);
    ``bicycle_bodies`` = ``bicycle.bodies(method)`` when already computed."""
    refuse_second_rider(bicycle, rider)
    bodies = dict(bicycle_bodies or bicycle.bodies(method))
    merged = merge_rider(bodies, rider_bodies(rider, method) if rider is not None else {}, combine)
    if rider is not None:
        props = body_properties(rider.parts, "exact")
        warn_rider(props.com, bicycle.geometry, bicycle.source, rider.name, props.mass)
    return merged


def rider_bodies(rider, method="mesh"):
    """``{body: MassProperties}`` of the rider's parts on ``rear_frame`` and ``front_frame`` (those present)."""
    out = {}
    for body in ("rear_frame", "front_frame"):
        parts = [p for p in rider.parts if p.body == body]
        if parts:
            out[body] = body_properties(parts, method)
    return out


def merge_rider(bodies, rider, combine="exact"):
    """``bodies`` with the rider's ``{body: MassProperties}`` merged by ``combine`` (a new dict)."""
    if combine not in COMBINE_CHOICES:
        raise InputError("combine", combine, f"combine must be one of {', '.join(COMBINE_CHOICES)}, got {combine!r}")
    merge = combine_exact if combine == "exact" else combine_without_parallel_axis
    out = dict(bodies)
    for body, props in rider.items():
        out[body] = merge((out[body], props))
    return out


def _check_wheel(props, axle, which, source):
    """A wheel must be balanced on its axle (the benchmark model has no wheel offset)."""
    if np.linalg.norm(props.com - axle) > 1e-9:
        raise InputError(source, "components", f"parts with body {which}_wheel centred on its axle "
                         f"{np.round(axle, 4).tolist()} m; together they put the wheel's centre of mass at "
                         f"{np.round(props.com, 4).tolist()} m")
