"""Display: Webots' drawing rules pixel for pixel, and the drawing on the display's texture (cameras, infra-red)."""

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.display_raster import Raster
from wbtc.runtime.simulation import Simulation


def _lit(raster: Raster) -> list[str]:
    return ["".join("#" if p else "." for p in row) for row in raster.pixels[..., 0] > 0]


def test_a_new_display_is_opaque_black_and_draws_white_by_default():
    raster = Raster(3, 2)
    assert raster.pixels.tolist() == [[[0, 0, 0, 255]] * 3] * 2
    raster.pixel(1, 1)
    raster.pixel(5, 5)  # off the display: nothing
    assert raster.pixels[1, 1].tolist() == [255, 255, 255, 255]
    assert int(raster.pixels[..., 0].astype(bool).sum()) == 1


def test_a_filled_oval_has_webots_row_spans():
    # Webots' display_infrared test: fillOval(5, 10, 4, 8) lights rows 2..18 with half-widths
    # 0, 1, 2, 3, 3, 4, 4, 4, 4, 4, 4, 4, 3, 3, 2, 1, 0 (read back by its expected_data.txt).
    raster = Raster(20, 20)
    raster.color = 0xFFFFFF
    raster.rectangle(0, 0, 20, 20, True)
    raster.color = 0
    raster.rectangle(0, 0, 20, 20, True)
    raster.color = 0xFFFFFF
    raster.oval(5, 10, 4, 8, True)
    lit = raster.pixels[..., 0] > 0
    halves = [int(lit[row].sum()) // 2 if lit[row].any() else None for row in range(20)]
    assert halves == [None, None, 0, 1, 2, 3, 3, 4, 4, 4, 4, 4, 4, 4, 3, 3, 2, 1, 0, None]
    assert all(lit[row, 5] for row in range(2, 19))


def test_an_oval_outline_and_a_line_follow_the_integer_algorithms():
    raster = Raster(9, 7)
    raster.oval(4, 3, 3, 2, False)
    # The walk from (3, 0): (2, 1), (1, 2), (0, 2), mirrored into the four quadrants.
    assert _lit(raster) == [".........", "...###...", "..#...#..", ".#.....#.", "..#...#..", "...###...", "........."]
    line = Raster(6, 3)
    line.line(0, 0, 5, 2)
    assert _lit(line) == ["##....", "..##..", "....##"]


def test_rectangles_polygons_and_clipping():
    raster = Raster(6, 5)
    raster.rectangle(-1, 1, 4, 3, False)  # its left side is off the display
    assert _lit(raster) == ["......", "###...", "..#...", "###...", "......"]
    triangle = Raster(5, 4)
    triangle.polygon([0, 4, 0], [0, 0, 3], True)
    assert _lit(triangle) == ["#####", "###..", "##...", "#...."]


def test_opacity_blends_with_integer_rounding_down_and_alpha_zero_clears():
    raster = Raster(2, 1)
    raster.color, raster.opacity = 0xFF8000, 128
    raster.pixel(0, 0)
    # (255 − 128) · 0 + 128 · 255 = 32640 → // 255 = 128; green 128 · 128 // 255 = 64; alpha stays 255.
    assert raster.pixels[0, 0].tolist() == [128, 64, 0, 255]
    raster.opacity, raster.alpha = 255, 0
    raster.rectangle(0, 0, 2, 1, True)
    assert raster.pixels.tolist() == [[[0, 0, 0, 0], [0, 0, 0, 0]]]


WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Background {
  skyColor [0 0 0]
}
DirectionalLight {
  direction 1 0 0
  intensity 1
  ambientIntensity 1
}
Robot {
  children [
    Display {
      translation 0.5 0 0
      children [
        Shape {
          appearance PBRAppearance {
            baseColor 1 1 1
            roughness 0.5
            metalness 0
            baseColorMap ImageTexture {
            }
          }
          geometry Box {
            size 0.01 0.4 0.4
          }
        }
      ]
      width 8
      height 8
    }
    DistanceSensor {
      name "ir"
      lookupTable [0 0 0, 1 1000 0]
      type "infra-red"
    }
    Camera {
      name "camera"
      fieldOfView 0.5
      width 16
      height 16
    }
  ]
  controller "<none>"
}
"""


@pytest.fixture()
def display_world(tmp_path: Path):
    world = tmp_path / "display.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    return sim, robot, tags


def test_what_a_display_draws_is_seen_by_infra_red_sensors_and_cameras(display_world, tmp_path: Path):
    sim, robot, tags = display_world
    display, ir, camera = tags["display"], tags["ir"], tags["camera"]
    apply_commands(sim, robot, [(ir, "enable", 16), (camera, "enable", 16)])
    sim.step()
    # Before any drawing the texture is the ImageTexture's own (none: white): the sensor sees white at
    # 0.495 m (the box's near face); roughness 0.5 shows infra-red 0.75 of the red: reflection 0.2 + 0.8 · 0.75.
    assert robot.sensors[ir].value == pytest.approx(495.0 / 0.8, abs=0.5)
    apply_commands(sim, robot, [(display, "setColor", 0x000000), (display, "fillRectangle", 0, 0, 8, 8),
                                (display, "setColor", 0x808080), (display, "fillRectangle", 2, 2, 4, 4),
                                (display, "imageSave", None, str(tmp_path / "shot.png"))])
    sim.step()
    # Red 128/255 at the centre: reflection 0.2 + 0.8 · 0.75 · 0.502 = 0.5012, so 495 / 0.5012 = 987.6.
    assert robot.sensors[ir].value == pytest.approx(495.0 / (0.2 + 0.8 * 0.75 * 128 / 255), abs=0.5)
    pixels = robot.sensors[camera].pixels
    centre, corner = pixels[8, 8, 2], pixels[0, 0, 2]  # BGRA: index 2 is red
    # The black border and the grey centre are rendered (black texels still reflect a little of the
    # light, PBR roughness 0.5: 13, which an 8-bit buffer rounded to 0).
    assert (corner, centre) == (13, 80)
    saved = np.asarray(Image.open(tmp_path / "shot.png"))
    assert saved.shape == (8, 8, 4)
    assert saved[0, 0].tolist() == [0, 0, 0, 255]
    assert saved[3, 3].tolist() == [128, 128, 128, 255]


def test_an_image_pasted_from_controller_bytes_keeps_its_channels(display_world):
    sim, robot, tags = display_world
    display = tags["display"]
    bgra = bytes([10, 20, 30, 255] * 4)  # Display.BGRA = 6: blue 10, green 20, red 30
    apply_commands(sim, robot, [(display, "imageNew", 7, bgra, 6, 2, 2), (display, "imagePaste", 7, 1, 1, False),
                                (display, "imageCopy", 8, 0, 0, 3, 3)])
    raster = robot.displays[display].raster
    assert raster.pixels[1, 1].tolist() == [30, 20, 10, 255]
    assert raster.pixels[0, 0].tolist() == [0, 0, 0, 255]
    assert robot.displays[display].images[8].shape == (3, 3, 4)


def test_texture_alpha_undoes_mujocos_double_drawing_of_blended_geoms():
    from wbtc.runtime.display import BLEND_ALPHA, texture_alpha

    stored = texture_alpha(np.array([0, 64, 128, 255], dtype=np.uint8))
    assert stored.tolist() == [0, 34, 75, 255]
    # MuJoCo draws a blended geom twice: a fragment of alpha a covers a(2 − a) of what is behind.
    fragment = BLEND_ALPHA * stored / 255.0
    assert (fragment * (2 - fragment)).tolist() == pytest.approx([0.0, 64 / 255, 128 / 255, 0.99997], abs=0.004)


def test_a_transparent_display_pixel_shows_the_sky_behind_it(tmp_path: Path):
    world = tmp_path / "display.wbt"
    world.write_text(WORLD.replace("skyColor [0 0 0]", "skyColor [1 0 0]"))
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    display, camera = tags["display"], tags["camera"]
    shown = robot.displays[display]
    assert len(shown.materials) == 1 and len(shown.geoms) == 1
    apply_commands(sim, robot, [(camera, "enable", 16), (display, "setColor", 0x00FF00),
                                (display, "fillRectangle", 0, 0, 8, 8)])
    sim.step()
    blue, green, red = robot.sensors[camera].pixels[8, 8, :3].tolist()
    assert red == 0 and green > 100  # the opaque green display hides the red sky
    assert sim.model.mat_rgba[shown.materials[0], 3] == 1.0  # opaque: MuJoCo does not blend it
    apply_commands(sim, robot, [(display, "setAlpha", 0.0), (display, "fillRectangle", 0, 0, 8, 8)])
    sim.step()
    assert robot.sensors[camera].pixels[8, 8, :3].tolist() == [0, 0, 255]  # the sky as its own colour
    assert sim.model.mat_rgba[shown.materials[0], 3] == pytest.approx(0.9949)
    assert sim.model.geom_rgba[shown.geoms[0], 3] == pytest.approx(0.9949)
    apply_commands(sim, robot, [(display, "setAlpha", 1.0), (display, "fillRectangle", 0, 0, 8, 8)])
    sim.step()
    assert robot.sensors[camera].pixels[8, 8, :3].tolist() == [blue, green, red]
    assert sim.model.mat_rgba[shown.materials[0], 3] == 1.0 and sim.model.geom_rgba[shown.geoms[0], 3] == 1.0
