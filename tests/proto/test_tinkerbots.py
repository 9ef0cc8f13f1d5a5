"""wbtc's TinkerbotsBase: a 4 cm Robot block whose slots take modules, LEGO parts and extensions."""

import mujoco
import pytest

from wbtc.pipeline import compile_world

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/kinematics/tinkerbots/protos/TinkerbotsBase.proto"
WorldInfo { basicTimeStep 16 }
DEF BASE TinkerbotsBase {
  translation 0 0 0.0205
  name "block"
  controller "<none>"
  upSlot Solid { translation 0 0 0.005 name "lid" children [ Shape { geometry Box { size 0.04 0.04 0.01 } } ] }
  leftBSlot Solid { name "lego" }
  extensionSlot [ Emitter { name "emitter" channel 5 } Receiver { channel 2 } ]
}
"""


def test_slots_and_extensions_of_the_base_block(tmp_path):
    world = tmp_path / "tinkerbots.wbt"
    world.write_text(WORLD, encoding="utf-8")
    result, _ = compile_world(world)
    robot = result.table.robots[0]
    assert (robot.name, robot.model) == ("block", "Tinkerbots")
    assert [(d.name, d.type) for d in robot.devices] == [("emitter", "Emitter"), ("receiver", "Receiver")]
    model, data = result.model, mujoco.MjData(result.model)
    mujoco.mj_forward(model, data)
    block = model.body("BASE").id
    assert model.body_mass[block] == pytest.approx(0.065)
    # The up slot sits on the top face, 2 cm above the centre; the lid 5 mm above that.
    assert data.xpos[model.body("block/lid").id] == pytest.approx([0, 0, 0.0205 + 0.025], abs=1e-9)
    # Left face, lego cross B: 1 cm forward, 1.5 cm to the right (left is -y here), 1 cm down.
    assert data.xpos[model.body("block/lego").id] == pytest.approx([0.01, -0.015, 0.0205 - 0.01], abs=1e-9)
    # With Physics at the top of the world, the block is free (one free joint).
    assert model.body_jntnum[block] == 1
