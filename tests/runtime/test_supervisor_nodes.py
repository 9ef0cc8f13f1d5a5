"""Supervisor node calls as Webots answers them: no pose for nodes that are not poses, every imported node,
device tags counted from the robot itself."""

import math
from pathlib import Path

from conftest import project_with_controller
from typer.testing import CliRunner

from wbtc.cli import app

WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 32
}
DEF BOX Solid {
  translation 1 0 0.1
  children [
    Shape {
      appearance DEF APP Appearance {
      }
      geometry Box {
        size 0.1 0.1 0.1
      }
    }
  ]
}
DEF GROUP Group {
}
DEF MOVER Solid {
  translation 0 2 0
  children [
    DEF CHILD Solid {
      translation 0 0.5 0
      name "child"
    }
  ]
  name "mover"
}
Robot {
  children [
    GPS {
    }
  ]
  controller "probe"
  supervisor TRUE
}
"""
PROBE = """from controller import Supervisor

s = Supervisor()
s.step(32)
print("box", s.getFromDef("BOX").getPosition())
app = s.getFromDef("APP")
print("appearance", app.getPosition(), len(app.getOrientation()), len(app.getPose()))
print("orientation nan", all(v != v for v in app.getOrientation()), all(v != v for v in app.getPose()))
children = s.getFromDef("GROUP").getField("children")
children.importMFNodeFromString(-1, 'Solid { name "a" } Solid { name "b" }')
children.importMFNodeFromString(0, 'Pose { }')
print("imported", children.getCount(), [children.getMFNode(i).getTypeName() for i in range(children.getCount())])
print("names", [children.getMFNode(i).getField("name").getSFString() for i in (1, 2)])
print("tags", s.getFromDevice(0) == s.getSelf(), s.getFromDevice(1).getTypeName())
s.getFromDef("MOVER").setVelocity([1, 0, 0, 0, 0, 2])
s.step(32)
print("child", [round(v, 6) for v in s.getFromDef("CHILD").getVelocity()])
"""


def test_poses_of_non_pose_nodes_are_nan_and_every_imported_node_is_added(tmp_path: Path):
    world = project_with_controller(tmp_path, "w.wbt", WORLD, "probe", PROBE)
    result = CliRunner().invoke(app, ["run", str(world), "--headless", "--duration", "0.1"])
    assert result.exit_code == 0, result.output
    lines = {line.split("] ", 1)[1].split(" ", 1)[0]: line.split("] ", 1)[1] for line in result.output.splitlines()
             if line.startswith("[robot] ")}
    assert lines["box"] == "box [1.0, 0.0, 0.1]"
    position = lines["appearance"].split("[")[1].split("]")[0].split(", ")
    assert all(math.isnan(float(v)) for v in position) and lines["appearance"].endswith("] 9 16")
    assert lines["orientation"] == "orientation nan True True"
    assert lines["imported"] == "imported 3 ['Pose', 'Solid', 'Solid']"
    assert lines["names"] == "names ['a', 'b']"
    assert lines["tags"] == "tags True GPS"  # Webots' tags: 0 is the robot itself, 1 its first device
    # A child of a Solid a supervisor moves kinematically moves with it: v = v0 + w x r, r = 0.5 m along the
    # mover's y, turned by 2 rad/s x 32 ms: (1 - cos 0.064, -sin 0.064, 0).
    velocity = [float(v) for v in lines["child"][len("child ["):-1].split(", ")]
    assert velocity == [round(1 - math.cos(0.064), 6), round(-math.sin(0.064), 6), 0.0, 0.0, 0.0, 2.0]
