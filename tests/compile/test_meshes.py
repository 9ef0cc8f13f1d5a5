"""IndexedFaceSet, Mesh and ElevationGrid conversion, mesh mass properties, MuJoCo hfield placement."""

import os
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.compile.faceset import indexed_face_set
from wbtc.compile.heightfield import HeightField, elevation_grid
from wbtc.compile.mesh_data import MeshData
from wbtc.compile.mesh_mass import mesh_volume_and_inertia
from wbtc.compile.meshes import clear_mesh_cache, mesh_file
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

FIXTURES = Path(__file__).resolve().parent / "fixtures" / "meshes"
WORLD = str(FIXTURES / "world.wbt")  # nodes "written" next to the fixtures (the file need not exist)
SQUARE = "coord Coordinate { point [ 0 0 0, 2 0 0, 2 1 0, 0 1 0 ] }"


def _node(body: str, version: str = "R2025a", path: str = WORLD):
    return build_scene(parse_text(f"#VRML_SIM {version} utf8\n{body}\n", path)).nodes[0]


def _normals(mesh: MeshData) -> np.ndarray:
    a, b, c = (mesh.vertices[mesh.faces[:, k]] for k in range(3))
    return np.cross(b - a, c - a)


# ---------------------------------------------------------------------------------- IndexedFaceSet


def test_quad_without_trailing_minus_one_is_fanned_with_default_texcoords() -> None:
    mesh = indexed_face_set(_node(f"IndexedFaceSet {{ {SQUARE} coordIndex [ 0 1 2 3 ] }}"))
    assert mesh is not None and mesh.warnings == []
    assert mesh.vertices.shape == (4, 3) and mesh.vertices.dtype == np.float64
    assert mesh.faces.dtype == np.int32 and mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3]]
    assert (_normals(mesh)[:, 2] > 0).all()
    # Webots' default mapping: s along the longest side (x, 2 m), t along the second (y, 1 m), both
    # divided by the longest side, so t stops at 0.5.
    assert mesh.texcoords.dtype == np.float32
    assert mesh.texcoords.tolist() == [[0.0, 0.0], [1.0, 0.0], [1.0, 0.5], [0.0, 0.5]]
    # MuJoCo counts v from the top image row.
    assert mesh.mujoco_texcoords().tolist() == [[0.0, 1.0], [1.0, 1.0], [1.0, 0.5], [0.0, 0.5]]


def test_default_texcoords_use_the_two_largest_box_sides() -> None:
    # Bounding box 1 (x) by 0 (y) by 4 (z): s runs along z, t along x (divided by 4).
    body = "IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 0 4 ] } coordIndex [ 0 1 2 -1 ] }"
    mesh = indexed_face_set(_node(body))
    assert mesh.texcoords.tolist() == [[0.0, 0.0], [0.0, 0.25], [1.0, 0.25]]


def test_ccw_false_flips_the_winding() -> None:
    mesh = indexed_face_set(_node(f"IndexedFaceSet {{ {SQUARE} coordIndex [ 0 1 2 3 -1 ] ccw FALSE }}"))
    assert mesh.faces.tolist() == [[0, 2, 1], [0, 3, 2]]
    assert (_normals(mesh)[:, 2] < 0).all()


def test_texcoord_index_splits_vertices() -> None:
    body = (f"IndexedFaceSet {{ {SQUARE} texCoord TextureCoordinate {{ point [ 0 0, 1 0, 1 1, 0 1 ] }} "
            "coordIndex [ 0 1 2 -1 0 2 3 -1 ] texCoordIndex [ 0 1 2 -1 3 2 1 -1 ] }")
    mesh = indexed_face_set(_node(body))
    # Coordinate 0 is used with texture coordinates 0 and 3: it becomes two vertices.
    assert mesh.vertices.tolist() == [[0, 0, 0], [0, 0, 0], [2, 0, 0], [2, 1, 0], [0, 1, 0]]
    assert mesh.texcoords.tolist() == [[0, 0], [0, 1], [1, 0], [1, 1], [1, 0]]
    assert mesh.faces.tolist() == [[0, 2, 3], [1, 3, 4]]
    for face_tex, expected in zip(mesh.texcoords[mesh.faces].tolist(), [[[0, 0], [1, 0], [1, 1]],
                                                                       [[0, 1], [1, 1], [1, 0]]], strict=True):
        assert face_tex == expected


