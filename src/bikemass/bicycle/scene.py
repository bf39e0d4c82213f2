"""The assembled 3D model as a trimesh scene (benchmark frame: x forward, y right, z down, m).

Solids become their meshes; a lumped body becomes the uniform solid ellipsoid
with the same mass and central inertia (where its moments allow one, else a
2 cm sphere); a point mass a 1 cm sphere.

Viewers of glTF (and most of STL and OBJ) expect y up: :data:`Y_UP` turns the benchmark frame into
glTF's own convention (a right-handed frame, +y up, the asset's front facing +z: the bicycle's
forward x becomes +z, its down z becomes -y, its right y becomes -x), a proper rotation, so
nothing is mirrored.
"""

import numpy as np
import trimesh

UP = ("z-down", "y")
"""The frames a model is written in: the benchmark frame as it is, or glTF's y up (:data:`Y_UP`)."""
Y_UP = np.array([[0.0, -1.0, 0.0, 0.0],
                 [0.0, 0.0, -1.0, 0.0],
                 [1.0, 0.0, 0.0, 0.0],
                 [0.0, 0.0, 0.0, 1.0]])
"""Homogeneous transform benchmark frame -> glTF's: ``(x, y, z) -> (-y, -z, x)`` (a rotation, det +1)."""

COLOURS = {"rear_frame": [31, 119, 180, 255], "front_frame": [255, 127, 14, 255],
           "rear_wheel": [100, 100, 100, 255], "front_wheel": [100, 100, 100, 255],
           "rider": [44, 160, 44, 255]}


def equivalent_ellipsoid(props):
    """Mesh of the uniform ellipsoid with ``props``' mass and central inertia, at its CoM."""
    moments, axes = props.principal()
    squares = 5 / (2 * props.mass) * (moments.sum() - 2 * moments)   # a_i^2 = 5/(2m) (I_j + I_k - I_i)
    mesh = trimesh.creation.icosphere(subdivisions=3)
    if props.mass > 0 and np.all(squares > 0):
        mesh.vertices = (mesh.vertices * np.sqrt(squares)) @ axes.T
    else:
        mesh.apply_scale(0.02)
    mesh.apply_translation(props.com)
    return mesh


def part_mesh(part):
    """The part's mesh, or a stand-in for lumped bodies and point masses."""
    mesh = part.mesh()
    if mesh is not None:
        return mesh
    props = part.exact()
    if part.solid.kind == "lumped":
        return equivalent_ellipsoid(props)
    sphere = trimesh.creation.icosphere(subdivisions=2, radius=0.01)
    sphere.apply_translation(props.com)
    return sphere


def build_scene(bicycle, rider=None, up="z-down"):
    """trimesh.Scene with one named geometry per part (rider parts prefixed ``rider_``), in the
    benchmark frame (``up="z-down"``) or turned by :data:`Y_UP` into glTF's y up (``up="y"``)."""
    if up not in UP:
        raise ValueError(f"up must be one of {', '.join(UP)}, got {up!r}")
    scene = trimesh.Scene()
    groups = [(bicycle.parts, "")] + ([(rider.parts, "rider_")] if rider is not None else [])
    for parts, prefix in groups:
        for part in parts:
            mesh = part_mesh(part)
            mesh.visual.face_colors = COLOURS["rider" if prefix else part.body]
            if up == "y":
                mesh.apply_transform(Y_UP)
            scene.add_geometry(mesh, geom_name=f"{prefix}{part.name}", node_name=f"{prefix}{part.name}")
    return scene


def export_scene(scene, fmt):
    """Bytes of ``scene`` as ``glb``, ``stl`` (one merged mesh) or ``obj``."""
    if fmt == "stl":
        return trimesh.util.concatenate(scene.dump()).export(file_type="stl")
    data = scene.export(file_type=fmt)
    return data.encode() if isinstance(data, str) else data
