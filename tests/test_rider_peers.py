"""Independent checks of the rider's solids and their placement.

* yeadon (Dembia et al.): its stadium solid with two equal circular stadia is a
  uniform cylinder; its local properties, rotated with yeadon's ``rotate_inertia``
  and combined with its ``parallel_axis``, must give our mass properties for the
  nine cylindrical segments of every pose.  The rotation is written here from the
  thesis's definition (axis (-sin a, 0, cos a)), not taken from bikemass.
  (yeadon's ``Solid.set_orientation`` is not used: it moves the CoM with R but the
  inertia with R^T, which flips the sign of Ixz for these rotations about y.)
* the torso (a trapezoidal prism, no yeadon counterpart) against scipy's numerical
  integration over its volume.
"""

import numpy as np
import pytest
from scipy import integrate

from bikemass.mass.parts import body_properties
from bikemass.rider import THESIS_POSES, load_rider
from bikemass.mass.solids import Cylinder

yeadon_solid = pytest.importorskip("yeadon.solid")
yeadon_inertia = pytest.importorskip("yeadon.inertia")


def thesis_rotation(angle_deg):
    """Rotation taking local +z to (-sin a, 0, cos a), a rotation about y by -a."""
    a = np.radians(angle_deg)
    return np.array([[np.cos(a), 0.0, -np.sin(a)], [0.0, 1.0, 0.0], [np.sin(a), 0.0, np.cos(a)]])


def yeadon_cylinder(diameter, length, density):
    circle = [yeadon_solid.Stadium(label, "radius", diameter / 2)
              for label in ("Ls0: hip joint centre", "Ls1: umbilicus")]
    return yeadon_solid.StadiumSolid("s0: hip joint centre", density, *circle, length)


def angle_of(part):
    axis = part.placement.rotation[:, 2]
    return np.degrees(np.arctan2(-axis[0], axis[2]))


@pytest.mark.parametrize("pose", THESIS_POSES)
def test_cylinders_against_yeadon(pose):
    parts = [p for p in load_rider(pose).parts if isinstance(p.solid, Cylinder)]
    assert len(parts) == 9                       # head + 4 pairs of limbs
    masses, coms, inertias = [], [], []
    for p in parts:
        solid = yeadon_cylinder(2 * p.solid.outer_radius, p.solid.length, p.density)
        R = thesis_rotation(angle_of(p))
        masses.append(solid.mass)
        coms.append(p.placement.translation + R @ np.asarray(solid.rel_center_of_mass).ravel())
        # rotate_inertia(R, I) expresses I in the frame B with v_a = R v_b: I_a = rotate_inertia(R^T, I_b)
        inertias.append(np.asarray(yeadon_inertia.rotate_inertia(R.T, solid.rel_inertia)))
    mass = sum(masses)
    com = sum(m * c for m, c in zip(masses, coms)) / mass
    inertia = sum(np.asarray(yeadon_inertia.parallel_axis(I, m, com - c))
                  for I, m, c in zip(inertias, masses, coms))
    ours = body_properties(parts, method="exact")
    assert ours.mass == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(ours.com, com, rtol=0, atol=1e-12)
    np.testing.assert_allclose(ours.inertia, inertia, rtol=0, atol=1e-12 * np.abs(inertia).max())


def test_torso_against_numerical_integration():
    """Mass, CoM and central moments of the thesis torso (depth 253, width 366 -> 253, length 466 mm)."""
    torso = next(p for p in load_rider("relaxed").parts if p.name == "torso").solid
    d, a, b, L = torso.depth, torso.width_top, torso.width_bottom, torso.length
    rho = 1000.0

    def volume_integral(f):
        half_width = lambda z: (a + (b - a) * z / L) / 2                # noqa: E731
        value, _ = integrate.tplquad(lambda x, y, z: f(x, y, z), 0, L,
                                     lambda z: -half_width(z), half_width,
                                     lambda z, y: -d / 2, lambda z, y: d / 2, epsabs=1e-13, epsrel=1e-12)
        return rho * value

    m = volume_integral(lambda x, y, z: 1.0)
    zc = volume_integral(lambda x, y, z: z) / m
    xx, yy = volume_integral(lambda x, y, z: x * x), volume_integral(lambda x, y, z: y * y)
    zz = volume_integral(lambda x, y, z: (z - zc) ** 2)
    exact = torso.exact(rho)
    assert exact.mass == pytest.approx(m, rel=1e-10)
    np.testing.assert_allclose(exact.com, [0.0, 0.0, zc], rtol=0, atol=1e-12)
    np.testing.assert_allclose(np.diag(exact.inertia), [yy + zz, xx + zz, xx + yy], rtol=1e-10)
