"""wbtc's Pi-puck on an e-puck2: Webots' LED names and places, its 10 g, and its board as a collision surface."""

from pathlib import Path

import mujoco
import pytest
from conftest import simulation_of

WORLD = """#VRML_SIM R2025a utf8
EXTERNPROTO "webots://projects/robots/gctronic/e-puck/protos/E-puck.proto"
EXTERNPROTO "webots://projects/robots/gctronic/e-puck/protos/Pi-puck.proto"
WorldInfo {
  basicTimeStep 8
}
Floor {
}
E-puck {
  controller "<none>"
  version "2"
  turretSlot [
    Pi-puck {
    }
  ]
}
DEF CUBE Solid {
  translation 0.01 0 0.1
  children [
    DEF CUBE_BOX Shape {
      geometry Box {
        size 0.01 0.01 0.01
      }
    }
  ]
  boundingObject USE CUBE_BOX
  physics Physics {
    density -1
    mass 0.005
  }
}
"""
LEDS = ["pi-puck led 0", "pi-puck led 1", "pi-puck led 2"]
#: E-puck's turret slot is 9.5 mm behind the centre and 48.6 mm up.
SLOT = (-0.0095, 0.0, 0.0486)


@pytest.fixture
def sim(tmp_path: Path):
    simulation = simulation_of(tmp_path, WORLD, "pi_puck.wbt")
    yield simulation
    simulation.close()


def test_the_three_leds_come_after_the_e_pucks_devices_at_webots_places(sim):
    entry = sim.table.robots[0]
    names = [d.name for d in entry.devices]
    assert names[-3:] == LEDS
    assert "tof" in names and "pi-puck" not in names
    devices = {d.name: d for d in entry.devices}
    assert all(devices[n].type == "LED" and devices[n].fields["gradual"] is True for n in LEDS)
    mujoco.mj_forward(sim.model, sim.data)
    places = [(0.0258, 0.0301), (0.0258, -0.0301), (-0.0245, -0.0057)]
    for name, (x, y) in zip(LEDS, places, strict=True):
        site = devices[name].site
        assert site is not None
        assert list(sim.data.site_xpos[sim.model.site(site).id]) == pytest.approx(
            [SLOT[0] + x, SLOT[1] + y, SLOT[2] + 0.0022], abs=1e-4)


def test_the_board_weighs_ten_grams(sim, tmp_path):
    bare = simulation_of(tmp_path, WORLD.replace("Pi-puck {\n    }", ""), "bare.wbt")
    try:
        with_board = sim.model.body_subtreemass[sim.model.body(sim.table.robots[0].body).id]
        without = bare.model.body_subtreemass[bare.model.body(bare.table.robots[0].body).id]
    finally:
        bare.close()
    assert with_board - without == pytest.approx(0.01)


def test_a_cube_dropped_on_the_robot_rests_on_the_board(sim):
    model, data = sim.model, sim.data
    cube = model.body(sim.table.bodies["CUBE"]).id
    board = model.body("e-puck/pi-puck").id
    for _ in range(150):  # 1.2 s
        sim.step()
    mujoco.mj_forward(model, data)
    (geom,) = [g for g in range(model.ngeom) if model.geom_bodyid[g] == board and model.geom_contype[g]]
    assert list(model.geom_size[geom][:2]) == pytest.approx([0.035, 0.001])  # radius, half height
    # In the board's frame (the e-puck leans a little on its front), the cube's centre is half its 1 cm
    # side above the board's top face, 1 mm above the board's centre.
    local = data.geom_xmat[geom].reshape(3, 3).T @ (data.xpos[cube] - data.geom_xpos[geom])
    assert local[2] == pytest.approx(0.001 + 0.005, abs=2e-4)
    assert data.geom_xpos[geom][2] == pytest.approx(SLOT[2] + 0.001, abs=5e-4)
