"""Beam properties of the tube sections: area, bending and torsion constants, shear coefficient.

Shear coefficients are Cowper's (G. R. Cowper, "The shear coefficient in
Timoshenko's beam theory", J. Appl. Mech. 33 (1966) 335-340, Table 1):

* hollow round tube, ``m = d_inner / d_outer``:
  ``kappa = 6 (1 + nu) (1 + m^2)^2 / ((7 + 6 nu) (1 + m^2)^2 + (20 + 12 nu) m^2)``
  (valid from the solid bar, m = 0, to the thin tube, m -> 1);
* thin-walled square tube: ``kappa = 20 (1 + nu) / (48 + 39 nu)``.

Torsion constants: a round tube's polar moment (exact); a square tube by Bredt's
thin-wall formula on the wall's mid-line, ``J = 4 A_m^2 t / s = t (b - t)^3``.
"""

from dataclasses import dataclass

from ..mass.sections import RoundSection, SquareSection


@dataclass(frozen=True)
class BeamProperties:
    """Section constants (SI): area, I about either principal axis, torsion J, polar Ip, kappa."""

    area: float
    I: float
    J: float
    polar: float
    kappa: float


def shear_coefficient(section, nu):
    """Cowper's shear coefficient of ``section`` for Poisson's ratio ``nu`` (see module doc)."""
    if isinstance(section, RoundSection):
        m2 = (section.inner_diameter / section.outer_diameter) ** 2
        return 6 * (1 + nu) * (1 + m2) ** 2 / ((7 + 6 * nu) * (1 + m2) ** 2 + (20 + 12 * nu) * m2)
    if isinstance(section, SquareSection):
        return 20 * (1 + nu) / (48 + 39 * nu)
    raise TypeError(f"no beam properties for {type(section).__name__}")


def torsion_constant(section):
    """St Venant torsion constant (m^4): exact for round tubes, Bredt for square tubes."""
    if isinstance(section, RoundSection):
        return section.polar_moment
    if isinstance(section, SquareSection):
        return section.wall * (section.side - section.wall) ** 3
    raise TypeError(f"no beam properties for {type(section).__name__}")


def beam_properties(section, nu):
    """:class:`BeamProperties` of ``section`` for Poisson's ratio ``nu``."""
    return BeamProperties(section.area, section.second_moment, torsion_constant(section),
                          section.polar_moment, shear_coefficient(section, nu))
