"""Pen on a Box: Webots' layout of the six faces in the paint layer, and a stroke that spills over an edge.

Webots paints a Box through its non-repeating texture coordinates (WbBox::computeTextureCoordinate with
`nonRecursive`, the same as the second texture coordinates of wren's unit box), counted with v from the
layer's first row: the four sides in its lower half (left, back, right, front from u = 0), the bottom and
the top in its upper half at u 0 to 0.25 and 0.5 to 0.75. A stroke is a disc of texels of the whole layer,
not cut at a face's slot, so where it spills out of one face's slot is decided by that layout.
"""

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from wbtc.compile import primitive_uv
from wbtc.pipeline import compile_world
from wbtc.runtime import pen_uv
from wbtc.runtime.simulation import Simulation
from wbtc.scene import build_scene
from wbtc.vrml import parse_text

WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 16 }
Background { skyColor [0 0 0] }
Solid {
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url ["white64.png"] } }
      geometry Box { size 0.1 0.1 0.1 }
    }
  ]
  name "cube"
}
Robot {
  children [
    Pen { translation 0.01 -0.2 0.048 rotation 1 0 0 1.5708 name "pen" inkColor 1 0 0 inkDensity 1 leadSize 0.02 }
  ]
  controller "<none>"
}
"""


@pytest.mark.parametrize(("point", "normal", "expected"), [
    # Box size (0.1, 0.2, 0.3); Webots' (u, v) from WbBox::computeTextureCoordinate, non-recursive.
    ((0.05, 0.02, 0.06), (1, 0, 0), (0.9, 0.65)),  # front (+x): u = 0.75 + 0.25 y', v = 0.5 + 0.5 (1 - z')
    ((-0.05, 0.02, 0.06), (-1, 0, 0), (0.35, 0.65)),  # back (-x): u = 0.25 + 0.25 (1 - y')
    ((0.03, 0.1, 0.06), (0, 1, 0), (0.05, 0.65)),  # left (+y): u = 0.25 (1 - x')
    ((0.03, -0.1, 0.06), (0, -1, 0), (0.7, 0.65)),  # right (-y): u = 0.5 + 0.25 x'
    ((0.03, 0.02, 0.15), (0, 0, 1), (0.7, 0.2)),  # top (+z): u = 0.5 + 0.25 x', v = 0.5 (1 - y')
    ((0.03, 0.02, -0.15), (0, 0, -1), (0.2, 0.3)),  # bottom (-z): u = 0.25 x', v = 0.5 y'
])
def test_box_faces_lie_in_webots_slots_of_the_layer(point, normal, expected):
    # x', y', z': the point's coordinates from the box's minimum corner over its size (0.8, 0.6, 0.7 here).
    text = "#VRML_SIM R2023b utf8\nShape { geometry Box { size 0.1 0.2 0.3 } }\n"
    box = next(node for node in build_scene(parse_text(text, "box.wbt")).walk() if node.base_type == "Box")
    painted = primitive_uv.primitive_mesh(box)
    assert painted is not None and painted.grid == (4, 2)
    mesh = painted.mesh
    # The layer's (u, v) with v from its first row, as MuJoCo keeps them (MeshData counts t upwards).
    tris = pen_uv.Triangles(mesh.vertices[mesh.faces], mesh.mujoco_texcoords()[mesh.faces].astype(float))
    normal = np.array(normal, dtype=float)
    hit = pen_uv.locate(tris, np.array(point) + 0.5 * normal, -normal)
    assert hit is not None
    assert pen_uv.texture_point(tris, hit[0], hit[1]).tolist() == pytest.approx(expected, abs=1e-6)


def test_a_stroke_near_the_right_face_top_edge_spills_onto_the_top_face(tmp_path: Path):
    Image.new("RGB", (64, 64), (255, 255, 255)).save(tmp_path / "white64.png")
    world = tmp_path / "pen_box.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    (geom,) = sim.table.paintable
    texture = sim.model.texture(sim.table.paintable[geom][0]).id
    model = sim.model
    width, height = int(model.tex_width[texture]), int(model.tex_height[texture])
    adr = int(model.tex_adr[texture])
    layer = model.tex_data[adr:adr + width * height * 3].reshape(height, width, 3)
    assert (width, height) == (256, 128)  # the 64-pixel image x (4, 2)
    sim.step()  # the pen writes from the start
    red = np.all(layer == (255, 0, 0), axis=2)
    # The pen looks along +y at the right face (-y) at x = 0.01, z = 0.048: x' = 0.6, z' = 0.98, so
    # (u, v) = (0.5 + 0.25 x', 0.5 + 0.5 (1 - z')) = (0.65, 0.51), texel (166, 65) (truncated). The stroke:
    # leadSize 0.02 x 64 / 0.0866 = 14 texels across, a disc of radius 7 about it: rows 58 to 72,
    # columns 159 to 173.
    disc = {(65 + dr, 166 + dc) for dr in range(-7, 8) for dc in range(-7, 8) if dr * dr + dc * dc <= 49}
    rows, cols = np.nonzero(red)
    assert set(zip(rows.tolist(), cols.tolist(), strict=True)) == disc
    assert len(disc) == 149
    # Its rows 58 to 63 lie in the top face's slot (rows 0 to 63, columns 128 to 191), at the top face's
    # y = -h edge, the one it shares with the right face: 54 texels of the stroke show there, over the edge.
    assert int(red[:64, 128:192].sum()) == 54
