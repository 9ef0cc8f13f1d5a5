"""Contacts at the pose a step ended in (wbtc.runtime.end_contacts): bumpers, which hold a touch until read,
and a supervisor's getContactPoints."""

from pathlib import Path

import numpy as np
import pytest

from wbtc.runtime.launch import prepare
from wbtc.runtime.sensors import TouchSensor

#: A 0.1 m box whose bottom is 0.12 m above a bumper plate, in a world of 32 ms steps.
_WORLD = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
DEF BOX Solid {
  translation 0 0 0.27
  children [ DEF BOX_SHAPE Shape { geometry Box { size 0.1 0.1 0.1 } } ]
  boundingObject USE BOX_SHAPE
  physics Physics { }
}
Robot {
  supervisor TRUE
  children [
    TouchSensor {
      translation 0 0 0.05
      name "plate"
      boundingObject Box { size 0.5 0.5 0.1 }
      physics Physics { }
    }
  ]
}
"""


def _prepared(tmp_path: Path, physics_step: float):
    world = tmp_path / "bumper.wbt"
    world.write_text(_WORLD)
    return prepare(world, physics_step=physics_step)


def _simulation(tmp_path: Path, physics_step: float):
    sim = _prepared(tmp_path, physics_step).sim
    plate = next(s for r in sim.robots for s in r.sensors.values() if isinstance(s, TouchSensor))
    return sim, plate


def test_a_bumper_reads_the_step_whose_end_pose_touches(tmp_path):
    # Webots' one semi-implicit Euler step of h drops a body g h^2 k (k + 1) / 2 in k steps:
    # 0.1005 m after 4 (0.0195 m above the plate), 0.1507 after 5 (0.0307 m into it). Webots collides
    # after each step, so its bumper reads 1 at the fifth step; colliding at the step's start read it
    # one step late, at the sixth.
    sim, plate = _simulation(tmp_path, physics_step=1000.0)
    plate.enable(32, sim.time_ms)
    readings, drops = [], []
    for _ in range(6):
        sim.step()
        readings.append(plate.value)
        drops.append(0.27 - float(sim.data.qpos[2]))
    g_h2 = 9.81 * 0.032**2
    assert np.allclose(drops[:5], [g_h2 * k * (k + 1) / 2 for k in range(1, 6)], atol=1e-9)
    assert readings == [0.0, 0.0, 0.0, 0.0, 1.0, 1.0]


def test_a_touch_between_samples_is_held_until_the_bumper_is_read(tmp_path):
    # Sampled every third step: the box is put on the plate for one step only (between samples),
    # then far above it. Webots' flag, raised by that step's collisions, is read at the next sample
    # and cleared by it.
    sim, plate = _simulation(tmp_path, physics_step=2.0)
    plate.enable(96, sim.time_ms)
    readings = []
    for step in range(1, 10):
        sim.data.qpos[2] = 0.149 if step == 4 else 5.0  # 1 mm into the plate: resting on it
        sim.data.qvel[:] = 0.0
        sim.step()
        readings.append((step, plate.value if plate.fresh else None))
        plate.fresh = False
    assert readings == [(1, None), (2, None), (3, 0.0), (4, None), (5, None), (6, 1.0),
                        (7, None), (8, None), (9, 0.0)]


def test_a_supervisor_gets_the_contact_points_of_the_end_pose(tmp_path):
    # The same fall: after the fifth step the box is 0.0307 m into the plate. Its contact points are
    # there (MuJoCo's: midway between the box's bottom and the plate's top face, z = 0.1), though the
    # step itself started 0.0195 m above the plate.
    prepared = _prepared(tmp_path, physics_step=1000.0)
    sim, hub = prepared.sim, prepared.hub
    robot = sim.robots[0]
    box = hub.call(robot, "getFromDef", ("BOX", -1))["id"]
    counts = []
    for _ in range(5):
        sim.step()
        counts.append(len(hub.call(robot, "node.getContactPoints", (box, False))))
    assert sim.data.ncon == 0  # the live data's contacts: the step's start pose
    assert counts == [0, 0, 0, 0, 4]
    points = hub.call(robot, "node.getContactPoints", (box, False))
    bottom = 0.27 - 0.05 - 9.81 * 0.032**2 * 15
    assert [p[2] for p, _ in points] == pytest.approx([(bottom + 0.1) / 2] * 4, abs=1e-9)
