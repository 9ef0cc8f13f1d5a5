"""Node.setJointPosition on a BallJoint without devices (one MuJoCo ball joint): Webots' three positions.

Webots turns the endPoint by q(axis, θ1)·q(axis2, θ2)·q(axis3, θ3) about the anchor, axis2 = axis3 × axis
(WbBallJoint::computeEndPointSolidPositionFromParameters); setJointPosition(p, i) sets θi and keeps the others.
A BallJoint with devices is three MuJoCo hinges, one per position, so both forms must put the endPoint at the
same place.
"""

from pathlib import Path

import numpy as np
import pytest

from wbtc.compile.compiler import compile_scene
from wbtc.pipeline import load_world
from wbtc.runtime.simulation import Simulation
from wbtc.runtime.supervisor import SupervisorHub

ARM = """Solid {{
          translation 0.1 0.05 0.3
          children [ Shape {{ geometry DEF B{n} Box {{ size 0.05 0.05 0.05 }} }} ]
          boundingObject USE B{n}
          physics Physics {{ }}
          name "end {n}"
        }}"""

# Two BallJoints with the same axes (axis and axis3 not perpendicular), in the same turned frame 1 m apart:
# PLAIN without devices (one ball joint), SENSED with a PositionSensor per axis (three hinges).
WORLD = f"""#VRML_SIM R2025a utf8
WorldInfo {{ basicTimeStep 32 }}
DEF HOLDER Robot {{
  rotation 0 0 1 0.4
  children [
    Pose {{
      rotation 1 0 0 0.3
      children [
        DEF PLAIN BallJoint {{
          jointParameters BallJointParameters {{ anchor 0 0 0.1 }}
          jointParameters2 JointParameters {{ axis 0 1 0.2 minStop -1 maxStop 1 }}
          jointParameters3 JointParameters {{ axis 1 1 1 }}
          endPoint {ARM.format(n=1)}
        }}
      ]
    }}
    Pose {{
      translation 1 0 0
      rotation 1 0 0 0.3
      children [
        DEF SENSED BallJoint {{
          jointParameters BallJointParameters {{ anchor 0 0 0.1 }}
          jointParameters2 JointParameters {{ axis 0 1 0.2 minStop -1 maxStop 1 }}
          jointParameters3 JointParameters {{ axis 1 1 1 }}
          device [ PositionSensor {{ name "s1" }} ]
          device2 [ PositionSensor {{ name "s2" }} ]
          device3 [ PositionSensor {{ name "s3" }} ]
          endPoint {ARM.format(n=2)}
        }}
      ]
    }}
    Pose {{
      translation 0 2 0
      children [
        DEF DEFAULT_AXES BallJoint {{
          endPoint {ARM.format(n=3)}
        }}
      ]
    }}
    Pose {{
      translation 0 -2 0
      children [
        DEF STARTED BallJoint {{
          jointParameters2 JointParameters {{ axis 1 0 0 }}
          jointParameters3 JointParameters {{ axis 0 0 1 position 0.5 }}
          endPoint {ARM.format(n=4)}
        }}
      ]
    }}
  ]
  name "holder"
  supervisor TRUE
}}
"""


@pytest.fixture
def arms(tmp_path: Path):
    world = tmp_path / "balls.wbt"
    world.write_text(WORLD, encoding="utf-8")
    scene, _ = load_world(world)
    sim = Simulation(compile_scene(scene), noise=False)
    hub, holder = SupervisorHub(sim, scene, world), sim.robots[0]
    yield sim, hub, holder
    sim.close()


def _set(hub: SupervisorHub, holder, joint: str, position: float, index: int) -> None:
    node = hub.call(holder, "getFromDef", (joint, -1))
    hub.queue(holder, "node.setJointPosition", (node["id"], position, index))
    hub.flush()


def _end(sim: Simulation, n: int) -> int:
    return sim.model.body(f"holder/end {n}").id


