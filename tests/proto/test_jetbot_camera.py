"""wbtc's JetBotRaspberryPiCamera: a 1280 x 720, 160-degree Camera "camera" looking along +x."""

from pathlib import Path

import pytest
from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app
from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/nvidia/jetbot/protos/JetBotRaspberryPiCamera.proto"
WorldInfo {
  basicTimeStep 16
}
Background {
  skyColor [ 0 0 1 ]
}
Solid {
  translation WALL_X 0 0.5
  children [
    Shape {
      appearance PBRAppearance {
        baseColor 1 0 0
        roughness 1
        metalness 0
        emissiveColor 1 0 0
      }
      geometry Box {
        size 0.1 20 20
      }
    }
  ]
}
Robot {
  translation 0 0 0.5
  children [
    JetBotRaspberryPiCamera {
      CAMERA_FIELDS
    }
  ]
  controller "probe"
}
"""
PROBE = """from controller import Robot

robot = Robot()
camera = robot.getDevice("camera")
camera.enable(16)
print("camera", camera.getWidth(), camera.getHeight(), camera.getFov(), camera.getNear())
robot.step(16)
image = camera.getImage()
w, h = camera.getWidth(), camera.getHeight()
x, y = w // 2, h // 2
print("centre", camera.imageGetRed(image, w, x, y), camera.imageGetGreen(image, w, x, y),
      camera.imageGetBlue(image, w, x, y))
"""


def _run(tmp_path: Path, wall_x: float, fields: str) -> dict[str, list[str]]:
    text = WORLD.replace("WALL_X", str(wall_x)).replace("CAMERA_FIELDS", fields)
    world = project_with_controller(tmp_path, "jetbot_camera.wbt", text, "probe", PROBE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--no-noise", "--duration", "0.05"])
    assert result.exit_code == 0, result.output
    return {line.split()[1]: line.split()[2:] for line in result.output.splitlines() if line.startswith("[robot] ")}


def test_the_camera_device_and_its_fields(tmp_path):
    world = tmp_path / "jetbot_camera.wbt"
    world.write_text(WORLD.replace("WALL_X", "0.5").replace("CAMERA_FIELDS", ""), encoding="utf-8")
    result, _ = compile_world(world)
    (entry,) = result.table.robots[0].devices
    assert (entry.name, entry.type) == ("camera", "Camera")
    fields = entry.fields
    assert (fields["width"], fields["height"]) == (1280, 720)
    assert (fields["fieldOfView"], fields["near"], fields["far"]) == (2.79253, 0.01, 1.0)


def test_it_looks_forwards_at_the_wall_and_not_backwards(tmp_path):
    near = _run(tmp_path / "near", 0.5, "width 64\n      height 36")
    assert [float(v) for v in near["camera"]] == pytest.approx([64, 36, 2.79253, 0.01])
    red, green, blue = (int(v) for v in near["centre"])
    assert red > 200 and green < 50 and blue < 50
    # Turned round, the camera sees the blue sky.
    fields = "rotation 0 0 1 3.14159\n      width 64\n      height 36"
    red, green, blue = (int(v) for v in _run(tmp_path / "back", 0.5, fields)["centre"])
    assert blue > 200 and red < 50


def test_name_and_resolution_follow_the_fields(tmp_path):
    world = tmp_path / "jetbot_camera.wbt"
    text = WORLD.replace("WALL_X", "0.5").replace("CAMERA_FIELDS", 'name "front camera" width 320 height 240')
    world.write_text(text, encoding="utf-8")
    result, _ = compile_world(world)
    (entry,) = result.table.robots[0].devices
    assert (entry.name, entry.fields["width"], entry.fields["height"]) == ("front camera", 320, 240)