def test_texcoord_without_index_follows_coord_index() -> None:
    body = (f"IndexedFaceSet {{ {SQUARE} texCoord TextureCoordinate {{ point [ 0 0, 1 0, 1 1, 0 1 ] }} "
            "coordIndex [ 3 2 1 -1 ] }")
    mesh = indexed_face_set(_node(body))
    assert mesh.vertices.tolist() == [[2, 0, 0], [2, 1, 0], [0, 1, 0]]
    assert mesh.texcoords.tolist() == [[1, 0], [1, 1], [0, 1]]
    assert mesh.faces.tolist() == [[2, 1, 0]]


def test_mismatched_texcoord_index_falls_back_to_the_default_mapping() -> None:
    body = (f"IndexedFaceSet {{ {SQUARE} texCoord TextureCoordinate {{ point [ 0 0, 1 0, 1 1 ] }} "
            "coordIndex [ 0 1 2 -1 ] texCoordIndex [ 0 1 ] }")
    warnings: list = []
    mesh = indexed_face_set(_node(body), warnings)
    assert mesh.texcoords.tolist() == [[0.0, 0.0], [1.0, 0.0], [1.0, 0.5]]
    assert "texCoordIndex" in warnings[0].message and warnings[0].severity == "warning"
    assert warnings == mesh.warnings


def test_bad_faces_are_skipped_with_warnings() -> None:
    body = f"IndexedFaceSet {{ {SQUARE} coordIndex [ 0 1 9 -1 0 0 1 -1 1 2 -1 0 1 2 -1 -1 2 3 0 -1 ] }}"
    warnings: list = []
    mesh = indexed_face_set(_node(body), warnings)
    assert mesh.faces.shape == (2, 3) and mesh.vertices.shape == (4, 3)
    messages = [w.message for w in warnings]
    assert messages[0].startswith("1 face(s) with an out-of-range coordinate index skipped")
    assert "[0, 1, 9]" in messages[0]
    assert messages[1].startswith("2 degenerate face(s)")
    assert str(warnings[0].span).endswith("world.wbt:2:1")


def test_only_degenerate_faces_give_none() -> None:
    collinear = "IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 2 0 0 ] } coordIndex [ 0 1 2 -1 ] }"
    warnings: list = []
    assert indexed_face_set(_node(collinear), warnings) is None
    assert warnings[-1].message == "IndexedFaceSet has no valid triangle: no geometry"
    assert indexed_face_set(_node("IndexedFaceSet { }")) is None
    assert indexed_face_set(_node(f"IndexedFaceSet {{ {SQUARE} }}")) is None


def test_concave_polygon_is_ear_clipped() -> None:
    # An arrow head: the corner (2, 1) is reflex; a fan from corner 0 would cover outside area.
    body = ("IndexedFaceSet { coord Coordinate { point [ 0 0 0, 4 0 0, 4 4 0, 2 1 0, 0 4 0 ] } "
            "coordIndex [ 0 1 2 3 4 -1 ] }")
    mesh = indexed_face_set(_node(body))
    normals = _normals(mesh)
    assert mesh.faces.shape == (3, 3)
    assert (normals[:, 2] > 0).all()
    assert np.isclose(normals[:, 2].sum() / 2, 10.0)  # the polygon's area


def test_concave_quad_is_split_at_its_reflex_corner() -> None:
    body = ("IndexedFaceSet { coord Coordinate { point [ 0 0 0, 4 0 0, 1 1 0, 0 4 0 ] } "
            "coordIndex [ 0 1 2 3 -1, 2 3 0 1 -1 ] }")
    mesh = indexed_face_set(_node(body))
    assert mesh.faces.tolist() == [[2, 3, 0], [2, 0, 1], [2, 3, 0], [2, 0, 1]]
    assert (_normals(mesh)[:, 2] > 0).all()


