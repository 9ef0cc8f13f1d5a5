"""Joint endPoints without Physics: they pass through other Physics-less Solids and stop at resetPhysics.

Webots gives a Solid without Physics no ODE body, drops contacts between two body-less geoms, and lets
no gravity act on them; `Node.resetPhysics()` zeroes the joints' motors' current velocity
(WbJoint::resetPhysics, WbMotor::resetPhysics), so a wheel slowing down under `acceleration` stops at once.
Their joints' motors move them by Webots' kinematic rule (`wbtc.runtime.kinematic_motors`).
"""

from pathlib import Path

import mujoco
import pytest

from wbtc.compile.bodyless import BODYLESS_CONAFFINITY, BODYLESS_CONTYPE
from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.supervisor import SupervisorHub

# A Robot without Physics whose Hinge2Joint endPoint (without Physics) sweeps, about its second axis
# (+z through the anchor, radius 0.13 m), through the box of a second Robot without Physics at y = 0.15;
# a Solid with Physics rests on the floor beside them.
WORLD = """#VRML_SIM R2025a utf8
WorldInfo { basicTimeStep 32 }
DEF FLOOR Solid {
  children [ Shape { geometry DEF FLOOR_BOX Box { size 4 4 0.02 } } ]
  translation 0 0 -0.2
  boundingObject USE FLOOR_BOX
  name "floor"
}
DEF SPINNER Robot {
  children [
    Shape { geometry DEF BODY Box { size 0.1 0.1 0.1 } }
    Hinge2Joint {
      jointParameters HingeJointParameters { anchor 0.07 0 0 axis 1 0 0 }
      jointParameters2 JointParameters { axis 0 0 1 }
      device [ RotationalMotor { name "wheel1" acceleration 10 maxVelocity 100 } ]
      device2 [ RotationalMotor { name "wheel2" acceleration 10 maxVelocity 100 } ]
      endPoint DEF END Solid {
        translation 0.2 0 0
        children [ Shape { geometry DEF CUBE Box { size 0.05 0.05 0.05 } } ]
        boundingObject USE CUBE
      }
    }
  ]
  boundingObject USE BODY
  supervisor TRUE
}
DEF WALL Robot {
  translation 0 0.15 0
  children [ Shape { geometry DEF WALL_BOX Box { size 0.1 0.1 0.1 } } ]
  boundingObject USE WALL_BOX
  name "wall"
}
DEF CRATE Solid {
  translation 1 1 -0.14
  children [ Shape { geometry DEF CRATE_BOX Box { size 0.1 0.1 0.1 } } ]
  boundingObject USE CRATE_BOX
  physics Physics { }
  name "crate"
}
"""


def _load(tmp_path: Path) -> tuple[Simulation, SupervisorHub]:
    world = tmp_path / "spinner.wbt"
    world.write_text(WORLD, encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    return sim, SupervisorHub(sim, scene, world)


def _colliding(model: mujoco.MjModel, body: int) -> list[int]:
    return [g for g in range(model.ngeom) if model.geom_bodyid[g] == body and model.geom_contype[g]]


def test_body_less_solids_do_not_collide_and_feel_no_gravity(tmp_path: Path) -> None:
    sim, _ = _load(tmp_path)
    model, table = sim.model, sim.table
    end, wall, floor, crate = (model.body(table.bodies[name]).id for name in ("END", "WALL", "FLOOR", "CRATE"))
    # The kinematic endPoint, the static wall and the static floor: body-less; the crate keeps its body.
    for body in (end, wall, floor):
        assert [(model.geom_contype[g], model.geom_conaffinity[g]) for g in _colliding(model, body)] == \
            [(BODYLESS_CONTYPE, BODYLESS_CONAFFINITY)]
    assert [(model.geom_contype[g], model.geom_conaffinity[g]) for g in _colliding(model, crate)] == [(1, 1)]
    assert model.body_gravcomp[end] == 1.0 and model.body_gravcomp[crate] == 0.0
    sim.close()


def test_a_hinge2_end_point_sweeps_through_a_static_robot_and_stops_at_reset_physics(tmp_path: Path) -> None:
    sim, hub = _load(tmp_path)
    model, data = sim.model, sim.data
    spinner = next(r for r in sim.robots if r.entry.name == "SPINNER" or r.entry.node.def_name == "SPINNER")
    motors = {m.entry.name: m for m in spinner.motors.values()}
    second = model.joint(motors["wheel2"].entry.joint)
    end = int(second.bodyid[0])
    wall = model.body(sim.table.bodies["WALL"]).id
    motors["wheel2"].apply("setPosition", (float("inf"),))
    motors["wheel2"].apply("setVelocity", (3.0,))
    for _ in range(40):  # 1.28 s: up to 3 rad/s within 0.3 s, past the wall (about 1.2 to 2.2 rad)
        sim.step()
        touching = {(model.geom_bodyid[c.geom1], model.geom_bodyid[c.geom2]) for c in data.contact[:data.ncon]}
        assert (end, wall) not in touching and (wall, end) not in touching
    # Webots' kinematic control: 3 rad/s reached at 10 rad/s^2 (0.32 rad/s a step) after 10 steps, so
    # 0.032 x (0.32 x (1 + ... + 9) + 3 x 31) = 3.4368 rad after 40 steps.
    assert data.qpos[second.qposadr[0]] - second.qpos0[0] == pytest.approx(3.4368, abs=1e-9)
    motors["wheel2"].apply("setVelocity", (0.0,))  # slowing down at 10 rad/s^2: still 2.68 rad/s a step later
    before = float(data.qpos[second.qposadr[0]])
    sim.step()
    assert motors["wheel2"].kinematic_velocity == pytest.approx(2.68, abs=1e-12)
    assert data.qpos[second.qposadr[0]] - before == pytest.approx(2.68 * 0.032, abs=1e-9)
    node = hub.call(spinner, "getFromDef", ("SPINNER", -1))
    hub.queue(spinner, "node.resetPhysics", (node["id"],))
    hub.flush()
    before = data.qpos.copy()
    for _ in range(5):
        sim.step()
    first = model.joint(motors["wheel1"].entry.joint)
    for joint in (first, second):  # both axes: the motors' velocities were zeroed, and nothing else moves them
        assert data.qpos[joint.qposadr[0]] == pytest.approx(before[joint.qposadr[0]], abs=1e-9)
    sim.close()
