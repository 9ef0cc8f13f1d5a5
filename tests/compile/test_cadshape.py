"""CadShape (R2022b+): one visual geom per material of its .obj/.dae file, with the file's own colours and textures.

The fixture world (fixtures/worlds/cadshape.wbt) holds cad_parts.obj (a red and a blue box, two materials of
cad_parts.mtl), cad_part.dae (a green tetrahedron written y-up, moved 1 m along y) and a CadShape whose
file is missing, in a Solid whose mass comes from its 0.1 m Box bounding object alone.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

from tests.conftest import serving
from wbtc.compile import remote
from wbtc.compile.cad_files import clear_cad_cache, read_mtl
from wbtc.compile.cad_shape import companion
from wbtc.pipeline import compile_world
from wbtc.runtime.devices import Camera
from wbtc.runtime.simulation import Simulation

FIXTURES = Path(__file__).resolve().parent / "fixtures"
WORLD = FIXTURES / "worlds" / "cadshape.wbt"
RED, BLUE, GREEN = [0.8, 0.1, 0.1, 1.0], [0.1, 0.2, 0.9, 1.0], [0.2, 0.7, 0.3, 1.0]


@pytest.fixture(autouse=True)
def _fresh_cache() -> Iterator[None]:
    clear_cad_cache()
    yield
    clear_cad_cache()


def _cad_geoms(model: mujoco.MjModel) -> list[int]:
    """The visual mesh geoms (group 1): in these worlds, only CadShapes make meshes."""
    return [g for g in range(model.ngeom)
            if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH and model.geom_group[g] == 1]


def _world_vertices(model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> np.ndarray:
    mesh = int(model.geom_dataid[geom])
    start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
    return model.mesh_vert[start:start + count] @ data.geom_xmat[geom].reshape(3, 3).T + data.geom_xpos[geom]


def _extents(result) -> dict[tuple[float, ...], tuple[list[float], list[float]]]:
    """Each CadShape geom's world bounding box (min, max), by its rgba."""
    model = result.model
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    boxes = {}
    for g in _cad_geoms(model):
        points = _world_vertices(model, data, g)
        boxes[tuple(round(float(v), 4) for v in model.geom_rgba[g])] = (np.round(points.min(0), 6).tolist(),
                                                          np.round(points.max(0), 6).tolist())
    return boxes


def _compile_text(tmp_path: Path, children: str) -> object:
    world = tmp_path / "world.wbt"
    world.write_text(f"#VRML_SIM R2025a utf8\nWorldInfo {{ }}\nSolid {{\n  children [\n{children}\n  ]\n}}\n")
    result, _ = compile_world(world)
    return result


# ---------------------------------------------------------------------------------- the fixture world


def test_one_visual_geom_per_material_with_the_files_colours_and_places() -> None:
    result, _ = compile_world(WORLD)
    boxes = _extents(result)
    assert len(_cad_geoms(result.model)) == 3
    assert boxes == {
        tuple(RED): ([-0.3, -0.1, 0.0], [-0.1, 0.1, 0.2]),
        tuple(BLUE): ([0.1, -0.1, 0.0], [0.3, 0.1, 0.4]),
        # Y-up COLLADA: (x, y, z) in the file lands at (x, -z, y); the file's node moves it 0.5 along x.
        tuple(GREEN): ([0.5, 1.0, 0.0], [0.7, 1.1, 0.4]),
    }
    # The boxes keep their 8 corners each (quads split in two triangles, 12 per box), the tetrahedron its 4.
    model = result.model
    counts = sorted((int(model.mesh_vertnum[model.geom_dataid[g]]), int(model.mesh_facenum[model.geom_dataid[g]]))
                    for g in _cad_geoms(model))
    assert counts == [(4, 4), (8, 12), (8, 12)]


