"""Pen on an IndexedFaceSet without texCoord: Webots' non-repeating mapping on a layer 4 x 2 times the image."""

from pathlib import Path

import numpy as np
from PIL import Image

from wbtc.compile import faceset_uv
from wbtc.compile.mesh_data import MeshData
from wbtc.compile.primitive_uv import Painted
from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 16 }
Background { skyColor [0 0 0] }
DirectionalLight { direction 0 0 -1 intensity 1 }
Solid {
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url ["white64x32.png"] } }
      geometry IndexedFaceSet {
        coord Coordinate { point [-0.5 -0.5 0, 0.5 -0.5 0, 0.5 0.5 0, -0.5 0.5 0] }
        coordIndex [0 1 2 3 -1]
      }
    }
  ]
  name "board"
}
Solid {
  translation 3 0 0
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url ["white64x32.png"] } }
      geometry IndexedFaceSet {
        coord Coordinate { point [-0.5 -0.5 0, 0.5 -0.5 0, 0.5 0.5 0, -0.5 0.5 0] }
        coordIndex [0 1 2 3 -1]
        texCoord TextureCoordinate { point [0 0, 1 0, 1 1, 0 1] }
      }
    }
  ]
  name "mapped"
}
Robot {
  translation 0 0 0.5
  children [
    Pen { name "pen" inkColor 1 0 0 inkDensity 1 leadSize 0.1 }
  ]
  controller "<none>"
}
"""


def _layer(sim: Simulation, body: str) -> tuple[int, np.ndarray]:
    """The paint texture of the one paintable geom of `body`: its id and its texels (a view)."""
    model = sim.model
    names = [name for name in sim.table.paintable if model.geom(name).bodyid == model.body(body).id]
    assert len(names) == 1
    texture = model.texture(sim.table.paintable[names[0]][0]).id
    width, height = int(model.tex_width[texture]), int(model.tex_height[texture])
    adr = int(model.tex_adr[texture])
    channels = int(model.tex_nchannel[texture])
    return texture, model.tex_data[adr:adr + width * height * channels].reshape(height, width, channels)


def test_the_layer_is_4_x_2_images_and_a_stroke_lands_in_the_bottom_face_cell(tmp_path: Path):
    Image.new("RGB", (64, 32), (255, 255, 255)).save(tmp_path / "white64x32.png")
    world = tmp_path / "pen.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    _, layer = _layer(sim, "board")
    # Webots' size factor (4, 2) for the default mapping; (1, 1) when the texture coordinates are valid.
    assert layer.shape == (64, 256, 3)
    assert _layer(sim, "mapped")[1].shape == (32, 64, 3)
    sim.step()
    red = np.all(layer == (255, 0, 0), axis=2)
    # The flat board lies on its bounding box's -z face (checked before +z): u = x / 4, v = y / 2 from
    # the top row. Its centre (fractions 0.5, 0.5) is (0.125, 0.25): texel (row 16, column 32) of the
    # 256 x 64 layer. The stroke keeps Webots' size: leadSize 0.1 x 64 / the radius 0.7071 = 9 texels
    # across, a disc of radius 4.
    assert int(red.sum()) == 49
    rows, cols = np.nonzero(red)
    assert (rows.min(), rows.max(), cols.min(), cols.max()) == (12, 20, 28, 36)


def test_webots_box_face_cells_for_the_non_repeating_mapping():
    low, high = np.array([-1.0, -2.0, -3.0]), np.array([1.0, 2.0, 3.0])
    # One triangle on each face of the box, counter-clockwise seen from outside.
    front = np.array([[1.0, -2.0, -3.0], [1.0, 2.0, -3.0], [1.0, 2.0, 3.0]])  # +x
    top = np.array([[-1.0, -2.0, 3.0], [1.0, -2.0, 3.0], [1.0, 2.0, 3.0]])  # +z
    left = np.array([[1.0, 2.0, -3.0], [-1.0, 2.0, -3.0], [-1.0, 2.0, 3.0]])  # +y
    corners = np.stack([front, top, left])
    assert faceset_uv.box_faces(corners, low, high).tolist() == ["+x", "+z", "+y"]
    uv = faceset_uv.layer_coordinates(corners, low, high)
    # +x: u = 0.75 + y / 4, v = 0.5 + (1 - z) / 2 (fractions of the box, v from the top row).
    np.testing.assert_allclose(uv[0], [[0.75, 1.0], [1.0, 1.0], [1.0, 0.5]])
    # +z: u = 0.5 + x / 4, v = (1 - y) / 2.
    np.testing.assert_allclose(uv[1], [[0.5, 0.5], [0.75, 0.5], [0.75, 0.0]])
    # +y: u = (1 - x) / 4, v = 0.5 + (1 - z) / 2.
    np.testing.assert_allclose(uv[2], [[0.0, 1.0], [0.25, 1.0], [0.25, 0.5]])


def test_the_layer_shows_the_image_through_the_default_mapping():
    # A 2 x 2 image: red, green on the top row; blue, white below.
    image = np.array([[[255, 0, 0], [0, 255, 0]], [[0, 0, 255], [255, 255, 255]]], dtype=np.uint8)
    # The unit square z = 0, facing +z: its -z cell is u = x / 4, v = y / 2 from the top row (MeshData's
    # t = 1 - v), and the default mapping shows s = x, t = y.
    square = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]])
    layer_uv = np.column_stack([square[:, 0] / 4, 1.0 - square[:, 1] / 2])
    mesh = MeshData(square, np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int32), layer_uv.astype(np.float32))
    layer = faceset_uv.draw_layer(image, Painted(mesh, (4, 2), [], image_uv=square[:, :2]), (8, 4), None)
    # The layer's first row is y = 0.25 (t = 0.25: the image's bottom row): the image upside down.
    assert layer[0, 0].tolist() == [0, 0, 255] and layer[0, 1].tolist() == [255, 255, 255]
    assert layer[1, 0].tolist() == [255, 0, 0] and layer[1, 1].tolist() == [0, 255, 0]
    # Texels beyond the triangles stay white but for a 2-texel rim copied from their edges.
    assert layer[3, 7].tolist() == [255, 255, 255] and layer[0, 2].tolist() == [255, 255, 255]
    assert layer[1, 3].tolist() == [0, 255, 0]
