"""RangeFinder: planar depth from the device camera, inf out of range, NaN before the first sample, .hdr files,
semi-transparent shapes seen and the sky not."""

import math
from pathlib import Path

import mujoco
import numpy as np
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world
from wbtc.runtime.range_finder import RangeFinder
from wbtc.runtime.simulation import Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Solid {
  translation 1.5 0 0.5
  children [
    Shape {
      geometry Box {
        size 0.2 0.8 0.4
      }
    }
  ]
}
Robot {
  children [
    RangeFinder {
      translation 0.1 0 0.5
      width 8
      height 6
      maxRange 5
    }
  ]
  controller "probe"
}
"""
PROBE = """from controller import Robot

robot = Robot()
rf = robot.getDevice("range-finder")
rf.enable(16)
print("before", rf.getRangeImage()[0])
robot.step(16)
image = rf.getRangeImageArray()
print("rows", " ".join(",".join("%.4f" % d for d in row) for row in image))
print("saved", rf.saveImage("depth.hdr", 100))
"""


def test_a_range_finder_sees_the_wall_at_its_planar_depth(tmp_path: Path):
    world = project_with_controller(tmp_path, "w.wbt", WORLD, "probe", PROBE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.05"])
    assert result.exit_code == 0, result.output
    out = {line.split()[1]: line.split()[2:] for line in result.output.splitlines() if line.startswith("[robot] ")}
    assert math.isnan(float(out["before"][0]))
    rows = [[float(v) for v in row.split(",")] for row in out["rows"]]
    assert len(rows) == 6 and all(len(row) == 8 for row in rows)
    # The box's face is 1.3 m ahead: 0.8 m wide and 0.4 m high, it fills the middle of the 45° view
    # (±0.54 m across, ±0.40 m up at 1.3 m); planar depth reads 1.3 off the axis too.
    middle = [rows[r][c] for r in (2, 3) for c in (2, 3, 4, 5)]
    assert all(abs(d - 1.3) < 2e-3 for d in middle)
    # Nothing else in the world: above and below the box, and at the corners, nothing is in range.
    assert all(math.isinf(d) for d in (rows[0][0], rows[0][7], rows[5][0], rows[5][7]))
    assert out["saved"] == ["0"]
    data = (tmp_path / "controllers" / "probe" / "depth.hdr").read_bytes()  # controllers run in their folder
    header = b"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 6 +X 8\n"
    assert data.startswith(header) and len(data) == len(header) + 4 * 48
    level, _, _, exponent = data[len(header) + 4 * (3 * 8 + 3):][:4]
    assert abs((level + 0.5) / 256 * 2 ** (exponent - 128) - 1.3) < 0.01


def test_a_cylindrical_range_finder_sees_all_around_along_its_rays(tmp_path: Path):
    # fieldOfView 2π over 16 columns: column j looks at azimuth π − (j + ½)·π/8; columns 7 and 8 look
    # ±π/16 off the axis, at the box's face 1.3 m ahead (0.26 m aside, within its ±0.4 m), and read the
    # distance along the ray, 1.3 / cos(π/16). One row: elevation 0.
    world = WORLD.replace("      width 8\n      height 6\n",
                          '      width 16\n      height 1\n      fieldOfView 6.283185\n'
                          '      projection "cylindrical"\n')
    world = project_with_controller(tmp_path, "w.wbt", world, "probe", PROBE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.05"])
    assert result.exit_code == 0, result.output
    out = {line.split()[1]: line.split()[2:] for line in result.output.splitlines() if line.startswith("[robot] ")}
    (row,) = [[float(v) for v in row.split(",")] for row in out["rows"]]
    assert len(row) == 16
    assert abs(row[7] - 1.3 / math.cos(math.pi / 16)) < 1e-3 and abs(row[8] - row[7]) < 1e-6
    # ±3π/16 (0.87 m aside) misses the box; nothing else is around, behind included.
    assert all(math.isinf(row[c]) for c in range(16) if c not in (7, 8))


SKY_WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
}
Background {
  skyColor [
    0.4 0.7 1
  ]
}
Solid {
  translation 1.5 0 0
  children [
    Shape {
      appearance Appearance {
        material Material {
          transparency 0.5
        }
      }
      geometry Box {
        size 0.1 0.6 0.6
      }
    }
  ]
}
Robot {
  children [
    RangeFinder {
      width 16
      height 16
      fieldOfView 1.5708
      minRange 1
      maxRange 3
    }
  ]
}
"""


def test_a_range_finder_sees_semi_transparent_shapes_and_not_the_sky(tmp_path: Path):
    # Webots' range_finder test reads a transparency 0.5 plane as any other shape and the sky as inf.
    # MuJoCo's renderer writes its skybox sphere (here about 1.5 m out) into the depth buffer and draws
    # blended geoms without depth: both would read wrong without the range finder's own depth pass.
    (tmp_path / "w.wbt").write_text(SKY_WORLD)
    result, _ = compile_world(tmp_path / "w.wbt")
    sim = Simulation(result)
    sensor = next(s for s in sim.robots[0].sensors.values() if isinstance(s, RangeFinder))
    image = np.array(sensor.sample(sim)["ranges"]).reshape(16, 16)
    # The box's near face, 1.45 m ahead, fills the middle (±0.3 m is ±3.3 pixels of 16 at 1.45 m).
    assert np.allclose(image[6:10, 6:10], 1.45, atol=2e-3)
    # Around it only sky: nothing within 3 m.
    assert np.isinf(image[:, :3]).all() and np.isinf(image[:3, :]).all() and np.isinf(image[13:, 13:]).all()
    # The renderer is shared with colour cameras of the same size: the sky and the alpha are back.
    renderer = sim.renderer(16, 16)
    assert renderer.scene.flags[mujoco.mjtRndFlag.mjRND_SKYBOX] == 1
    assert 0 < sim.model.mat_rgba[:, 3].min() < 1
    sim.close()
