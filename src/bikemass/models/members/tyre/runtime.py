"""The tyre member's run-time protocol (:mod:`bikemass.models.members.spec`): how the family takes
its typed parameters."""

from ....core.units import Quantity
from .parameters import as_tyres, tyres_from_node


def coerce(given, source="tyres"):
    """:func:`as_tyres`: the default tyres without ``given``."""
    return as_tyres(given, source)


def values(typed, base):
    """The generated code's tyre parameters (:meth:`Tyres.values`)."""
    return typed.values()


def read_block(node):
    """The ``tyre:`` block of a parameter file (:func:`tyres_from_node`)."""
    return tyres_from_node(node)


def write_block(typed):
    """The ``tyre:`` block of a parameter file, in the tyre file's form (coefficients in 1/rad, lengths in m,
    typed: a file writer renders them with their units; the moments only where a tyre has them)."""
    def one(t):
        return {"cornering_coefficient": Quantity(t.cornering_coefficient, "1/rad"),
                "camber_coefficient": Quantity(t.camber_coefficient, "1/rad"),
                "relaxation_length": t.relaxation_length,
                **({"pneumatic_trail": Quantity(t.pneumatic_trail, "m")} if t.pneumatic_trail else {}),
                **({"twisting_coefficient": Quantity(t.twisting_coefficient, "m/rad")} if t.twisting_coefficient
                   else {})}
    return {"front": one(typed.front), "rear": one(typed.rear)}


def units():
    """Units of the ``tyre:`` block's plain values."""
    return {"relaxation_length": "m"}


INPUTS = {f"{code}{wheel[0].upper()}": f"{wheel}.{field}" for wheel in ("front", "rear")
          for code, field in (("Ca", "cornering_coefficient"), ("Cg", "camber_coefficient"),
                              ("sigma", "relaxation_length"), ("tp", "pneumatic_trail"), ("Cmg", "twisting_coefficient"))}
"""Each tyre parameter of the generated code as an input of a scenario (``CaF`` the front tyre's cornering
coefficient, 1/rad; ``sigmaR`` the rear's relaxation length, m; ...)."""