def test_materials_follow_webots_pbr_conversion() -> None:
    model = compile_world(WORLD)[0].model
    by_colour = {tuple(round(float(v), 4) for v in model.geom_rgba[g]): int(model.geom_matid[g])
                 for g in _cad_geoms(model)}
    # Roughness 1 − shininess/255 (red: Ns 0 -> 1, blue: Ns 127.5 -> 0.5, green: 51 -> 0.8), metalness 0:
    # a dielectric's highlight 0.5·(1 − roughness), shininess 1 − roughness (appearance._pbr_specular).
    for colour, specular, shininess in ((RED, 0.0, 0.0), (BLUE, 0.25, 0.5), (GREEN, 0.1, 0.2)):
        material = by_colour[tuple(colour)]
        assert model.mat_rgba[material].tolist() == pytest.approx(colour)
        assert model.mat_specular[material] == pytest.approx(specular)
        assert model.mat_shininess[material] == pytest.approx(shininess)


def test_cad_geoms_do_not_collide_and_add_no_mass() -> None:
    model = compile_world(WORLD)[0].model
    geoms = _cad_geoms(model)
    assert [(int(model.geom_contype[g]), int(model.geom_conaffinity[g])) for g in geoms] == [(0, 0)] * 3
    colliding = [g for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g]]
    assert [int(model.geom_type[g]) for g in colliding] == [mujoco.mjtGeom.mjGEOM_BOX]
    body = int(model.geom_bodyid[geoms[0]])
    assert model.body_mass[body] == pytest.approx(1.0)  # 0.1 m box at density 1000, nothing else
    assert model.body_inertia[body] == pytest.approx([1.0 * 0.02 / 12] * 3)
    assert model.body_ipos[body] == pytest.approx([0.0, 0.0, 0.0])


def test_missing_file_warns_at_the_node_and_the_world_compiles() -> None:
    result, _ = compile_world(WORLD)
    lines = WORLD.read_text().splitlines()
    line = next(i for i, text in enumerate(lines, 1) if "missing.obj" in text) - 2  # the CadShape's own line
    column = lines[line - 1].index("CadShape") + 1
    found = [w for w in result.warnings if "missing.obj" in w.message]
    assert [(w.span.line, w.span.column, w.topic) for w in found] == [(line, column, "unreadable file")]
    assert found[0].message.startswith("CadShape file not found: '../meshes/missing.obj'")
    assert str(found[0].span).endswith(f"cadshape.wbt:{line}:{column}")
    assert len(result.warnings) == 1
    assert result.model.ngeom == 4  # the bounding box and the three parts of the two files found


def test_camera_sees_the_parts_in_their_colours() -> None:
    result, _ = compile_world(WORLD)
    sim = Simulation(result, noise=False)
    try:
        camera = next(s for s in sim.robots[0].sensors.values() if isinstance(s, Camera))
        rgb = sim.renderer(64, 64).draw(sim.data, camera.camera, camera.near)[::-1].astype(int)
    finally:
        sim.close()
    # 1.5 m above, field of view 1 rad: the red box's top (x = -0.2, 1.3 m away) is 9 rows below the
    # centre, the blue one's (x = 0.2, 1.1 m away) 10.6 rows above; between them the black sky.
    red, blue, middle = rgb[41, 32], rgb[21, 32], rgb[32, 32]
    assert red[0] > 40 and red[0] > 2 * max(red[1], red[2])
    assert blue[2] > 40 and blue[2] > max(blue[0], blue[1]) + 20
    assert middle.max() < 10


def test_recordings_carry_the_parts() -> None:
    from wbtc.runtime.animation import _scene

    result, _ = compile_world(WORLD)
    sim = Simulation(result, noise=False)
    try:
        scene = _scene(sim)
    finally:
        sim.close()
    meshes = sorted(entry["rgba"] for entry in scene["geoms"] if entry["type"] == "mesh")
    assert meshes == sorted([RED, BLUE, GREEN])


# ---------------------------------------------------------------------------------- files


