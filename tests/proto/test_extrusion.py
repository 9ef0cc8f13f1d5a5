"""wbtc's Extrusion: vertex and face counts, the cross-section frame, and the volume it encloses."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text

UNIT_SQUARE = "crossSection [ 0.5 0.5, 0.5 -0.5, -0.5 -0.5, -0.5 0.5, 0.5 0.5 ]"


def extrusion(tmp_path: Path, fields: str) -> Node:
    """The IndexedFaceSet an Extrusion with `fields` expands to."""
    text = ("#VRML_SIM R2025a utf8\nWorldInfo {\n}\nShape {\n  geometry Extrusion {\n"
            f"    {fields}\n  }}\n}}\n")
    world = tmp_path / "extrusion.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    assert not expansion.console
    return scene.nodes[1].get("geometry")


def mesh(face_set: Node) -> tuple[np.ndarray, list[list[int]]]:
    points = np.asarray(face_set.get("coord").get("point"), dtype=float).reshape(-1, 3)
    faces, face = [], []
    for i in face_set.get("coordIndex"):
        if i < 0:
            faces.append(face)
            face = []
        else:
            face.append(i)
    return points, faces


def volume(points: np.ndarray, faces: list[list[int]]) -> float:
    """Signed volume of a closed mesh (positive when its faces are counter-clockwise seen from outside)."""
    total = 0.0
    for f in faces:
        for k in range(1, len(f) - 1):
            a, b, c = points[f[0]], points[f[k]], points[f[k + 1]]
            total += float(np.dot(a, np.cross(b, c))) / 6
    return total


def test_square_along_z_with_spline_subdivision(tmp_path: Path) -> None:
    points, faces = mesh(extrusion(tmp_path, f"{UNIT_SQUARE}\n    spine [ 0 0 0, 0 0 2 ]"))
    # 4 spline points per segment: 5 rings of 5 points; 4 x 4 side quads and two caps of 4 corners.
    assert points.shape == (25, 3)
    assert len(faces) == 18 and sorted(len(f) for f in faces) == [4] * 18
    assert sorted(set(np.round(points[:, 2], 9))) == [0, 0.5, 1, 1.5, 2]
    # Along +z Webots' frame turns the cross-section by half a turn: (x, y) lies at (-x, -y) (its test for
    # "Z has a positive component" sees the 6e-17 that cos(pi / 2) leaves).
    assert np.allclose(points[:5, :2], [[-0.5, -0.5], [-0.5, 0.5], [0.5, 0.5], [0.5, -0.5], [-0.5, -0.5]])
    assert volume(points, faces) == pytest.approx(2.0)  # faces point outwards


def test_square_along_x_without_subdivision(tmp_path: Path) -> None:
    points, faces = mesh(extrusion(tmp_path, f"{UNIT_SQUARE}\n    spine [ 0 0 0, 3 0 0 ]\n"
                                             "    splineSubdivision 0"))
    assert points.shape == (10, 3) and len(faces) == 6
    assert points[:, 0].min() == 0 and points[:, 0].max() == 3
    assert np.allclose(np.abs(points[:, 1:]), 0.5)
    assert volume(points, faces) == pytest.approx(3.0)


def test_scaled_frustum_and_open_ends(tmp_path: Path) -> None:
    points, faces = mesh(extrusion(tmp_path, f"{UNIT_SQUARE}\n    spine [ 0 0 0, 0 0 1 ]\n"
                                             "    scale [ 1 1, 2 2 ]\n    splineSubdivision 0"))
    assert volume(points, faces) == pytest.approx(7 / 3)  # (1 + 4 + 2) / 3
    points, faces = mesh(extrusion(tmp_path, f"{UNIT_SQUARE}\n    spine [ 0 0 0, 0 0 1 ]\n"
                                             "    beginCap FALSE\n    endCap FALSE"))
    assert len(faces) == 16


def test_orientation_turns_the_cross_section(tmp_path: Path) -> None:
    points, _ = mesh(extrusion(tmp_path, "crossSection [ 1 0, 0 0 ]\n    spine [ 0 0 0, 0 0 1 ]\n"
                                         "    orientation [ 0 0 1 1.5707963, 0 0 1 1.5707963 ]\n"
                                         "    splineSubdivision 0"))
    # (1, 0) lies at (-1, 0, 0) (see above), then turns a quarter about z.
    assert np.allclose(points[0], [0, -1, 0], atol=1e-5)
    assert np.allclose(points[2], [0, -1, 1], atol=1e-5)


def test_bent_spine_keeps_the_cross_section_across_it(tmp_path: Path) -> None:
    points, _ = mesh(extrusion(tmp_path, "crossSection [ 1 0, 0 1 ]\n    spine [ 0 0 0, 1 0 0, 1 1 0 ]\n"
                                         "    splineSubdivision 0"))
    # The spine bends in the xy plane: Z is -z there (y up), X to the left of the direction of travel.
    assert np.allclose(points[0], [0, 1, 0]) and np.allclose(points[1], [0, 0, 1])
    assert np.allclose(points[-2], [0, 1, 0]) and np.allclose(points[-1], [1, 1, 1])


def test_mass_from_the_extrusion_as_a_bounding_object(tmp_path: Path) -> None:
    world = tmp_path / "mass.wbt"
    world.write_text("#VRML_SIM R2025a utf8\nWorldInfo {\n}\nDEF BAR Solid {\n  translation 0 0 1\n"
                     f"  boundingObject Extrusion {{ {UNIT_SQUARE} spine [ 0 0 0, 0 0 2 ] }}\n"
                     "  physics Physics {\n    density 500\n  }\n}\n")
    result, _ = compile_world(world)
    body = result.model.body(result.table.bodies["BAR"]).id
    assert result.model.body_mass[body] == pytest.approx(1000.0, rel=1e-6)
    assert result.model.body_ipos[body] == pytest.approx([0, 0, 1], abs=1e-9)