def test_keyhole_polygon_with_a_bridged_hole() -> None:
    # A 4 x 4 square with a 1 x 1 hole, joined to the outside by a bridge (a doubled edge), as some PROTOs write
    # floors with holes. Corners 1 and 8, 2 and 7 are repeats.
    points = ("2 2 0, 2 0 0, 0.5 0 0, 0.5 0.5 0, -0.5 0.5 0, -0.5 -0.5 0, 0.5 -0.5 0, 0.5 0 0, 2 0 0, 2 -2 0, "
              "-2 -2 0, -2 2 0")
    body = f"IndexedFaceSet {{ coord Coordinate {{ point [ {points} ] }} coordIndex [ 0 1 2 3 4 5 6 7 8 9 10 11 ] }}"
    mesh = indexed_face_set(_node(body))
    assert mesh.warnings == [] and mesh.faces.shape == (10, 3)
    normals = _normals(mesh)
    assert (normals[:, 2] < 0).all()  # clockwise seen from +z, as written
    assert np.isclose(-normals[:, 2].sum() / 2, 15.0)


def test_repeated_closing_corner_is_ignored() -> None:
    mesh = indexed_face_set(_node(f"IndexedFaceSet {{ {SQUARE} coordIndex [ 0 1 2 3 0 -1 ] }}"))
    assert mesh.faces.tolist() == [[0, 1, 2], [0, 2, 3]] and mesh.warnings == []


def test_unused_coordinates_are_dropped() -> None:
    body = ("IndexedFaceSet { coord Coordinate { point [ 9 9 9, 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 1 2 3 ] }")
    mesh = indexed_face_set(_node(body))
    assert mesh.vertices.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    assert mesh.faces.tolist() == [[0, 1, 2]]
    # The default mapping still uses the bounding box of every coordinate (as Webots does).
    assert np.allclose(mesh.texcoords, [[0, 0], [1 / 9, 0], [0, 1 / 9]])


# ---------------------------------------------------------------------------------- Mesh files


def test_obj_with_texture_coordinates_and_objects() -> None:
    mesh = mesh_file(_node('Mesh { url "textured.obj" }'))
    assert mesh.vertices.shape == (7, 3) and mesh.faces.shape == (3, 3) and mesh.warnings == []
    assert mesh.texcoords.shape == (7, 2)
    # Each vertex keeps the (s, t) written in the file (t upwards, as in OBJ and VRML).
    by_position = {tuple(v): tuple(t) for v, t in zip(mesh.vertices.tolist(), mesh.texcoords.tolist(), strict=True)}
    assert by_position[(2.0, 1.0, 0.0)] == (1.0, 1.0)
    assert by_position[(0.0, 1.0, 1.0)] == (0.0, 1.0)
    assert (_normals(mesh)[:, 2] > 0).all()


def test_name_selects_a_sub_mesh() -> None:
    mesh = mesh_file(_node('Mesh { url "textured.obj" name "roof" }'))
    assert mesh.vertices.tolist() == [[0, 0, 1], [1, 0, 1], [0, 1, 1]]
    assert mesh.faces.tolist() == [[0, 1, 2]] and mesh.texcoords.tolist() == [[0, 0], [1, 0], [0, 1]]
    warnings: list = []
    assert mesh_file(_node('Mesh { url "textured.obj" name "chimney" }'), warnings) is None
    assert "no sub-mesh named 'chimney'" in warnings[0].message and "plate, roof" in warnings[0].message


def test_stl_cube_is_merged_and_measured() -> None:
    mesh = mesh_file(_node('Mesh { url "cube.stl" }'))
    assert mesh.vertices.shape == (8, 3) and mesh.faces.shape == (12, 3) and mesh.texcoords is None
    volume, center, inertia = mesh_volume_and_inertia(mesh)
    assert volume == pytest.approx(1.0)
    assert np.allclose(center, [0.5, 0.5, 0.5])
    assert np.allclose(inertia, np.eye(3) / 6)  # m (a^2 + a^2) / 12 with m = 1, a = 1


def test_ccw_false_on_a_mesh_file_turns_it_inside_out() -> None:
    normal = mesh_file(_node('Mesh { url "cube.stl" }'))
    flipped = mesh_file(_node('Mesh { url "cube.stl" ccw FALSE }'))
    assert flipped.faces.tolist() == normal.faces[:, [0, 2, 1]].tolist()
    # The volume of an inside-out closed mesh is still measured right.
    assert mesh_volume_and_inertia(flipped)[0] == pytest.approx(1.0)


