"""The compliances of the flexible model from the beam finite elements (bikemass.models.compliance,
bikemass.fe.fork): against closed forms of a cantilever (tip stiffness with shear, the line the tip
turns about, the modal integrals of the static shape), against PyNiteFEA on the Jamis frame and fork,
and the reduction's own exactness (one element per tube equals a fine mesh)."""

from dataclasses import replace

import numpy as np
import pytest
from scipy.integrate import quad

import bikemass as bm
from bikemass.core.errors import InputError
from bikemass.models.compliance import Compliance
from bikemass.fe.fork import DEFAULT_SECTIONS, Fork, fork_bending, fork_structure
from bikemass.fe.model import resolve_material
from bikemass.fe.properties import beam_properties
from bikemass.fe.stiffness import head_tube_axis
from bikemass.fe.twist import frame_twist
from bikemass.mass.materials import Material
from bikemass.mass.sections import RoundSection
from bikemass.mass.tubes import Structure, Tube

STEEL = resolve_material("steel")
RIGID = Material("rigid", "rigid, massless", STEEL.E, STEEL.nu, 1e-12)
"""A stand-in for parts the closed forms take as rigid and massless."""
BLADE = RoundSection(0.025, 0.0009)
DOWN = np.array([0.0, 0.0, 1.0])


def tube(name, points, a, b, section, material):
    return Tube(name, a, b, np.asarray(points[a], float), np.asarray(points[b], float), section, material,
                "front_frame")


def cantilever(F, L, a, timoshenko):
    """Static field of a cantilever (steel, :data:`BLADE`) under a tip force ``F`` whose line of action
    is ``a`` beyond the tip: deflection ``w(x)``, section rotation ``psi(x)`` (x from the clamp) and the
    section constants."""
    p = beam_properties(BLADE, STEEL.nu)
    EI = STEEL.E * p.I
    shear = 1 / (p.kappa * STEEL.G * p.area) if timoshenko else 0.0

    def w(x):
        return F * x ** 2 * (3 * L - x) / (6 * EI) + F * a * x ** 2 / (2 * EI) + F * shear * x

    def psi(x):
        return F * x * (2 * L - x) / (2 * EI) + F * a * x / EI

    return w, psi, p


