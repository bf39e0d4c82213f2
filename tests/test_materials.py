"""The shipped materials (frames/materials.yaml) against their published sources."""

import numpy as np
import pytest

from bikemass.mass.materials import load_materials


def _ply_stiffness(E1, E2, G12, nu12):
    """Reduced stiffness Q (plane stress) of an orthotropic ply in its own axes."""
    nu21 = nu12 * E2 / E1
    d = 1.0 - nu12 * nu21
    return np.array([[E1 / d, nu12 * E2 / d, 0.0], [nu12 * E2 / d, E2 / d, 0.0], [0.0, 0.0, G12]])


def _rotated(Q, degrees):
    """Q of a ply turned by ``degrees`` in the laminate's axes (engineering shear strain)."""
    c, s = np.cos(np.radians(degrees)), np.sin(np.radians(degrees))
    T = np.array([[c * c, s * s, 2 * c * s], [s * s, c * c, -2 * c * s], [-c * s, c * s, c * c - s * s]])
    R = np.diag([1.0, 1.0, 2.0])
    return np.linalg.inv(T) @ Q @ R @ T @ np.linalg.inv(R)


def test_carbon_is_the_quasi_isotropic_laminate_of_the_published_ply():
    # Zweben (1989) via Rasheed (2015), Table 3.10: high-modulus graphite/epoxy, V_f 0.6 (GPa)
    Q = _ply_stiffness(220.0e9, 6.9e9, 4.8e9, 0.25)
    A = sum(_rotated(Q, a) for a in (0.0, 45.0, -45.0, 90.0)) / 4      # [0/45/-45/90]s, equal plies
    a = np.linalg.inv(A)
    E, nu, G = 1 / a[0, 0], -a[0, 1] / a[0, 0], 1 / a[2, 2]
    # in-plane isotropic: the same E along 30 degrees, G = E / (2 (1 + nu))
    turned = np.linalg.inv(sum(_rotated(Q, a + 30.0) for a in (0.0, 45.0, -45.0, 90.0)) / 4)
    assert 1 / turned[0, 0] == pytest.approx(E, rel=1e-12)
    assert G == pytest.approx(E / (2 * (1 + nu)), rel=1e-12)
    carbon = load_materials()["carbon"]
    assert carbon.E == pytest.approx(E, rel=1e-3)          # the file rounds to 0.1 GPa
    assert carbon.nu == pytest.approx(nu, abs=5e-4)        # and to 0.001
    assert carbon.G == pytest.approx(G, rel=2e-3)
    assert carbon.density == pytest.approx(1640.0, rel=1e-12)


@pytest.mark.parametrize("name, E, nu, density", [
    ("steel", 205.0e9, 0.290, 7850.0),          # Williams (2015), Table 3-6: 4130 steel
    ("titanium", 113.8e9, 0.342, 4430.0),       # Ti-6Al-4V
    ("aluminum", 68.9e9, 0.330, 2700.0),        # 6061 aluminium
])
def test_metals_are_the_thesis_table(name, E, nu, density):
    m = load_materials()[name]
    assert (m.E, m.nu, m.density) == pytest.approx((E, nu, density), rel=1e-12)
    assert m.G == pytest.approx(E / (2 * (1 + nu)), rel=1e-12)


def test_every_material_is_offered_and_sourced():
    """Every shipped material has an alias the command line shows and a source in docs/fe.md."""
    from pathlib import Path

    from bikemass.cli.dialect import material_list
    listed = material_list()
    fe = (Path(__file__).resolve().parents[1] / "docs" / "fe.md").read_text()
    for m in {m.key: m for m in load_materials().values()}.values():
        assert m.name in listed
        assert f"`{m.key}`" in fe, m.key


def test_the_json_says_what_was_used(capsys):
    """A material on a bicycle's tubes is labelled as such in the JSON as in the title: not a frame."""
    import json

    from bikemass.cli.main import main
    assert main(["stability", "jamis", "--stiffness", "carbon", "--speeds", "0:10:0.5", "--format", "json"]) == 0
    frame = json.loads(capsys.readouterr().out)["frame"]
    assert frame == f"{load_materials()['carbon'].name} on the bicycle's tube sections"
    assert "laminate" in frame and "carbon frame" not in frame
    assert main(["stability", "benchmark", "--format", "json"]) == 0
    assert json.loads(capsys.readouterr().out)["frame"] == "rigid frame"