def test_a_ball_joint_without_devices_turns_as_its_three_hinges_do(arms) -> None:
    sim, hub, holder = arms
    data = sim.data
    shift = sim.data.xpos[_end(sim, 2)] - sim.data.xpos[_end(sim, 1)]  # the frames lie 1 m apart
    for index, position in ((3, 0.6), (1, -0.4), (2, 0.3), (3, -1.2)):
        for joint in ("PLAIN", "SENSED"):
            _set(hub, holder, joint, position, index)
        plain, sensed = _end(sim, 1), _end(sim, 2)
        assert data.xpos[sensed] - data.xpos[plain] == pytest.approx(shift, abs=1e-9)
        q1, q2 = data.xquat[plain], data.xquat[sensed]
        assert min(np.abs(q1 - q2).max(), np.abs(q1 + q2).max()) < 1e-9
    # The other two positions were kept: the sensed joint's hinges hold exactly what was set.
    sensed_hinges = [sim.model.joint(j).qposadr[0] for j in range(sim.model.njnt)
                     if sim.model.jnt_bodyid[j] == _end(sim, 2)]
    assert data.qpos[sensed_hinges] == pytest.approx([-0.4, 0.3, -1.2], abs=1e-12)
    ball = sim.model.body_jntadr[_end(sim, 1)]
    assert data.qvel[sim.model.jnt_dofadr[ball]:sim.model.jnt_dofadr[ball] + 3] == pytest.approx([0.0] * 3)


def test_default_axes_are_x_and_z(arms) -> None:
    # No jointParameters2/3: Webots' axis is x and axis3 z; index 3 turns the arm about the robot's z.
    sim, hub, holder = arms
    end = _end(sim, 3)
    anchor = sim.data.xpos[sim.model.body_parentid[end]] + _turn_z(0.4) @ np.array([0.0, 2.0, 0.0])
    before = sim.data.xpos[end] - anchor
    _set(hub, holder, "DEFAULT_AXES", 0.6, 3)
    assert sim.data.xpos[end] - anchor == pytest.approx(_turn_z(0.6) @ before, abs=1e-9)


def test_positions_start_from_the_world_file(arms) -> None:
    # θ3 starts at 0.5: setting it to 0.5 moves nothing, and θ1 = 0.3 then turns the arm about x only,
    # q(x, 0.3)·q(z, 0.5) after q(z, 0.5) as written.
    sim, hub, holder = arms
    end = _end(sim, 4)
    anchor = sim.data.xpos[sim.model.body_parentid[end]] + _turn_z(0.4) @ np.array([0.0, -2.0, 0.0])
    before = sim.data.xpos[end] - anchor
    _set(hub, holder, "STARTED", 0.5, 3)
    assert sim.data.xpos[end] - anchor == pytest.approx(before, abs=1e-12)
    _set(hub, holder, "STARTED", 0.3, 1)
    turn_x = np.array([[1.0, 0.0, 0.0], [0.0, np.cos(0.3), -np.sin(0.3)], [0.0, np.sin(0.3), np.cos(0.3)]])
    frame = _turn_z(0.4)  # the robot's rotation: the joint's axes are in its frame
    assert sim.data.xpos[end] - anchor == pytest.approx(frame @ turn_x @ frame.T @ before, abs=1e-9)


def test_positions_beyond_the_hard_limits_are_clamped_with_webots_warning(arms, capsys) -> None:
    sim, hub, holder = arms
    _set(hub, holder, "PLAIN", 1.5, 2)
    _set(hub, holder, "SENSED", 1.0, 2)
    q1, q2 = sim.data.xquat[_end(sim, 1)], sim.data.xquat[_end(sim, 2)]
    assert min(np.abs(q1 - q2).max(), np.abs(q1 + q2).max()) < 1e-9
    assert capsys.readouterr().err.splitlines() == [
        "[holder] Warning: wb_supervisor_node_set_joint_position() called with a 'position' argument 1.5 outside "
        "hard limits of the joint. Applied position is 1.",
    ]


def _turn_z(angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
