"""wbtc's TexturedBox (a geometry PROTO) and TexturedBoxShape: Webots' faces and texture coordinates, the
box as a Shape's geometry and as a boundingObject (a mesh whose hull is the box), and the Shape version's
textured and painted faces."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.expand import expand_scene
from wbtc.runtime.simulation import Simulation
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text

HEADER = "#VRML_SIM R2025a utf8\nWorldInfo {\n  basicTimeStep 8\n}\n"


def expand(tmp_path: Path, body: str) -> tuple[Node, list]:
    """The first node of a world made of `body`, expanded, and the templates' console output."""
    text = HEADER + body
    world = tmp_path / "box.wbt"
    world.write_text(text)
    scene, expansion = expand_scene(build_scene(parse_text(text, str(world))), strict=True)
    return scene.nodes[1], expansion.console


def faces(face_set: Node) -> list[list[tuple[tuple[float, ...], tuple[float, ...] | None]]]:
    """Each face of an IndexedFaceSet as its corners: (point, texture point or None)."""
    points = np.asarray(face_set.get("coord").get("point"), dtype=float).reshape(-1, 3)
    coord_index = list(face_set.get("coordIndex"))
    tex = face_set.get("texCoord")
    uv = np.asarray(tex.get("point"), dtype=float).reshape(-1, 2) if tex is not None else None
    tex_index = list(face_set.get("texCoordIndex")) if tex is not None else coord_index
    result, face = [], []
    for i, j in zip(coord_index, tex_index, strict=True):
        if i < 0:
            result.append(face)
            face = []
        else:
            face.append((tuple(np.round(points[i], 9)), tuple(np.round(uv[j], 9)) if uv is not None else None))
    return result


def face_at(face_set: Node, axis: int, sign: int) -> dict[tuple[float, ...], tuple[float, ...] | None]:
    """The corners (point -> texture point) of the face whose points all lie on the +-axis side."""
    for face in faces(face_set):
        if all(np.sign(point[axis]) == sign for point, _ in face):
            return dict(face)
    raise AssertionError(f"no face on side {sign} of axis {axis}")


def box(tmp_path: Path, fields: str) -> Node:
    shape, console = expand(tmp_path, f"Shape {{\n  geometry TexturedBox {{\n    {fields}\n  }}\n}}\n")
    assert not console
    return shape.get("geometry")


def test_default_and_metric_texture_coordinates_of_the_front_face(tmp_path: Path) -> None:
    default = box(tmp_path, 'size 0.4 0.2 0.1\n    mapping "default"')
    assert default.base_type == "IndexedFaceSet"
    # Front (+x): s from -y to +y, t from -z to +z; the whole image on the face.
    assert face_at(default, 0, 1) == {(0.2, -0.1, -0.05): (0, 0), (0.2, 0.1, -0.05): (1, 0),
                                      (0.2, 0.1, 0.05): (1, 1), (0.2, -0.1, 0.05): (0, 1)}
    # Top (+z): s along +y, t along -x (Webots' default mapping).
    assert face_at(default, 2, 1) == {(0.2, -0.1, 0.05): (0, 0), (0.2, 0.1, 0.05): (1, 0),
                                      (-0.2, 0.1, 0.05): (1, 1), (-0.2, -0.1, 0.05): (0, 1)}
    metric = box(tmp_path, 'size 0.4 0.2 0.1\n    mapping "metric"')
    # One image spans the largest edge (0.4 m): the 0.2 x 0.1 m front face gets half by a quarter of it.
    assert face_at(metric, 0, 1) == {(0.2, -0.1, -0.05): (0, 0), (0.2, 0.1, -0.05): (0.5, 0),
                                     (0.2, 0.1, 0.05): (0.5, 0.25), (0.2, -0.1, 0.05): (0, 0.25)}
    # The 0.4 x 0.1 m right face (-y): s along +x.
    assert face_at(metric, 1, -1) == {(-0.2, -0.1, -0.05): (0, 0), (0.2, -0.1, -0.05): (1, 0),
                                      (0.2, -0.1, 0.05): (1, 0.25), (-0.2, -0.1, 0.05): (0, 0.25)}


