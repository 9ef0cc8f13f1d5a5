"""wbtc's VelodynePuck: a fixed 16-layer lidar all around (3600 points a layer), 1-100 m, per-version fields."""

import math
from pathlib import Path

import pytest
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/devices/velodyne/protos/VelodynePuck.proto"
WorldInfo {
  basicTimeStep 16
}
Solid {
  translation 2.05 0 0.5
  children [
    Shape {
      geometry DEF WALL Box {
        size 0.1 8 3
      }
    }
  ]
  boundingObject USE WALL
}
Robot {
  translation 0 0 0.5
  children [
    VelodynePuck {
      PUCK_FIELDS
    }
  ]
  controller "probe"
}
"""
PROBE = """from controller import Robot

robot = Robot()
lidar = robot.getDevice("Velodyne Puck")
lidar.enable(16)
print("shape", lidar.getNumberOfLayers(), lidar.getHorizontalResolution())
print("fov", lidar.getFov(), lidar.getVerticalFov(), lidar.getMinRange(), lidar.getMaxRange(), lidar.getFrequency())
robot.step(16)
layers = [lidar.getLayerRangeImage(i) for i in range(lidar.getNumberOfLayers())]
print("centre", *[layer[1800] for layer in layers])
print("aside", layers[7][1800 - 400], layers[7][0])
"""


def test_devices_fields_and_masses_per_version(tmp_path: Path):
    world = tmp_path / "puck.wbt"
    masses = {}
    for version in ("Puck", "Puck LITE", "Puck Hi-Res"):
        world.write_text(WORLD.replace("PUCK_FIELDS", f'version "{version}"'), encoding="utf-8")
        result, _ = compile_world(world)
        entry = result.table.robots[0].device("Velodyne Puck")
        assert entry.type == "Lidar" and entry.fields["model"] == "Velodyne Puck"
        assert entry.fields["numberOfLayers"] == 16 and entry.fields["horizontalResolution"] == 3600
        assert entry.fields["fieldOfView"] == pytest.approx(2 * math.pi, abs=1e-4)
        assert (entry.fields["minRange"], entry.fields["maxRange"], entry.fields["type"]) == (1, 100, "fixed")
        masses[version] = (result.model.body_subtreemass[result.model.body("robot/Velodyne Puck").id],
                           entry.fields["verticalFieldOfView"])
    assert masses == {"Puck": (pytest.approx(0.83), 0.5236), "Puck LITE": (pytest.approx(0.59), 0.5236),
                      "Puck Hi-Res": (pytest.approx(0.83), 0.3491)}
    world.write_text(WORLD.replace("PUCK_FIELDS", "enablePhysics FALSE"), encoding="utf-8")
    result, _ = compile_world(world)
    assert result.model.body_subtreemass[result.model.body("robot").id] == pytest.approx(0.0)


def test_sixteen_layers_read_a_wall_two_metres_ahead(tmp_path: Path):
    world = project_with_controller(tmp_path, "puck.wbt", WORLD.replace("PUCK_FIELDS", ""), "probe", PROBE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--no-noise", "--duration", "0.05"])
    assert result.exit_code == 0, result.output
    out = {line.split()[1]: line.split()[2:] for line in result.output.splitlines() if line.startswith("[robot] ")}
    assert [int(v) for v in out["shape"]] == [16, 3600]
    assert [float(v) for v in out["fov"]] == pytest.approx([6.28318, 0.5236, 1, 100, 5])
    # Column 1800 of 3600 looks half a column (π / 3600) right of +x; layer i looks 15° - i·2° up, from the top.
    step = 2 * math.pi / 3600
    centre = [float(v) for v in out["centre"]]
    for i, reading in enumerate(centre):
        elevation = 0.5236 / 2 - i * 0.5236 / 15
        assert reading == pytest.approx(2 / (math.cos(elevation) * math.cos(step / 2)), rel=1e-4)
    # 400 columns to the left (39.95° off +x), still on the wall; column 0 looks backwards at nothing.
    aside, behind = (float(v) for v in out["aside"])
    assert aside == pytest.approx(2 / (math.cos(math.radians(1)) * math.cos(399.5 * step)), rel=1e-4)
    assert math.isinf(behind)