def test_mtl_fields_webots_reads(tmp_path: Path) -> None:
    (tmp_path / "look.mtl").write_text(
        "newmtl glow\nKd 0.5\nKe 0.1 0.2 0.3\nd 0.25\nNs 300\nKs 1 1 1\nillum 2\n"
        "newmtl clear\nTr 0.4\nNs 25.5\nmap_Kd -s 1 1 1 -clamp on textures\\my image.png\n"
        "newmtl plain\n")
    materials = read_mtl(str(tmp_path / "look.mtl"))
    glow, clear, plain = materials["glow"], materials["clear"], materials["plain"]
    assert glow.base == (0.5, 0.5, 0.5) and glow.emissive == (0.1, 0.2, 0.3)
    assert glow.transparency == pytest.approx(0.75)  # d is the opacity
    assert glow.roughness == 0.0  # 1 − 300/255 < 0: Webots resets it to 0
    assert clear.transparency == pytest.approx(0.4)  # Tr is 1 − opacity
    assert clear.roughness == pytest.approx(0.9)
    assert clear.texture == "textures/my image.png"
    assert clear.base == (0.6, 0.6, 0.6)  # Assimp's default Kd
    assert (plain.base, plain.roughness, plain.transparency, plain.texture) == ((0.6, 0.6, 0.6), 1.0, 0.0, None)


