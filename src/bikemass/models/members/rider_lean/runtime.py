"""The rider-lean member's run-time protocol (:mod:`bikemass.models.members.spec`): how the family takes
its typed parameters."""

from ....core.errors import InputError
from ...moore2012 import PARAMETERIZATION, moore_yaml, to_moore_values
from .parameters import RiderLeanParameters


def coerce(given, source="model"):
    """``given`` when it is :class:`RiderLeanParameters`; InputError otherwise (the rider split at the hips)."""
    if isinstance(given, RiderLeanParameters):
        return given
    raise InputError(source, "rider-lean", "the rider split at the hips for rider-lean: a Scenario with a rider "
                     "(bm.Scenario(bike, rider, model='rider-lean')) or RiderLeanParameters "
                     "(rider_lean_parameters(bicycle, rider) or from_moore_values)")


def values(typed, base):
    """Every parameter of the generated code from the split set (the bicycle without the upper body
    replaces the rigid set's 26)."""
    return typed.values()


def write_set(typed):
    """The parameter file of the split set: BicycleParameters' ``MooreRiderLean2012`` form (it replaces the
    benchmark set's 26 names)."""
    return {"description": "", "parameterization": PARAMETERIZATION, "parameters": "", "rider": None,
            "values": to_moore_values(typed)}


def bicycleparameters_yaml(typed):
    """The split set as BicycleParameters' ``MooreRiderLean2012`` YAML text."""
    return moore_yaml(typed)


INPUTS = {"mU": "upper.mass", "xU": "upper.x", "zU": "upper.z", "IUxx": "upper.Ixx", "IUyy": "upper.Iyy",
          "IUzz": "upper.Izz", "IUxz": "upper.Ixz", "zhip": "upper.hip_z", "klean": "joint.stiffness",
          "clean": "joint.damping"}
"""The upper body's mass, mass centre, inertia and hip height and the lean joint's stiffness and damping as
inputs of a scenario (the 26 benchmark names are the bicycle's without the upper body)."""