def test_open_mesh_uses_the_convex_hull() -> None:
    cube = mesh_file(_node('Mesh { url "cube.stl" }'))
    open_box = MeshData(cube.vertices, cube.faces[:-2])  # one side missing
    volume, center, inertia = mesh_volume_and_inertia(open_box)
    assert volume == pytest.approx(1.0)
    assert np.allclose(center, [0.5, 0.5, 0.5])
    assert np.allclose(inertia, np.eye(3) / 6)
    flat = indexed_face_set(_node(f"IndexedFaceSet {{ {SQUARE} coordIndex [ 0 1 2 3 ] }}"))
    volume, center, inertia = mesh_volume_and_inertia(flat)
    assert volume == 0.0 and np.allclose(center, [1.0, 0.5, 0.0]) and not inertia.any()


def test_urls_that_cannot_be_read() -> None:
    warnings: list = []
    assert mesh_file(_node('Mesh { url "webots://projects/robots/x.obj" }'), warnings) is None
    assert warnings[0].message == ("Mesh url 'webots://projects/robots/x.obj' cannot be read (WBTC_OFFLINE is set; "
                                   "not in WEBOTS_HOME or wbtc's asset cache): no geometry")
    warnings.clear()
    assert mesh_file(_node('Mesh { url [ "missing.obj" ] }'), warnings) is None
    assert warnings[0].message.startswith("Mesh file not found: 'missing.obj'")
    # The first URL that exists wins.
    mesh = mesh_file(_node('Mesh { url [ "https://example.com/a.stl" "missing.stl" "cube.stl" ] }'))
    assert mesh.faces.shape == (12, 3)


def test_relative_url_resolves_against_the_writing_file(tmp_path: Path) -> None:
    # A node written in a PROTO one folder below the meshes: "../cube.stl" climbs back up.
    proto_file = tmp_path / "protos" / "Thing.proto"
    proto_file.parent.mkdir()
    (tmp_path / "cube.stl").write_bytes((FIXTURES / "cube.stl").read_bytes())
    mesh = mesh_file(_node('Mesh { url "../cube.stl" }', path=str(proto_file)))
    assert mesh is not None and mesh.vertices.shape == (8, 3)


def test_mesh_cache_follows_modification_time(tmp_path: Path) -> None:
    clear_mesh_cache()
    target = tmp_path / "shape.stl"
    target.write_bytes((FIXTURES / "cube.stl").read_bytes())
    world = str(tmp_path / "w.wbt")
    first = mesh_file(_node('Mesh { url "shape.stl" }', path=world))
    first.vertices[:] = 0  # results are copies: the cache is not affected
    assert mesh_file(_node('Mesh { url "shape.stl" }', path=world)).vertices.max() == 1.0
    text = (FIXTURES / "cube.stl").read_text().replace("vertex 1 ", "vertex 3 ")
    target.write_text(text)
    stat = target.stat()
    os.utime(target, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000_000))
    assert mesh_file(_node('Mesh { url "shape.stl" }', path=world)).vertices[:, 0].max() == 3.0


# ---------------------------------------------------------------------------------- ElevationGrid


def _ray_height(model: mujoco.MjModel, data: mujoco.MjData, x: float, y: float) -> float:
    geomid = np.zeros(1, dtype=np.int32)
    distance = mujoco.mj_ray(model, data, np.array([x, y, 100.0]), np.array([0.0, 0.0, -1.0]), None, 1, -1, geomid)
    assert distance >= 0
    return 100.0 - distance


def _compile_hfield(field: HeightField, body_quat: tuple[float, float, float, float] = (1, 0, 0, 0)):
    spec = mujoco.MjSpec()
    asset = spec.add_hfield()
    asset.name = "terrain"
    asset.nrow, asset.ncol = field.nrow, field.ncol
    asset.size = list(field.mujoco_size())
    asset.userdata = field.normalized().tolist()
    # The body stands for the ElevationGrid's frame: (1, 2, 0.5) in the world.
    body = spec.worldbody.add_body(pos=[1.0, 2.0, 0.5], quat=list(body_quat))
    geom = body.add_geom(type=mujoco.mjtGeom.mjGEOM_HFIELD, hfieldname="terrain")
    geom.pos = list(field.center_offset)
    geom.quat = list(field.quat)
    model = spec.compile()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    return model, data