def test_textured_obj_finds_its_texture_beside_the_obj(tmp_path: Path) -> None:
    # The .mtl is in a subfolder; its map_Kd is found relative to the .obj file, as Webots looks for it.
    (tmp_path / "materials").mkdir()
    shutil.copy(FIXTURES / "meshes" / "checker.png", tmp_path / "checker.png")
    (tmp_path / "materials" / "plate.mtl").write_text("newmtl plate\nKd 0.2 0.2 0.2\nmap_Kd checker.png\n")
    (tmp_path / "plate.obj").write_text(
        "mtllib materials/plate.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "usemtl plate\nf 1/1 2/2 3/3 4/4\nusemtl\nf 1 3 4\n")
    result = _compile_text(tmp_path, 'CadShape { url [ "plate.obj" ] }')
    model = result.model
    assert not result.warnings
    geoms = _cad_geoms(model)
    assert len(geoms) == 2
    textured = [g for g in geoms if model.mat_texid[model.geom_matid[g], mujoco.mjtTextureRole.mjTEXROLE_RGB] >= 0]
    assert len(textured) == 1 and model.ntex == 1
    mesh = int(model.geom_dataid[textured[0]])
    assert int(model.mesh_texcoordnum[mesh]) == 4
    # The face written after a bare `usemtl` has no material: Assimp's default grey.
    plain = next(g for g in geoms if g not in textured)
    assert model.geom_rgba[plain].tolist() == pytest.approx([0.6, 0.6, 0.6, 1.0])


def test_missing_mtl_warns_and_leaves_the_parts_grey(tmp_path: Path) -> None:
    (tmp_path / "tri.obj").write_text("mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl red\n"
                                      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    result = _compile_text(tmp_path, 'CadShape { url [ "tri.obj" ] }')
    [warning] = result.warnings
    assert "material file 'gone.mtl' not found" in warning.message and warning.topic == "unreadable file"
    [geom] = _cad_geoms(result.model)
    assert result.model.geom_rgba[geom].tolist() == pytest.approx([0.6, 0.6, 0.6, 1.0])


def test_ccw_false_turns_the_faces_over(tmp_path: Path) -> None:
    shutil.copy(FIXTURES / "meshes" / "cad_parts.obj", tmp_path)
    shutil.copy(FIXTURES / "meshes" / "cad_parts.mtl", tmp_path)

    def outward(ccw: str) -> list[float]:
        model = _compile_text(tmp_path, f'CadShape {{ url [ "cad_parts.obj" ] ccw {ccw} }}').model
        signs = []
        for g in _cad_geoms(model):
            mesh = int(model.geom_dataid[g])
            vertices = model.mesh_vert[model.mesh_vertadr[mesh]:model.mesh_vertadr[mesh] + model.mesh_vertnum[mesh]]
            faces = model.mesh_face[model.mesh_faceadr[mesh]:model.mesh_faceadr[mesh] + model.mesh_facenum[mesh]]
            a, b, c = (vertices[faces[:, k]] for k in range(3))
            normals = np.cross(b - a, c - a)
            # A box's face normal points away from the box's centre when the face is seen from outside.
            signs += np.sign(np.einsum("ij,ij->i", normals, (a + b + c) / 3 - vertices.mean(0))).tolist()
        return signs

    assert outward("TRUE") == [1.0] * 24
    assert outward("FALSE") == [-1.0] * 24


def test_z_up_centimetre_dae_with_texture_and_transparency(tmp_path: Path) -> None:
    shutil.copy(FIXTURES / "meshes" / "checker.png", tmp_path / "checker.png")
    (tmp_path / "quad.dae").write_text(QUAD_DAE)
    result = _compile_text(tmp_path, 'CadShape { url [ "quad.dae" ] }')
    assert not result.warnings
    model = result.model
    [geom] = _cad_geoms(model)
    # A Z_UP file keeps its axes in Webots; its centimetres become metres.
    assert list(_extents(result).values()) == [([0.0, 0.0, 0.0], [0.1, 0.2, 0.0])]
    material = int(model.geom_matid[geom])
    assert model.mat_texid[material, mujoco.mjtTextureRole.mjTEXROLE_RGB] >= 0
    # <transparent opaque="A_ONE"> alpha 0.25 × <transparency> 1: opacity 0.25.
    assert model.geom_rgba[geom].tolist() == pytest.approx([1.0, 1.0, 1.0, 0.25])


def test_other_files_and_broken_files_warn_and_are_left_out(tmp_path: Path) -> None:
    (tmp_path / "part.stl").write_text("solid x\nendsolid x\n")
    (tmp_path / "broken.dae").write_text("<COLLADA><library_geometries>")
    result = _compile_text(tmp_path, 'CadShape { url [ "part.stl" ] }\nCadShape { url [ "broken.dae" ] }\n'
                                     'CadShape { castShadows FALSE }')
    messages = [(w.span.line, w.message) for w in result.warnings]
    assert messages[0] == (5, "CadShape url 'part.stl' is not a Collada ('.dae') or Wavefront ('.obj') file; "
                              "it is left out")
    assert messages[1][0] == 6 and messages[1][1].startswith("cannot read ")
    assert messages[2] == (6, "the CadShape's file cannot be read; it is left out")
    assert (7, "CadShape.castShadows is not honoured by wbtc yet; it is ignored") in messages
    assert (7, "CadShape has no url: it shows nothing") in messages
    assert _cad_geoms(result.model) == []


def test_companion_files_are_named_beside_the_cad_file() -> None:
    assert companion("forklift.mtl", "webots://projects/vehicles/meshes/forklift.obj") == (
        "webots://projects/vehicles/meshes/forklift.mtl")
    assert companion("../textures/a.png", "https://example.org/m/parts/x.dae") == "https://example.org/m/textures/a.png"
    assert companion("tex\\b.png", "/data/cad/x.obj") == "/data/cad/tex/b.png"
    assert companion("/abs/c.png", "/data/cad/x.obj") == "/abs/c.png"


@pytest.fixture
def site(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[tuple[Path, list[str]]]:
    """`webots://` served by an HTTP server on 127.0.0.1 from `tmp_path/site/R2025a`, an empty asset cache."""
    root = tmp_path / "site"
    (root / "R2025a").mkdir(parents=True)
    monkeypatch.delenv("WBTC_OFFLINE", raising=False)
    monkeypatch.delenv("WEBOTS_HOME", raising=False)
    monkeypatch.setenv("WBTC_ASSET_CACHE", str(tmp_path / "cache"))
    monkeypatch.setattr(remote, "_FAILED", {})
    monkeypatch.setattr(remote, "_UNREACHABLE", [])
    with serving(root) as (port, asked):
        monkeypatch.setenv("WBTC_WEBOTS_URL", f"http://127.0.0.1:{port}/R2025a/")
        yield root / "R2025a", asked


def test_remote_obj_fetches_its_mtl_and_texture_from_beside_it(tmp_path: Path, site) -> None:
    folder, asked = site
    meshes = folder / "projects" / "cad" / "meshes"
    meshes.mkdir(parents=True)
    shutil.copy(FIXTURES / "meshes" / "checker.png", meshes / "checker.png")
    (meshes / "plate.mtl").write_text("newmtl plate\nKd 0.3 0.4 0.5\nmap_Kd checker.png\nnewmtl dark\nKd 0.1 0 0\n")
    (meshes / "plate.obj").write_text("mtllib plate.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\n"
                                      "vt 1 1\nvt 0 1\nusemtl plate\nf 1/1 2/2 3/3\nusemtl dark\nf 1 3 4\n")
    result = _compile_text(tmp_path, 'CadShape { url [ "webots://projects/cad/meshes/plate.obj" ] }')
    assert not result.warnings
    assert sorted(asked) == sorted(f"/R2025a/projects/cad/meshes/{name}"
                                   for name in ("plate.obj", "plate.mtl", "checker.png"))
    model = result.model
    colours = sorted([round(float(v), 4) for v in model.geom_rgba[g]] for g in _cad_geoms(model))
    assert colours == [[0.1, 0.0, 0.0, 1.0], [1.0, 1.0, 1.0, 1.0]]  # a textured part shows its texture
    assert model.ntex == 1


QUAD_DAE = """<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="centimeter" meter="0.01"/><up_axis>Z_UP</up_axis></asset>
  <library_images><image id="checker-image"><init_from>checker.png</init_from></image></library_images>
  <library_effects>
    <effect id="tex-effect"><profile_COMMON>
      <newparam sid="checker-surface"><surface type="2D"><init_from>checker-image</init_from></surface></newparam>
      <newparam sid="checker-sampler"><sampler2D><source>checker-surface</source></sampler2D></newparam>
      <technique sid="common"><lambert>
        <diffuse><texture texture="checker-sampler" texcoord="UVMap"/></diffuse>
        <transparent opaque="A_ONE"><color>0 0 0 0.25</color></transparent>
      </lambert></technique>
    </profile_COMMON></effect>
  </library_effects>
  <library_materials><material id="tex-material"><instance_effect url="#tex-effect"/></material></library_materials>
  <library_geometries><geometry id="quad"><mesh>
    <source id="quad-pos"><float_array id="quad-pos-array" count="12">0 0 0 10 0 0 10 20 0 0 20 0</float_array>
      <technique_common><accessor source="#quad-pos-array" count="4" stride="3">
        <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
      </accessor></technique_common></source>
    <source id="quad-uv"><float_array id="quad-uv-array" count="8">0 0 1 0 1 1 0 1</float_array>
      <technique_common><accessor source="#quad-uv-array" count="4" stride="2">
        <param name="S" type="float"/><param name="T" type="float"/>
      </accessor></technique_common></source>
    <vertices id="quad-vertices"><input semantic="POSITION" source="#quad-pos"/></vertices>
    <polylist material="mat" count="1">
      <input semantic="VERTEX" source="#quad-vertices" offset="0"/>
      <input semantic="TEXCOORD" source="#quad-uv" offset="1" set="0"/>
      <vcount>4</vcount>
      <p>0 0 1 1 2 2 3 3</p>
    </polylist>
  </mesh></geometry></library_geometries>
  <library_visual_scenes><visual_scene id="scene"><node id="n">
    <instance_geometry url="#quad"><bind_material><technique_common>
      <instance_material symbol="mat" target="#tex-material"/></technique_common></bind_material></instance_geometry>
  </node></visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
"""


def test_an_led_lights_its_shapes_but_not_its_cadshapes(tmp_path: Path) -> None:
    shutil.copy(FIXTURES / "meshes" / "cad_parts.obj", tmp_path)
    shutil.copy(FIXTURES / "meshes" / "cad_parts.mtl", tmp_path)
    world = tmp_path / "led.wbt"
    world.write_text('#VRML_SIM R2025a utf8\nWorldInfo { }\nRobot {\n  children [\n    LED {\n      children [\n'
                     '        CadShape { url [ "cad_parts.obj" ] }\n'
                     '        Shape { geometry Sphere { radius 0.01 } }\n      ]\n    }\n  ]\n}\n')
    result, _ = compile_world(world)
    model = result.model
    led = next(d for d in result.table.robots[0].devices if d.type == "LED")
    # Webots' LED changes the materials of the Shapes among its children; a CadShape is not a Shape.
    assert [int(model.geom_type[model.geom(name).id]) for name in led.geoms] == [mujoco.mjtGeom.mjGEOM_SPHERE]
    assert len(_cad_geoms(model)) == 2
