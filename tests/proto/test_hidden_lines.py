"""A PROTO instance's `hidden` lines put its inner Solids and joints where the world was saved."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.proto.hidden import joints_of, solids_of
from wbtc.runtime.simulation import Simulation
from wbtc.scene.build import build_scene
from wbtc.vrml.parser import parse_text

PROTO = """#VRML_SIM R2025a utf8
PROTO TwoWheels [
  field SFVec3f translation 0 0 0
]
{
  Robot {
    translation IS translation
    children [
      HingeJoint {
        jointParameters HingeJointParameters {
          axis 0 1 0
        }
        endPoint Solid {
          translation 0.1 0 0
          children [
            Shape {
              geometry Box {
                size 0.02 0.02 0.02
              }
            }
          ]
          name "left"
        }
      }
      HingeJoint {
        jointParameters HingeJointParameters {
          axis 0 1 0
        }
        endPoint Solid {
          translation -0.1 0 0
          name "right"
        }
      }
    ]
    controller "<none>"
  }
}
"""

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "TwoWheels.proto"
WorldInfo {
  gravity 0
}
DEF BOT TwoWheels {
  hidden position_0_1 0.25
  hidden translation_1 0.1 0 0.05
  hidden rotation_2 0 0 1 0.5
  hidden translation_0 5 5 5
  translation 0 0 1
}
"""


def test_hidden_joint_positions_and_inner_poses_are_applied(tmp_path: Path):
    (tmp_path / "TwoWheels.proto").write_text(PROTO)
    world = tmp_path / "hidden.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    sim = Simulation(result, noise=False)
    model, data = result.model, sim.data
    robot = model.body(result.table.bodies["BOT"]).id
    # translation_0 is exposed by the PROTO (translation IS translation): the interface value counts.
    assert data.xpos[robot] == pytest.approx([0.0, 0.0, 1.0])
    joints = [j for j in range(model.njnt) if model.body_rootid[model.jnt_bodyid[j]] == robot]
    assert [float(data.qpos[model.jnt_qposadr[j]]) for j in joints] == pytest.approx([0.0, 0.25])
    left = next(b for b in range(model.nbody) if model.body(b).name.endswith("left"))
    assert data.xpos[left] == pytest.approx([0.1, 0.0, 1.05])


def test_joints_inside_grouping_nodes_and_solids_behind_slots_are_counted() -> None:
    # Webots counts a Solid's joints through Pose/Transform/Group children (never inside another Solid),
    # and its Solids through Slot end points, as Car's wheels are.
    text = """#VRML_SIM R2025a utf8
Robot {
  children [
    Pose { children [ DEF A HingeJoint { endPoint Slot { endPoint Solid { name "w" } } } ] }
    Solid { name "inner" children [ DEF B SliderJoint { } ] }
    DEF C HingeJoint { }
  ]
}
"""
    robot = build_scene(parse_text(text, "t.wbt")).nodes[0]
    assert [j.def_name for j in joints_of(robot)] == ["A", "C"]
    assert [str(s.get("name")) for s in solids_of(robot)] == ["robot", "w", "inner"]
