"""Property tests of the inertia algebra (hypothesis)."""

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st
from scipy.spatial.transform import Rotation

from bikemass.mass.inertia import MassProperties, combine, combine_without_parallel_axis, point_inertia
from bikemass.mass.placement import Placement
from bikemass.mass.solids import Box, Cylinder, TrapezoidalPrism

finite = st.floats(-2, 2, allow_nan=False)
positive = st.floats(0.01, 2, allow_nan=False)
vec = st.tuples(finite, finite, finite).map(np.array)


@st.composite
def bodies(draw):
    kind = draw(st.sampled_from(["box", "cyl", "prism"]))
    a, b, c = draw(positive), draw(positive), draw(positive)
    solid = {"box": Box(a, b, c), "cyl": Cylinder(a, b), "prism": TrapezoidalPrism(a, b, c, a + b)}[kind]
    R = Rotation.from_rotvec(draw(st.tuples(finite, finite, finite))).as_matrix()
    return solid.exact_with_mass(draw(positive)).transformed(R, draw(vec))


def assert_physical(I):
    assert np.allclose(I, I.T, atol=1e-12)
    p = np.linalg.eigvalsh(I)
    assert p.min() > -1e-12
    # triangle inequality of principal moments: each <= sum of the other two
    assert p[2] <= p[0] + p[1] + 1e-9 * p[2]


@settings(max_examples=60, deadline=None)
@given(st.lists(bodies(), min_size=1, max_size=4))
def test_combined_inertia_is_a_physical_tensor(parts):
    assert_physical(combine(parts).inertia)


@settings(max_examples=60, deadline=None)
@given(bodies(), vec)
def test_parallel_axis_round_trip(body, point):
    about = body.inertia_about(point)
    back = about - point_inertia(body.mass, body.com - point)
    assert np.allclose(back, body.inertia, atol=1e-10)
    assert_physical(about)


@settings(max_examples=60, deadline=None)
@given(bodies(), st.tuples(finite, finite, finite))
def test_rotation_preserves_principal_moments(body, rotvec):
    R = Rotation.from_rotvec(rotvec).as_matrix()
    assert np.allclose(np.linalg.eigvalsh(body.in_axes(R)), np.linalg.eigvalsh(body.inertia), atol=1e-10)


@settings(max_examples=40, deadline=None)
@given(st.lists(bodies(), min_size=2, max_size=4))
def test_combination_is_order_free_and_associative(parts):
    a = combine(parts)
    b = combine([combine(parts[:1]), combine(parts[1:])]) if len(parts) > 1 else a
    c = combine(parts[::-1])
    for other in (b, c):
        assert other.mass == pytest.approx(a.mass)
        assert np.allclose(other.com, a.com, atol=1e-12)
        assert np.allclose(other.inertia, a.inertia, atol=1e-10)


def test_two_point_masses_dumbbell():
    d = MassProperties.point(1.0, [1, 0, 0]) + MassProperties.point(1.0, [-1, 0, 0])
    assert d.com == pytest.approx([0, 0, 0])
    assert np.diag(d.inertia) == pytest.approx([0, 2, 2])


def test_product_of_inertia_sign_is_tensor_convention():
    """Ixz = -sum m x z: masses at (+1, 0, +1) and (-1, 0, -1) give Ixz = -2."""
    d = MassProperties.point(1.0, [1, 0, 1]) + MassProperties.point(1.0, [-1, 0, -1])
    assert d.inertia[0, 2] == pytest.approx(-2.0)


def test_thesis_combination_drops_the_transfer_terms():
    a, b = MassProperties.point(1.0, [1, 0, 0]), MassProperties.point(1.0, [-1, 0, 0])
    assert combine_without_parallel_axis([a, b]).inertia == pytest.approx(np.zeros((3, 3)))


def test_placement_then_composes():
    p1 = Placement(Rotation.from_rotvec([0, 0.3, 0]).as_matrix(), [1, 2, 3])
    p2 = Placement(Rotation.from_rotvec([0.2, 0, 0.1]).as_matrix(), [-1, 0, 0.5])
    x = np.array([0.3, -0.2, 0.9])
    assert p1.then(p2).apply(x) == pytest.approx(p2.apply(p1.apply(x)))