def test_flat_cube_and_none_mappings(tmp_path: Path) -> None:
    flat = box(tmp_path, "size 1 2 3")  # "flat" is the default mapping
    assert face_at(flat, 0, -1)[(-0.5, 1, -1.5)] == (1, 0)  # the back mirrors the front's projection
    # Webots moves the left face's back corners in by 1e-4.
    assert face_at(flat, 1, 1) == {(0.5, 1, -1.5): (1, 0), (-0.5, 1, -1.5): (0.9999, 0.0001),
                                   (-0.5, 1, 1.5): (0.9999, 0.9999), (0.5, 1, 1.5): (1, 1)}
    cube = box(tmp_path, 'mapping "cube"')
    assert face_at(cube, 2, 1)[(0.05, 0.05, 0.05)] == pytest.approx((0.5, 2 / 3))
    assert face_at(cube, 2, -1)[(-0.05, -0.05, -0.05)] == pytest.approx((0.25, 0))
    none = box(tmp_path, 'mapping "none"')
    assert none.get("texCoord") is None and len(faces(none)) == 6


def test_face_flags(tmp_path: Path) -> None:
    assert len(faces(box(tmp_path, "left FALSE\n    top FALSE"))) == 4
    shape, console = expand(tmp_path, "Shape {\n  geometry TexturedBox {\n    front FALSE back FALSE left FALSE "
                                      "right FALSE top FALSE bottom FALSE\n  }\n}\n")
    kept = faces(shape.get("geometry"))
    assert len(kept) == 1 and all(point[0] == 0.05 for point, _ in kept[0])  # the front face, as Webots
    assert console


def test_a_solid_with_a_textured_box_bounding_object_rests_on_its_bottom(tmp_path: Path) -> None:
    world = tmp_path / "solid.wbt"
    world.write_text(HEADER + "Floor {\n}\nDEF BOX Solid {\n  translation 0 0 0.3\n  children [\n"
                     "    Shape {\n      geometry DEF TB TexturedBox {\n        size 0.4 0.2 0.1\n"
                     '        mapping "metric"\n      }\n    }\n  ]\n  boundingObject USE TB\n'
                     "  physics Physics {\n  }\n}\n")
    result, _ = compile_world(world)
    model = result.model
    body = model.body(result.table.bodies["BOX"]).id
    geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == body]
    assert all(model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH for g in geoms)
    assert sorted(bool(model.geom_contype[g]) for g in geoms) == [False, True]  # drawn once, collides once
    assert model.body_mass[body] == pytest.approx(0.4 * 0.2 * 0.1 * 1000)  # density 1000 over the box
    assert sorted(model.body_inertia[body]) == pytest.approx(
        sorted(8 / 12 * np.array([0.2**2 + 0.1**2, 0.4**2 + 0.1**2, 0.4**2 + 0.2**2])), rel=1e-6)
    sim = Simulation(result, noise=False)
    for _ in range(100):  # 0.8 s
        sim.step()
    assert sim.data.xpos[body][2] == pytest.approx(0.05, abs=1e-3)


def test_textured_box_shape_paints_the_faces_whose_flag_is_false(tmp_path: Path) -> None:
    group, console = expand(tmp_path, 'TexturedBoxShape {\n  size 0.2 0.2 0.2\n  textureUrl ["my.png"]\n'
                                      '  textureMapping "default"\n  faceColor 0 0 1\n'
                                      "  topFace FALSE\n  bottomFace FALSE\n}\n")
    assert not console and group.base_type == "Group"
    textured, painted = group.get("children")
    assert len(faces(textured.get("geometry"))) == 4
    assert face_at(textured.get("geometry"), 0, 1)[(0.1, 0.1, 0.1)] == (1, 1)
    assert list(painted.get("appearance").get("baseColor")) == [0, 0, 1]
    painted_faces = faces(painted.get("geometry"))
    assert len(painted_faces) == 2 and painted.get("geometry").get("texCoord") is None
    assert sorted(face[0][0][2] for face in painted_faces) == [-0.1, 0.1]  # top and bottom
    group, _ = expand(tmp_path, "TexturedBoxShape {\n}\n")
    assert len(group.get("children")) == 1  # every face textured: one Shape


def test_textured_box_shape_compiles_to_visual_meshes_only(tmp_path: Path) -> None:
    world = tmp_path / "shape.wbt"
    world.write_text(HEADER + "DEF S Solid {\n  children [\n    TexturedBoxShape {\n      frontFace FALSE\n"
                     "    }\n  ]\n}\n")
    result, _ = compile_world(world)
    model = result.model
    body = model.body(result.table.bodies["S"]).id
    geoms = [g for g in range(model.ngeom) if model.geom_bodyid[g] == body]
    assert len(geoms) == 2 and not any(model.geom_contype[g] for g in geoms)
