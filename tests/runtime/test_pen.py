"""Pen: ink on shapes, with Webots' stroke size, blending, reach and paint layer."""

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from wbtc.compile import primitive_uv
from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 16 }
Background { skyColor [0 0 0] }
DirectionalLight { direction 0 0 -1 intensity 1 }
Solid {
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url ["white64.png"] } }
      geometry Plane { size 1 1 }
    }
  ]
  name "board"
}
Solid {
  translation 2 0 0.05
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url ["white64.png"] } }
      geometry Box { size 0.1 0.1 0.1 }
    }
  ]
  name "cube"
}
Solid {
  translation -2 0 0.05
  children [ Shape { geometry Box { size 0.1 0.1 0.1 } } ]
  name "plain"
}
Robot {
  translation 0 0 0.5
  children [
    Pen { name "pen" inkColor 1 0 0 inkDensity 1 leadSize 0.1 }
    Pen { translation 0.2 0 0 name "short" inkColor 1 0 0 leadSize 0.1 maxDistance 0.2 }
    Pen { translation 0.3 0 0 name "reach" inkColor 1 0 0 leadSize 0.1 maxDistance 0.6 write FALSE }
    Pen { translation -2 0 0 name "untextured" inkColor 1 0 0 leadSize 0.1 }
    Pen { translation 2 0 0 name "cube pen" inkColor 0 0 1 inkDensity 1 leadSize 0.01 write FALSE }
    Camera { translation 0 0 -0.1 rotation 0 1 0 1.5708 name "camera" width 16 height 16 fieldOfView 0.2 }
  ]
  controller "<none>"
}
"""


@pytest.fixture
def pen_world(tmp_path: Path):
    Image.new("RGB", (64, 64), (255, 255, 255)).save(tmp_path / "white64.png")
    world = tmp_path / "pen.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    # Every pen but the one a test needs stays up.
    apply_commands(sim, robot, [(tags[name], "write", False) for name in ("pen", "short", "untextured")])
    return sim, robot, tags


def _texture(sim: Simulation, geom_name: str) -> tuple[int, np.ndarray]:
    texture = sim.model.texture(sim.table.paintable[geom_name][0]).id
    model = sim.model
    width, height, channels = (int(model.tex_width[texture]), int(model.tex_height[texture]),
                               int(model.tex_nchannel[texture]))
    adr = int(model.tex_adr[texture])
    return texture, model.tex_data[adr:adr + width * height * channels].reshape(height, width, channels)


def _paintable(sim: Simulation, body: str) -> str:
    names = [name for name in sim.table.paintable if sim.model.geom(name).bodyid == sim.model.body(body).id]
    assert len(names) == 1
    return names[0]


def test_a_pen_over_a_textured_plane_inks_webots_disc(pen_world):
    sim, robot, tags = pen_world
    _, pixels = _texture(sim, _paintable(sim, "board"))
    assert (pixels == 255).all()
    apply_commands(sim, robot, [(tags["pen"], "write", True)])
    sim.step()
    red = np.all(pixels == (255, 0, 0), axis=2)
    # Webots' stroke: leadSize 0.1 x 64 texels / the plane's bounding radius 0.7071 = 9 texels across, a
    # disc of radius 4 texels around the texel under the pen (the plane's centre: texel (32, 32)).
    assert int(red.sum()) == sum(1 for dr in range(-4, 5) for dc in range(-4, 5) if dr * dr + dc * dc <= 16) == 49
    rows, cols = np.nonzero(red)
    assert (rows.min(), rows.max(), cols.min(), cols.max()) == (28, 36, 28, 36)
    assert (pixels[~red] == 255).all()


def test_density_half_covers_half_in_linear_light_and_strokes_add_up(pen_world):
    sim, robot, tags = pen_world
    _, pixels = _texture(sim, _paintable(sim, "board"))
    apply_commands(sim, robot, [(tags["pen"], "setInkColor", 0x000000, 0.5), (tags["pen"], "write", True)])
    sim.step()
    # Half of white's linear light is left: 0.5 in sRGB is 188.
    assert pixels[32, 32].tolist() == [188, 188, 188]
    sim.step()
    # A second stroke of 0.5 covers the rest (Webots adds densities up to 1).
    assert pixels[32, 32].tolist() == [0, 0, 0]


def test_colours_mix_by_density_as_webots_layer_does(pen_world):
    sim, robot, tags = pen_world
    _, pixels = _texture(sim, _paintable(sim, "board"))
    apply_commands(sim, robot, [(tags["pen"], "setInkColor", 0x00FF00, 1.0), (tags["pen"], "write", True)])
    sim.step()
    apply_commands(sim, robot, [(tags["pen"], "setInkColor", 0xCC33FF, 1.0)])
    sim.step()
    # Equal densities: the mean of green and purple, (0.4, 0.6, 0.5) in linear light, written as sRGB.
    assert pixels[32, 32].tolist() == [170, 203, 188]


def test_write_false_stops_the_ink(pen_world):
    sim, robot, tags = pen_world
    texture, pixels = _texture(sim, _paintable(sim, "board"))
    apply_commands(sim, robot, [(tags["pen"], "setInkColor", 0x000000, 0.25), (tags["pen"], "write", True)])
    sim.step()
    once = pixels.copy()
    apply_commands(sim, robot, [(tags["pen"], "write", False)])
    version = sim.texture_versions[texture]
    sim.step()
    sim.step()
    assert (pixels == once).all() and sim.texture_versions[texture] == version


def test_no_ink_beyond_max_distance_and_ink_within_it(pen_world):
    sim, robot, tags = pen_world
    _, pixels = _texture(sim, _paintable(sim, "board"))
    apply_commands(sim, robot, [(tags["short"], "write", True)])  # the board is 0.5 m below, reach 0.2 m
    sim.step()
    assert (pixels == 255).all() and not sim.canvases
    apply_commands(sim, robot, [(tags["short"], "write", False), (tags["reach"], "write", True)])
    sim.step()
    assert int(np.any(pixels != 255, axis=2).sum()) == 49


def test_an_untextured_shape_gets_ink_on_a_layer_of_webots_default_size(pen_world):
    sim, robot, tags = pen_world
    _, layer = _texture(sim, _paintable(sim, "plain"))
    # A 0.1 m Box: bounding radius 0.0866 m, so Webots' default side 32 + 992 x 0.0866 / 10 = 40.6 texels, the
    # nearest power of two 32, x (4, 2) for a Box's faces; in the shape's own colour (white here), which the
    # material no longer multiplies.
    assert layer.shape == (64, 128, 3) and (layer == 255).all()
    geom = sim.model.geom(_paintable(sim, "plain"))
    assert sim.model.mat_rgba[geom.matid[0]].tolist() == [1.0, 1.0, 1.0, 1.0]
    apply_commands(sim, robot, [(tags["untextured"], "write", True)])
    sim.step()
    # leadSize 0.1 x 32 / 0.0866 = 36 texels across: a disc of radius 18 about the top face's centre, which
    # Webots' layer has at (u, v) = (0.625, 0.25): row 16, column 80 of the 128 x 64 layer. Clipped by the
    # layer's first row only (not by the face's slot, as Webots' layer is one image); ink density 0.5 of
    # red over white, blended in linear light: (255, 188, 188).
    inked = np.any(layer != 255, axis=2)
    rows, cols = np.nonzero(inked)
    assert (rows.min(), rows.max(), cols.min(), cols.max()) == (0, 34, 62, 98)
    assert int(inked.sum()) == 997
    assert {tuple(v) for v in layer[inked].tolist()} == {(255, 188, 188)}


def test_default_layer_sizes():
    from wbtc.compile.paintable import default_size

    assert [default_size(r) for r in (0.0, 0.1, 0.7071, 3.0, 5.0, 10.0, 25.0)] == [32, 32, 128, 256, 512, 1024, 1024]


def test_ink_on_a_box_face_stays_on_that_face(pen_world):
    sim, robot, tags = pen_world
    _, layer = _texture(sim, _paintable(sim, "cube"))
    assert layer.shape == (128, 256, 3)  # Webots' layer of a Box: the 64-pixel image x (4, 2)
    apply_commands(sim, robot, [(tags["cube pen"], "write", True)])
    sim.step()
    blue = np.all(layer == (0, 0, 255), axis=2)
    rows, cols = np.nonzero(blue)
    assert len(rows) > 0
    # All of it within one face's slot of the layer (64 x 64 texels): the top face's, Webots' third slot of
    # the first row (u 0.5 to 0.75, v 0 to 0.5).
    assert {(r // 64, c // 64) for r, c in zip(rows, cols, strict=True)} == {(0, 2)}


def test_a_camera_sees_the_ink(pen_world):
    sim, robot, tags = pen_world
    apply_commands(sim, robot, [(tags["camera"], "enable", 16), (tags["pen"], "write", True)])
    sim.step()
    blue, green, red = robot.sensors[tags["camera"]].pixels[8, 8, :3].tolist()
    assert red > 150 and green < 30 and blue < 30


def test_worlds_without_a_pen_keep_their_shared_textures(tmp_path: Path):
    Image.new("RGB", (64, 64), (255, 255, 255)).save(tmp_path / "white64.png")
    world = tmp_path / "nopen.wbt"
    world.write_text(WORLD[:WORLD.index("Robot {")])
    result, _ = compile_world(world)
    assert not result.table.paintable
    names = [result.model.texture(t).name for t in range(result.model.ntex)]
    assert not any(name.startswith("paint_") for name in names)


def test_primitive_meshes_face_outwards_and_fill_their_layer_slots():
    for made in (primitive_uv.box(np.array([0.1, 0.2, 0.3])), primitive_uv.revolution(0.1, 0.2, "cylinder", 12),
                 primitive_uv.revolution(0.1, 0.2, "cone"), primitive_uv.revolution(0.1, 0.2, "capsule"),
                 [primitive_uv.sphere(0.1)]):
        for part in made:
            corners = part.vertices[part.faces]
            normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
            assert (np.einsum("ij,ij->i", normals, corners.mean(axis=1)) > 0).all()
            assert part.texcoords.min() >= 0.0 and part.texcoords.max() <= 1.0


def test_shapes_sharing_an_image_each_get_their_own_texture(pen_world):
    sim, _, _ = pen_world
    textures = [entry[0] for entry in sim.table.paintable.values()]
    assert len(textures) == 3 and len(set(textures)) == 3  # the board, the cube, and the untextured box
    # The plane's stroke scale: 64 texels / its bounding radius (half its diagonal, 0.7071 m).
    assert sim.table.paintable[_paintable(sim, "board")][1] == pytest.approx(64 / np.sqrt(0.5), rel=1e-6)


def test_ink_evaporates_at_world_info_rate(tmp_path: Path):
    Image.new("RGB", (64, 64), (255, 255, 255)).save(tmp_path / "white64.png")
    world = tmp_path / "pen.wbt"
    world.write_text(WORLD.replace("basicTimeStep 16", "basicTimeStep 16 inkEvaporation 2"))
    result, _ = compile_world(world)
    assert result.table.ink_evaporation == 2.0
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    apply_commands(sim, robot, [(tags[name], "write", False) for name in ("short", "untextured")])
    sim.step()  # one full-density red stroke
    apply_commands(sim, robot, [(tags["pen"], "write", False)])
    texture, pixels = _texture(sim, _paintable(sim, "board"))
    assert pixels[32, 32].tolist() == [255, 0, 0]
    for _ in range(10):
        sim.step()
    coverage = float(np.exp(-2.0 * 0.016 * 10))  # 0.726 of the ink is left after 10 steps of 16 ms
    assert sim.canvases[texture].coverage[32, 32] == pytest.approx(coverage, rel=1e-5)
    green = 1.0 - coverage  # white's linear light shows through where the ink has gone
    expected = round(255 * (1.055 * green ** (1 / 2.4) - 0.055))
    assert pixels[32, 32].tolist() == [255, expected, expected]


def test_a_texture_transform_repeats_the_image_in_the_layer_and_strokes_keep_their_size(tmp_path: Path):
    image = np.full((64, 64, 3), 255, dtype=np.uint8)
    image[:32, :32] = (0, 0, 255)  # the image's top-left quarter is blue
    Image.fromarray(image).save(tmp_path / "white64.png")
    world = tmp_path / "pen.wbt"
    world.write_text(WORLD.replace('appearance Appearance { texture ImageTexture { url ["white64.png"] } }\n'
                                   '      geometry Plane',
                                   'appearance Appearance { texture ImageTexture { url ["white64.png"] } '
                                   'textureTransform TextureTransform { scale 4 4 } }\n      geometry Plane'))
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    apply_commands(sim, robot, [(tags[name], "write", False) for name in ("short", "untextured")])
    _, layer = _texture(sim, _paintable(sim, "board"))
    assert layer.shape == (256, 256, 3) and sim.table.paintable[_paintable(sim, "board")][2] == 4.0
    # Four copies of the image a side: blue top-left quarters of each 64-texel tile.
    blue = np.all(layer == (0, 0, 255), axis=2)
    assert blue[0:32, 0:32].all() and blue[64:96, 192:224].all() and not blue[32:64, 0:64].any()
    sim.step()
    # The same stroke as on the untransformed plane (radius 4 of Webots' 64-texel layer), 4 times finer.
    red = np.all(layer == (255, 0, 0), axis=2)
    assert int(red.sum()) == sum(1 for dr in range(-16, 17) for dc in range(-16, 17) if dr * dr + dc * dc <= 256)
