"""Pen on a Cylinder: Webots' layer layout (2 x 2 images) and its pick on the round cylinder, not the faces."""

from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from wbtc.compile import primitive_uv
from wbtc.pipeline import compile_world
from wbtc.runtime import pen_uv
from wbtc.runtime.simulation import Simulation
from wbtc.scene import Node, build_scene
from wbtc.vrml import parse_text

WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 16 }
Background { skyColor [0 0 0] }
Solid {
  children [
    Shape {
      appearance Appearance { texture ImageTexture { url ["white256.png"] } }
      geometry Cylinder { radius 0.05 height 0.1 subdivision 12 }
    }
  ]
  name "can"
}
Robot {
  translation -0.15 0.01 0.08
  children [
    Pen { rotation 0 1 0 -0.785398 name "pen" inkColor 1 0 0 inkDensity 1 leadSize 0.001 }
  ]
  controller "<none>"
}
"""


def test_cylinder_layer_has_webots_quarters_and_seam():
    painted = primitive_uv.primitive_mesh(_cylinder(12))
    assert painted is not None and painted.grid == (2, 2)
    # Webots' layer (v from the first row): side u, v in [0, 0.5]; top cap u in [0.5, 1]; bottom v in [0.5, 1].
    # In (s, t) with t upwards: the side top-left, the top cap top-right, the bottom cap bottom-left.
    assert painted.regions == [(0.0, 0.5, 0.5, 1.0), (0.5, 0.5, 1.0, 1.0), (0.0, 0.0, 0.5, 0.5)]
    mesh = painted.mesh
    vertices, uv = np.asarray(mesh.vertices, dtype=float), np.asarray(mesh.texcoords, dtype=float)
    side = np.abs(np.abs(vertices[:, 2]) - 0.05) < 1e-9
    side &= np.hypot(vertices[:, 0], vertices[:, 1]) > 0.049
    side &= uv[:, 1] >= 0.5 - 1e-6  # side rows only (the caps' rims share the positions)
    side &= uv[:, 0] <= 0.5 + 1e-6
    bottom_rim = side & (vertices[:, 2] < 0) & (uv[:, 1] < 0.5 + 1e-6)
    # The seam at +y (s 0 and 0.5 there), a quarter turn on at -x (s 0.125), half a turn at -y (0.25).
    for point, expected in (((0.0, 0.05), {0.0, 0.5}), ((-0.05, 0.0), {0.125}), ((0.0, -0.05), {0.25}),
                            ((0.05, 0.0), {0.375})):
        here = bottom_rim & (np.hypot(vertices[:, 0] - point[0], vertices[:, 1] - point[1]) < 1e-6)
        assert {round(float(s), 6) for s in uv[here, 0]} == expected


def _cylinder(sides: int) -> Node:
    text = f"#VRML_SIM R2023b utf8\nShape {{ geometry Cylinder {{ radius 0.05 height 0.1 subdivision {sides} }} }}\n"
    scene = build_scene(parse_text(text, "can.wbt"))
    return next(node for node in scene.walk() if node.base_type == "Cylinder")


def test_cylinder_point_is_webots_pick_on_the_round_shape():
    # The ray of Webots' pen_cylinder test's first stroke, in the cylinder's frame: it meets the round
    # side at (-0.0332, -0.0374, 0.0113); the 12-sided faces inside it would put it 9 texels lower.
    origin = np.array([-0.00656847, -0.12123757, 0.10001154])
    direction = np.array([-0.21291891, 0.67111476, -0.71012008])
    u, v = pen_uv.cylinder_point(origin, direction, 0.05, 0.05)
    assert (u, v) == pytest.approx((0.1922998, 0.1933757), abs=1e-6)
    # From -x, level, 2.5 cm up: a quarter turn from the seam, a quarter of the way down.
    assert pen_uv.cylinder_point(np.array([-1.0, 0.0, 0.025]), np.array([1.0, 0.0, 0.0]), 0.05, 0.05) == \
        pytest.approx((0.125, 0.125))
    # The caps: straight down on the top at (0.02, 0.01), straight up on the bottom.
    assert pen_uv.cylinder_point(np.array([0.02, 0.01, 1.0]), np.array([0.0, 0.0, -1.0]), 0.05, 0.05) == \
        pytest.approx((0.85, 0.2))
    assert pen_uv.cylinder_point(np.array([0.02, 0.01, -1.0]), np.array([0.0, 0.0, 1.0]), 0.05, 0.05) == \
        pytest.approx((0.35, 0.8))
    assert pen_uv.cylinder_point(np.array([1.0, 1.0, 1.0]), np.array([1.0, 0.0, 0.0]), 0.05, 0.05) is None


def test_a_slanted_pen_inks_the_cylinder_where_webots_does(tmp_path: Path):
    Image.new("RGB", (256, 256), (255, 255, 255)).save(tmp_path / "white256.png")
    world = tmp_path / "can.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    name = next(iter(sim.table.paintable))
    model = sim.model
    texture = model.texture(sim.table.paintable[name][0]).id
    width, height = int(model.tex_width[texture]), int(model.tex_height[texture])
    assert (width, height) == (512, 512)
    adr = int(model.tex_adr[texture])
    pixels = model.tex_data[adr:adr + width * height * 3].reshape(height, width, 3)
    sim.step()
    rows, cols = np.nonzero(np.all(pixels == (255, 0, 0), axis=2))
    # 45 degrees down from (-0.15, 0.01, 0.08): the round side at (-0.04899, 0.01, -0.02101), u = 0.10897,
    # v = 0.35505: texel (181, 55) of the 512-texel layer, a disc of radius 1 (leadSize 0.001 x 256 / 0.0707
    # = 3 texels across). The 12-sided faces would have put it 4 texels lower (row 185).
    assert len(rows) == 5
    assert (int(np.median(rows)), int(np.median(cols))) == (181, 55)
    assert sim.table.paintable[name][3] == "Cylinder"
