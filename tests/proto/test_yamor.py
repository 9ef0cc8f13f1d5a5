"""wbtc's Yamor module: Webots' devices and order, its 0.186 kg, the hinge, and docking by its Connectors."""

import math
from pathlib import Path

import numpy as np
import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.simulation import Simulation

# Two pairs of modules in a row, each "front" module's front_connector facing the "back" module's
# rear_connector: 1 cm apart in the near pair (within the 0.05 m distance tolerance), 8 cm in the far one.
# A module's front_connector is 0.067 m ahead of its origin, its rear_connector 0.03 m behind.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo {
  basicTimeStep 8
}
Floor {
  size 4 4
}
Yamor {
  translation 0 0 0.0245
  name "near front"
  controller "<none>"
}
Yamor {
  translation 0.107 0 0.0245
  name "near back"
  controller "<none>"
}
Yamor {
  translation 0 0.5 0.0245
  name "far front"
  controller "<none>"
}
Yamor {
  translation 0.177 0.5 0.0245
  name "far back"
  controller "<none>"
}
"""


@pytest.fixture()
def compiled(tmp_path: Path):
    world = tmp_path / "yamor.wbt"
    world.write_text(WORLD)
    result, _ = compile_world(world)
    return result


def _device(sim: Simulation, robot: str, name: str):
    state = next(r for r in sim.robots if r.entry.name == robot)
    tag = next(t for t, d in enumerate(state.entry.devices) if d.name == name)
    return state.sensors.get(tag) or state.motors[tag]


def _site(sim: Simulation, robot: str, name: str) -> np.ndarray:
    return sim.data.site_xpos[_device(sim, robot, name).site].copy()


def test_devices_in_webots_order_and_the_mass(compiled):
    robot = compiled.table.robots[0]
    assert [(d.name, d.type) for d in robot.devices] == [
        ("rear_connector", "Connector"), ("motor", "RotationalMotor"), ("front_connector", "Connector")]
    model = compiled.model
    assert model.body_subtreemass[model.body(robot.body).id] == pytest.approx(0.17 + 0.016)
    connector = robot.devices[0].fields
    assert (connector["isLocked"], connector["distanceTolerance"], connector["axisTolerance"],
            connector["rotationTolerance"]) == (True, 0.05, 0.5, 0.5)


def test_facing_connectors_close_together_dock_and_far_apart_do_not(compiled):
    sim = Simulation(compiled, noise=False)
    front, back = _device(sim, "near front", "front_connector"), _device(sim, "near back", "rear_connector")
    far_front = _device(sim, "far front", "front_connector")
    assert np.linalg.norm(_site(sim, "near back", "rear_connector") - _site(sim, "near front", "front_connector")) \
        == pytest.approx(0.01, abs=1e-6)
    for _ in range(60):
        sim.step()
    # Written locked and in position: docked at the start, the snap pulls the two faces together.
    assert front.peer is back and back.peer is front
    assert front.sample(sim) == 1
    gap = np.linalg.norm(_site(sim, "near back", "rear_connector") - _site(sim, "near front", "front_connector"))
    assert gap < 1e-3
    # 8 cm apart: no peer present, nothing docked, and they stay apart.
    assert far_front.peer is None and far_front.sample(sim) == 0
    far_gap = np.linalg.norm(_site(sim, "far back", "rear_connector") - _site(sim, "far front", "front_connector"))
    assert far_gap == pytest.approx(0.08, abs=2e-3)
    # Unlocking both sides breaks the connection; locking again while in position docks again.
    front.command("unlock", ())
    back.command("unlock", ())
    assert front.peer is None and back.peer is None
    front.command("lock", ())
    assert front.peer is back


def test_the_hinge_turns_the_head_clockwise_seen_from_above(compiled):
    sim = Simulation(compiled, noise=False)
    motor = _device(sim, "far front", "motor")
    motor.apply("setPosition", (1.0,))
    for _ in range(125):  # 1 s: 1 rad at most 3.9667 rad/s
        sim.step()
    # In the body's frame (the light body turns a little the other way as the head turns).
    state = next(r for r in sim.robots if r.entry.name == "far front")
    rot = sim.data.xmat[state.body].reshape(3, 3)
    hinge = sim.data.xpos[state.body] + rot @ np.array([0.03, 0.0, 0.0])
    head = rot.T @ (_site(sim, "far front", "front_connector") - hinge)
    # The hinge axis is -z: +1 rad turns the front connector (0.037 m from the hinge) towards -y.
    assert head[:2] == pytest.approx([0.037 * math.cos(1.0), -0.037 * math.sin(1.0)], abs=2e-3)