def test_elevation_grid_layout() -> None:
    node = _node("ElevationGrid { height [ 0 1 2, 3 4 5 ] xDimension 3 xSpacing 0.5 yDimension 2 ySpacing 2 "
                 "thickness 0.2 }")
    field = elevation_grid(node, legacy_axes=False)
    assert (field.nrow, field.ncol) == (2, 3)
    assert field.heights.dtype == np.float32 and field.heights.tolist() == [[0, 1, 2], [3, 4, 5]]
    assert (field.x_size, field.y_size, field.thickness) == (1.0, 2.0, 0.2)
    assert field.mujoco_size() == (0.5, 1.0, 5.0, 0.2)
    assert field.normalized().tolist() == pytest.approx([0, 0.2, 0.4, 0.6, 0.8, 1.0])
    assert field.center_offset == (0.5, 1.0, 0.0) and field.quat == (1, 0, 0, 0)


def test_hfield_surface_matches_webots_heights() -> None:
    # Webots: grid point (i, j) at (i * xSpacing, j * ySpacing, height[i + j * xDimension]).
    heights = [0.1, 0.4, 0.2, 0.3,
               0.5, 0.9, 0.6, 0.7,
               -0.2, 0.8, 1.2, 0.0]
    node = _node(f"ElevationGrid {{ height [ {' '.join(map(str, heights))} ] xDimension 4 xSpacing 0.5 "
                 "yDimension 3 ySpacing 0.25 thickness 0.1 }")
    field = elevation_grid(node, legacy_axes=False)
    model, data = _compile_hfield(field)
    for i, j in [(1, 0), (2, 2), (0, 1), (3, 1)]:
        x = 1.0 + np.clip(i * 0.5, 1e-9, 1.5 - 1e-9)  # stay inside the grid's edges
        y = 2.0 + np.clip(j * 0.25, 1e-9, 0.5 - 1e-9)
        assert _ray_height(model, data, x, y) == pytest.approx(0.5 + heights[i + 4 * j], abs=1e-5)


def test_legacy_hfield_surface_matches_webots_heights() -> None:
    # Before R2022a: (i * xSpacing, height[i + j * xDimension], j * zSpacing), heights along +y. The
    # body turns the node's +y up (+90 degrees about x), as a world converted to z-up would.
    heights = [0.0, 0.3, 0.6,
               1.0, 0.2, 0.5]
    node = _node(f"ElevationGrid {{ height [ {' '.join(map(str, heights))} ] xDimension 3 xSpacing 1 "
                 "zDimension 2 zSpacing 2 }", version="R2021a")
    field = elevation_grid(node, legacy_axes=True)
    assert (field.nrow, field.ncol, field.x_size, field.y_size) == (2, 3, 2.0, 2.0)
    assert np.allclose(field.heights, [[0.0, 0.3, 0.6], [1.0, 0.2, 0.5]])
    half = np.sqrt(0.5)
    model, data = _compile_hfield(field, body_quat=(half, half, 0.0, 0.0))
    # Node point (x, h, z) lands at world (1 + x, 2 - z, 0.5 + h).
    for i, j in [(1, 0), (2, 1), (0, 1)]:
        x = 1.0 + np.clip(i * 1.0, 1e-9, 2.0 - 1e-9)
        y = 2.0 - np.clip(j * 2.0, 1e-9, 2.0 - 1e-9)
        assert _ray_height(model, data, x, y) == pytest.approx(0.5 + heights[i + 3 * j], abs=1e-5)


def test_elevation_grid_fixes_like_webots() -> None:
    warnings: list = []
    field = elevation_grid(_node("ElevationGrid { height [ 1 2 3 ] xDimension 2 yDimension 2 xSpacing -1 }"),
                           False, warnings)
    assert field.heights.tolist() == [[1, 2], [3, 0]] and field.x_size == 1.0
    assert [w.message for w in warnings] == ["'xSpacing' must be positive: 1 used, as in Webots",
                                             "'height' has 3 value(s) for 4 grid points: the rest are 0"]
    flat = elevation_grid(_node("ElevationGrid { height [ 2 2 2 2 ] xDimension 2 yDimension 2 thickness 0 }"), False)
    assert flat.normalized().tolist() == [0, 0, 0, 0]
    assert flat.mujoco_size()[2:] == (1e-4, 1e-4) and flat.center_offset == (0.5, 0.5, 2.0)
    warnings.clear()
    assert elevation_grid(_node("ElevationGrid { height [ 1 2 ] xDimension 2 yDimension 1 }"), False, warnings) is None
    assert warnings[0].message == "ElevationGrid of 2 x 1 points has no cell: no geometry"