@pytest.mark.parametrize("timoshenko", [True, False])
def test_fork_blade_is_a_cantilever(timoshenko):
    """One blade along a vertical steer axis, clamped by a rigid steerer in its bearings, loaded
    through the rigid wheel at the contact's foot 0.4 m below the hub: Timoshenko's cantilever."""
    L, a = 0.6, 0.4
    points = {"top": [0, 0, -1.2], "bottom": [0, 0, -1.0], "end": [0, 0, -1.0 + L]}
    fork = Fork((tube("steerer", points, "top", "bottom", RoundSection(1.0, 0.5), RIGID),
                 tube("blade", points, "bottom", "end", BLADE, STEEL)),
                ("top", "bottom"), ("end",), points["end"], {k: np.array(v, float) for k, v in points.items()})
    got = fork_bending(fork, contact=[0.05, 0, 0], steer_axis=DOWN, timoshenko=timoshenko)
    w, psi, p = cantilever(1.0, L, a, timoshenko)
    theta = psi(L)                        # the hub turns about -x
    u_Q = w(L) + a * theta
    rho_A, rho_I = STEEL.density * p.area, STEEL.density * p.I
    z = lambda x: -1.0 + x
    expected_L = quad(lambda x: rho_A * w(x), 0, L)[0] / theta
    expected_Jx = (quad(lambda x: -z(x) * rho_A * w(x), 0, L)[0] - quad(lambda x: rho_I * psi(x), 0, L)[0]) / theta
    expected_m = (quad(lambda x: rho_A * w(x) ** 2, 0, L)[0] + quad(lambda x: rho_I * psi(x) ** 2, 0, L)[0]) / theta ** 2
    assert got.direction == pytest.approx((-1.0, 0.0), abs=1e-9)
    np.testing.assert_allclose(got.point, (0.0, -1.0 + L - w(L) / theta), rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(got.stiffness, u_Q / theta ** 2, rtol=1e-6)
    np.testing.assert_allclose(got.modal_momentum, expected_L, rtol=1e-6)
    np.testing.assert_allclose(got.modal_moment, (expected_Jx, 0.0), rtol=1e-6, atol=1e-12)
    np.testing.assert_allclose(got.modal_mass, expected_m, rtol=1e-6)
    np.testing.assert_allclose(got.load_point, (0.0, 0.0), atol=1e-12)


@pytest.mark.parametrize("timoshenko", [True, False])
def test_frame_twist_of_a_column(timoshenko):
    """A 'frame' that is one column clamped at its foot under a rigid, massless head tube; the contact's
    foot on the (vertical) steer axis is the column's foot, so the loads through the two bearings
    bend the column with a moment that grows from zero at the foot: w'' = -F x / EI, shear F."""
    L, head = 0.6, 0.2
    points = {"d1": [0, -0.05, 0], "d2": [0, 0.05, 0], "base": [0, 0, 0], "bottom": [0, 0, -L],
              "top": [0, 0, -L - head]}
    def t(name, a, b, section, material):
        return replace(tube(name, points, a, b, section, material), body="rear_frame")
    structure = Structure((t("foot_left", "d1", "base", RoundSection(1.0, 0.5), RIGID),
                           t("foot_right", "d2", "base", RoundSection(1.0, 0.5), RIGID),
                           t("column", "base", "bottom", BLADE, STEEL),
                           t("head_tube", "bottom", "top", RoundSection(1.0, 0.5), RIGID)),
                          ("d1", "d2"), ("top", "bottom"), {k: np.array(v, float) for k, v in points.items()})
    got = frame_twist(structure, contact=[0.07, 0, 0], timoshenko=timoshenko)
    p = beam_properties(BLADE, STEEL.nu)
    EI = STEEL.E * p.I
    shear = 1 / (p.kappa * STEEL.G * p.area) if timoshenko else 0.0
    w = lambda x: -x ** 3 / (6 * EI) + shear * x                   # x: height above the foot
    psi = lambda x: -x ** 2 / (2 * EI)
    theta = abs(psi(L))
    u_Q = w(L) - L * psi(L)                                        # the rigid head tube carried down to the foot
    rho_A, rho_I = STEEL.density * p.area, STEEL.density * p.I
    sign = np.sign(psi(L))                                         # the coordinate turns the head tube positively
    expected_L = sign * quad(lambda x: rho_A * w(x), 0, L)[0] / theta
    expected_m = (quad(lambda x: rho_A * w(x) ** 2, 0, L)[0] + quad(lambda x: rho_I * psi(x) ** 2, 0, L)[0]) / theta ** 2
    np.testing.assert_allclose(np.abs(got.direction), (1.0, 0.0), atol=1e-9)
    np.testing.assert_allclose(got.point, (0.0, -(L - w(L) / psi(L))), rtol=1e-6)
    np.testing.assert_allclose(got.stiffness, u_Q / theta ** 2, rtol=1e-6)
    np.testing.assert_allclose(got.modal_momentum * got.direction[0], expected_L, rtol=1e-6)
    np.testing.assert_allclose(got.modal_mass, expected_m, rtol=1e-6)


def jamis(material="steel"):
    bike = bm.load_bicycle("jamis")
    return bike, np.array([bike.geometry.wheelbase, 0.0, 0.0]), resolve_material(material)


def test_one_element_per_tube_is_exact():
    """The static field of end-loaded beams is the elements' own interpolation: a 5 mm mesh gives the
    same reduction (stiffness, axis, modal L, J and m) as one element per tube."""
    bike, contact, steel = jamis()
    axis = head_tube_axis(bike.structure)
    for make in (lambda es: frame_twist(bike.structure, contact, steel, element_size=es),
                 lambda es: fork_bending(fork_structure(bike, steel), contact, axis, element_size=es)):
        coarse, fine = make(None), make(0.005)
        for name in ("point", "direction", "stiffness", "modal_momentum", "modal_moment", "modal_mass"):
            np.testing.assert_allclose(getattr(fine, name), getattr(coarse, name), rtol=1e-8, atol=1e-10)


Pynite = pytest.importorskip("Pynite")


def _pynite(keypoints, tubes, loads, supports):
    """Displacements {key: (DX, DY, DZ, RX, RY, RZ)} of a PyNite model of ``tubes`` under nodal
    ``loads`` {key: (FX, FY, FZ, MX, MY, MZ)}."""
    model = Pynite.FEModel3D()
    for key, point in keypoints.items():
        model.add_node(key, *point)
    for i, t in enumerate(tubes):
        p = beam_properties(t.section, t.material.nu)
        model.add_material(f"m{i}", t.material.E, t.material.G, t.material.nu, t.material.density)
        model.add_section(f"s{i}", p.area, p.I, p.I, p.J)
        model.add_member(f"t{i}", t.start_key, t.end_key, f"m{i}", f"s{i}")
    for key, held in supports.items():
        model.def_support(key, *held)
    for key, values in loads.items():
        for d, value in zip(("FX", "FY", "FZ", "MX", "MY", "MZ"), values):
            if value:
                model.add_node_load(key, d, float(value))
    model.analyze_linear(check_statics=False)
    return {k: np.array([getattr(model.nodes[k], a)["Combo 1"] for a in ("DX", "DY", "DZ", "RX", "RY", "RZ")])
            for k in keypoints}


def test_frame_twist_against_pynite():
    """The Jamis frame in PyNite (Euler-Bernoulli) with the same bearing loads: the head tube's
    sideways motion gives the same twist axis and stiffness."""
    bike, contact, steel = jamis()
    structure = bike.structure
    ours = frame_twist(structure, contact, steel, timoshenko=False)
    top, bottom = (structure.keypoints[k] for k in structure.head_tube)
    s = head_tube_axis(structure)
    Q = bottom + np.dot(contact - bottom, s) * s
    share_top = -np.dot(Q - bottom, s) / np.dot(bottom - top, s)
    tubes = [replace(t, material=steel) for t in structure.tubes]
    loads = {structure.head_tube[0]: (0, share_top, 0, 0, 0, 0), structure.head_tube[1]: (0, 1 - share_top, 0, 0, 0, 0)}
    u = _pynite(structure.keypoints, tubes, loads, {k: (True,) * 6 for k in structure.dropouts})
    u_top, u_bottom = (u[k][1] for k in structure.head_tube)
    length = np.linalg.norm(bottom - top)
    theta = (u_top - u_bottom) / length
    Z = bottom + u_bottom / theta * s
    u_Q = u_bottom - theta * np.dot(Q - bottom, s)
    np.testing.assert_allclose(ours.point, (Z[0], Z[2]), rtol=1e-6)
    np.testing.assert_allclose(ours.stiffness, u_Q / theta ** 2, rtol=1e-6)


def test_fork_bending_against_pynite():
    """The Jamis fork in PyNite: bearings held, the hub tied to the blade ends by stiff links, the
    bottom bearing also held against turning about z (the load has no moment about the steer axis,
    so that support carries none).  PyNite's result then differs from ours by a rigid turn about the
    steer axis (ours holds the steerer's turn about that axis, PyNite its turn about z); with that
    turn taken out, the hub's motion gives the same axis and stiffness."""
    bike, contact, steel = jamis()
    fork = fork_structure(bike, steel)
    axis = head_tube_axis(bike.structure)
    ours = fork_bending(fork, contact, axis, timoshenko=False)
    keypoints = {**fork.keypoints, "hub": fork.hub}
    link = RoundSection(0.03, 0.015)
    stiff = Material("link", "stiff link", steel.E * 1e5, steel.nu, 1e-12)
    tubes = [*fork.tubes, *(Tube(f"link_{k}", k, "hub", fork.keypoints[k], fork.hub, link, stiff, "front_frame")
                            for k in fork.dropouts)]
    Q = fork.keypoints[fork.bearings[1]] + np.dot(contact - fork.keypoints[fork.bearings[1]], axis) * axis
    moment = np.cross(Q - fork.hub, [0, 1.0, 0])
    u = _pynite(keypoints, tubes, {"hub": (0, 1.0, 0, *moment)},
                {fork.bearings[0]: (True, True, True, False, False, False),
                 fork.bearings[1]: (True, True, True, False, False, True)})
    h = u["hub"]
    bottom = fork.keypoints[fork.bearings[1]]
    turn = u[fork.bearings[1]][3:] @ axis                       # PyNite's rigid turn about the steer axis
    h = h - turn * np.r_[np.cross(axis, fork.hub - bottom), axis]
    theta = np.hypot(h[3], h[5])
    u_Q = h[1] + np.cross(h[3:], Q - fork.hub)[1]
    np.testing.assert_allclose(ours.stiffness, u_Q / theta ** 2, rtol=1e-6)
    np.testing.assert_allclose(ours.direction, np.array([h[3], h[5]]) / theta, atol=1e-6)


def test_forks_of_the_shipped_bicycles():
    """The fork is the front frame's fork*/steerer tubes, cut at the bearings, without the steerer's
    part above the top bearing (rigid with the stem); its dropouts are the blade ends."""
    for name in ("jamis", "cargo", "bmc-roadmachine@56"):
        bike = bm.load_bicycle(name)
        fork = fork_structure(bike)
        names = {t.name.split(":")[0] for t in fork.tubes}
        assert {"fork_blade_left", "fork_blade_right", "fork_crown"} <= names
        assert set(fork.bearings) <= set(fork.keypoints)
        assert len(fork.dropouts) == 2
        top = fork.keypoints[fork.bearings[0]]
        s = head_tube_axis(bike.structure)
        assert all(np.dot(t.start - top, s) > -1e-9 and np.dot(t.end - top, s) > -1e-9 for t in fork.tubes)


def test_default_fork():
    """A bicycle without fork tubes gets the documented default: two blades of the steel-road
    tubeset's fork section and its steerer section, in the frame's material."""
    bike = bm.load_bicycle("jamis")
    bare = replace(bike, tubes=tuple(t for t in bike.tubes if not t.name.startswith(("fork", "steerer"))))
    fork = fork_structure(bare)
    sections = {t.name.split(":")[0]: t.section for t in fork.tubes}
    assert sections["fork_blade_left"] == DEFAULT_SECTIONS["blade"]
    assert sections["steerer"] == DEFAULT_SECTIONS["steerer"]
    assert fork.dropouts == ("fork_end_left", "fork_end_right")
    assert fork.mass == pytest.approx(sum(t.section.area * t.length * STEEL.density for t in fork.tubes))


def test_compliance_value():
    c = Compliance("x", (0.1, -0.5), (0.6, 0.8), 1000.0, 0.2, (0.1, 0.3), 0.05)
    assert c.units()["stiffness"] == "N m/rad" and c.units()["modal_mass"] == "kg m^2/rad^2"
    assert c.massless().modal_mass == 0 and c.massless().modal_moment == (0.0, 0.0)
    assert c.scaled(stiffness=3).stiffness == 3000.0
    with pytest.raises(AttributeError):
        c.stiffness = 1.0
    with pytest.raises(InputError, match="direction: a unit vector"):
        Compliance("x", (0, 0), (1.0, 1.0), 1.0, 0, (0, 0), 0)
    with pytest.raises(InputError, match="stiffness: a positive number"):
        Compliance("x", (0, 0), (1.0, 0.0), 0.0, 0, (0, 0), 0)
    with pytest.raises(InputError, match="finite numbers"):
        Compliance("x", (0, 0), (1.0, 0.0), float("inf"), 0, (0, 0), 0)
