"""wbtc's Kinect: Webots' device names built from `cameraName`, 320 x 190 views, a range reading of a wall."""

import math
from pathlib import Path

import pytest
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/devices/microsoft/protos/Kinect.proto"
WorldInfo {
  basicTimeStep 16
}
Solid {
  translation 1.5127 0 0.55
  children [
    Shape {
      geometry DEF WALL Box {
        size 0.1 6 3
      }
    }
  ]
  boundingObject USE WALL
}
Robot {
  translation 0 0 0.5
  children [
    Kinect {
      KINECT_FIELDS
    }
  ]
  controller "probe"
}
"""
PROBE = """from controller import Robot

robot = Robot()
names = [robot.getDeviceByIndex(i).getName() for i in range(robot.getNumberOfDevices())]
print("names", "|".join(names))
camera = robot.getDevice("kinect color")
depth = robot.getDevice("kinect range")
camera.enable(16)
depth.enable(16)
print("sizes", camera.getWidth(), camera.getHeight(), depth.getWidth(), depth.getHeight())
print("fov", camera.getFov(), depth.getFov(), depth.getMaxRange())
robot.step(16)
image = depth.getRangeImage()
w, h = depth.getWidth(), depth.getHeight()
print("depth", image[(h // 2) * w + w // 2], image[0], image[-1])
"""


def _run(tmp_path: Path, fields: str = "") -> dict[str, list[str]]:
    world = project_with_controller(tmp_path, "kinect.wbt", WORLD.replace("KINECT_FIELDS", fields), "probe", PROBE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.05"])
    assert result.exit_code == 0, result.output
    lines = [line.split(maxsplit=2)[1:] for line in result.output.splitlines() if line.startswith("[robot] ")]
    return {key: rest.split() if key != "names" else rest.split("|") for key, rest in lines}


def test_devices_and_their_fields(tmp_path):
    world = tmp_path / "kinect.wbt"
    world.write_text(WORLD.replace("KINECT_FIELDS", ""), encoding="utf-8")
    result, _ = compile_world(world)
    robot = result.table.robots[0]
    assert [(d.name, d.type) for d in robot.devices] == [
        ("tilt motor", "RotationalMotor"), ("kinect color", "Camera"), ("kinect range", "RangeFinder")]
    color, depth = robot.device("kinect color").fields, robot.device("kinect range").fields
    assert (color["width"], color["height"], color["fieldOfView"]) == (320, 190, 1.0)
    assert (depth["width"], depth["height"], depth["fieldOfView"], depth["maxRange"]) == (320, 190, 1.0, 3.5)
    tilt = robot.device("tilt motor").fields
    assert (tilt["minPosition"], tilt["maxPosition"]) == (-0.47, 0.47)
    model = result.model
    kinect = model.body("robot/Kinect").id
    assert model.body_subtreemass[kinect] == pytest.approx(0.5)  # 0.4 kg foot + 0.1 kg bar


def test_the_range_finder_reads_a_wall_at_a_known_distance(tmp_path):
    # The devices sit 12.7 mm ahead of the hinge, 5 cm above the foot (0.55 m up); the wall's face is at
    # x = 1.4627, so 1.45 m ahead of them, and fills the whole view (the range finder reads planar depth).
    out = _run(tmp_path)
    assert out["names"] == ["tilt motor", "kinect color", "kinect range"]
    assert [int(v) for v in out["sizes"]] == [320, 190, 320, 190]
    assert [float(v) for v in out["fov"]] == pytest.approx([1.0, 1.0, 3.5])
    centre, corner, other = (float(v) for v in out["depth"])
    assert centre == pytest.approx(1.45, abs=2e-3)
    assert corner == pytest.approx(1.45, abs=2e-3) and other == pytest.approx(1.45, abs=2e-3)


def test_names_follow_camera_name_and_max_range_cuts_far_walls(tmp_path):
    fields = 'cameraName "kinect"\n      maxRange 1.2\n      width 64\n      height 48\n      tiltMotorName "neck"'
    out = _run(tmp_path, fields)
    assert out["names"] == ["neck", "kinect color", "kinect range"]
    assert [int(v) for v in out["sizes"]] == [64, 48, 64, 48]
    assert math.isinf(float(out["depth"][0]))  # the wall is beyond 1.2 m: out of range


def test_without_its_foot_the_kinect_is_the_bar_alone(tmp_path):
    world = tmp_path / "kinect.wbt"
    world.write_text(WORLD.replace("KINECT_FIELDS", 'foot FALSE cameraName "eye"'), encoding="utf-8")
    result, _ = compile_world(world)
    robot = result.table.robots[0]
    assert [d.name for d in robot.devices] == ["eye color", "eye range"]
