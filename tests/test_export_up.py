"""``bikemass export --up y``: the 3D model in glTF's frame (y up, the asset's front facing +z), read
back with trimesh (an independent glTF reader).

References: the benchmark bicycle's published geometry (Meijaard et al. 2007, Table 1: wheelbase
w = 1.02 m, wheel radii rR = 0.3 m, rF = 0.35 m), and the same model exported in the benchmark frame
(z down), whose every vertex the y-up file must hold turned by the rotation (x, y, z) -> (-y, -z, x).
glTF stores positions as 32-bit floats: 1e-6 m.
"""

import numpy as np
import pytest

from bikemass.cli.main import main

trimesh = pytest.importorskip("trimesh")

TOL = 1e-6
"""m: a 32-bit float holds a coordinate of about 1.6 m to 1.2e-7 m."""
ROTATION = np.array([[0.0, -1.0, 0.0], [0.0, 0.0, -1.0], [1.0, 0.0, 0.0]])


def exported(tmp_path, name, *options):
    path = tmp_path / name
    assert main(["export", "benchmark", "-o", str(path), *options]) == 0
    return trimesh.load(path, force="scene")


def world_vertices(scene):
    """``{geometry name: vertices in the scene's frame}`` (node transforms applied)."""
    out = {}
    for node in scene.graph.nodes_geometry:
        transform, name = scene.graph[node]
        out[name] = trimesh.transform_points(scene.geometry[name].vertices, transform)
    return out


def test_y_up_is_the_benchmark_frame_rotated(tmp_path):
    assert np.linalg.det(ROTATION) == pytest.approx(1.0)            # a rotation: nothing mirrored
    down = world_vertices(exported(tmp_path, "down.glb"))
    up = world_vertices(exported(tmp_path, "up.glb", "--up", "y"))
    assert set(up) == set(down) and len(up) == 4
    for name in down:
        np.testing.assert_allclose(up[name], down[name] @ ROTATION.T, rtol=0, atol=TOL)


def test_y_up_wheels_stand_where_the_published_geometry_puts_them(tmp_path):
    up = world_vertices(exported(tmp_path, "up.glb", "--up", "y"))
    # the wheels' stand-ins (uniform ellipsoids of their mass and inertia) are centred on the hubs:
    # rear hub rR above the rear contact, front hub rF above the front contact, w ahead (+z)
    np.testing.assert_allclose(up["rear_wheel"].mean(axis=0), [0.0, 0.3, 0.0], atol=TOL)
    np.testing.assert_allclose(up["front_wheel"].mean(axis=0), [0.0, 0.35, 1.02], atol=TOL)
    frame = up["rear_frame"]
    assert frame[:, 1].max() > 0.5 and frame[:, 1].min() > 0         # above the ground: y up


def test_up_applies_to_every_format_and_is_checked(tmp_path, capsys):
    assert main(["export", "benchmark", "-o", str(tmp_path / "x.stl")]) == 0
    down = trimesh.load(tmp_path / "x.stl")
    assert main(["export", "benchmark", "--up", "y", "-o", str(tmp_path / "y.stl")]) == 0
    up = trimesh.load(tmp_path / "y.stl")
    np.testing.assert_allclose(up.bounds, np.sort((down.bounds @ ROTATION.T), axis=0), atol=TOL)
    capsys.readouterr()
    assert main(["export", "benchmark", "--up", "x", "-o", str(tmp_path / "z.glb")]) == 2
    assert "--up" in capsys.readouterr().err and not (tmp_path / "z.glb").exists()
