"""Node.setVisibility: a shape hidden from one camera is drawn by the others, and hiding survives a rebuild."""

from pathlib import Path

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime import visibility
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import RobotState, Simulation

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 16
}
Background {
  skyColor [0 0 1]
}
DirectionalLight {
  direction 0 0 -1
}
DEF RED Shape {
  appearance Appearance {
    material Material {
      diffuseColor 1 0 0
    }
  }
  geometry Box {
    size 1 1 0.1
  }
}
Robot {
  translation 0 0 1
  rotation 0 1 0 1.5708
  children [
    DEF CAM0 Camera {
      name "camera0"
      width 8
      height 8
    }
    DEF CAM1 Camera {
      name "camera1"
      width 8
      height 8
    }
  ]
  controller "<none>"
}
"""


def _centre(robot: RobotState, tag: int) -> list[int]:
    return robot.sensors[tag].pixels[4, 4, 2::-1].tolist()  # BGRA to RGB


def test_a_shape_hidden_from_one_camera_is_still_seen_by_the_other(tmp_path: Path):
    world = tmp_path / "visibility.wbt"
    world.write_text(WORLD)
    scene, _ = load_world(world)
    result = compile_scene(scene)
    sim = Simulation(result, noise=False)
    robot = sim.robots[0]
    tags = {entry.name: tag for tag, entry in enumerate(robot.entry.devices)}
    red = next(n for n in scene.nodes if n.def_name == "RED")
    cam0 = next(n for n in robot.entry.node.child_nodes() if n.def_name == "CAM0")
    apply_commands(sim, robot, [(tags["camera0"], "enable", 16), (tags["camera1"], "enable", 16)])
    sim.step()
    assert _centre(robot, tags["camera0"]) == _centre(robot, tags["camera1"])
    assert _centre(robot, tags["camera0"])[0] > 200  # the red box
    visibility.set_visibility(sim, red, cam0, False)
    sim.step()
    assert _centre(robot, tags["camera0"]) == [0, 0, 255]  # the sky behind it
    assert _centre(robot, tags["camera1"])[0] > 200
    visibility.set_visibility(sim, red, cam0, True)
    sim.step()
    assert _centre(robot, tags["camera0"])[0] > 200
