"""Free bodies integrated at their centre of mass under `--ode-contacts` (wbtc.runtime.com_integration)."""

from __future__ import annotations

import math
from pathlib import Path

import mujoco
import numpy as np
import pytest

from wbtc.runtime.com_integration import ComIntegration
from wbtc.runtime.launch import prepare

_BODY = """<mujoco><option gravity="0 0 -9.81" timestep="0.032"/><worldbody>
<body pos="0 0 1" quat="0.9 0.3 0.2 0.1"><freejoint/>
<inertial pos="0.01 0.02 -0.03" mass="0.5" diaginertia="8e-5 9e-5 7e-5"/></body></worldbody></mujoco>"""


def _split(com: ComIntegration):
    """A substep as wbtc.runtime.substeps runs it under `--ode-contacts`, with only this rule."""
    def step(model: mujoco.MjModel, data: mujoco.MjData) -> None:
        mujoco.mj_step1(model, data)
        com.hook(model, data)
        mujoco.mj_step2(model, data)
    return com.wrap(step)


def _spinning_body() -> tuple[mujoco.MjModel, mujoco.MjData, np.ndarray]:
    """A free body whose centre of mass, 3.7 cm off its origin, moves at (0.1, 0.2, 0.3) m/s, spinning."""
    model = mujoco.MjModel.from_xml_string(_BODY)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    spin = np.array([16.0, 3.0, -2.0])  # body frame, as a free joint's
    arm = data.xipos[1] - data.xpos[1]
    data.qvel[3:] = spin
    data.qvel[:3] = np.array([0.1, 0.2, 0.3]) - np.cross(data.xmat[1].reshape(3, 3) @ spin, arm)
    mujoco.mj_forward(model, data)
    return model, data, data.xipos[1].copy()


def test_the_centre_of_mass_follows_odes_euler_steps():
    model, data, start = _spinning_body()
    step = _split(ComIntegration(model))
    for _ in range(10):
        step(model, data)
    mujoco.mj_forward(model, data)
    # ODE's semi-implicit Euler: x_k = x_0 + v_0 k h - g h^2 k (k + 1) / 2, whatever the spin.
    h = 0.032
    expected = start + np.array([0.1, 0.2, 0.3]) * 10 * h + np.array([0, 0, -9.81]) * h * h * 10 * 11 / 2
    assert data.xipos[1].tolist() == pytest.approx(expected.tolist(), abs=1e-12)
    velocity = np.zeros(6)
    mujoco.mj_objectVelocity(model, data, mujoco.mjtObj.mjOBJ_BODY, 1, velocity, 0)
    assert velocity[3:].tolist() == pytest.approx([0.1, 0.2, 0.3 - 9.81 * 10 * h], abs=1e-12)


def test_a_body_turns_as_odes_step_turns_it():
    # ODE (dxStepBody, no finite rotation mode) turns a body by q + h/2 (0, w) q, normalised: by
    # 2 atan(|w| h / 2) per step, 0.51622 rad for 16.5 rad/s at 32 ms, where MuJoCo turns it by |w| h (0.528).
    model = mujoco.MjModel.from_xml_string(_BODY.replace('gravity="0 0 -9.81"', 'gravity="0 0 0"'))
    data = mujoco.MjData(model)
    data.qpos[3:] = (1.0, 0.0, 0.0, 0.0)
    data.qvel[3:] = (0.0, 0.0, 16.5)
    mujoco.mj_forward(model, data)
    step = _split(ComIntegration(model))
    step(model, data)
    angle = 2 * math.atan2(float(data.qpos[6]), float(data.qpos[3]))
    assert angle == pytest.approx(2 * math.atan(16.5 * 0.032 / 2), abs=1e-12)
    assert angle == pytest.approx(0.51622, abs=1e-5)


def test_mujoco_alone_moves_a_spinning_centre_of_mass():
    # What the module corrects: MuJoCo's straight step of the origin moves the centre of mass.
    model, data, start = _spinning_body()
    mujoco.mj_step(model, data)
    mujoco.mj_forward(model, data)
    h = 0.032
    ode = start + np.array([0.1, 0.2, 0.3]) * h + np.array([0, 0, -9.81]) * h * h
    assert np.linalg.norm(data.xipos[1] - ode) > 0.004


def test_a_model_without_free_bodies_has_nothing_to_integrate():
    assert ComIntegration(mujoco.MjModel.from_xml_string(_BODY))
    model = mujoco.MjModel.from_xml_string(_BODY.replace("<freejoint/>", '<joint type="hinge"/>'))
    assert not ComIntegration(model)


_ROBOT = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
Solid { boundingObject Plane { size 10 10 } }
DEF ROBOT Robot {
  translation 0 0 0.0549
  children [
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 1 0 anchor 0 0 -0.03 }
      device [ RotationalMotor { name "left" maxVelocity 20 } ]
      endPoint Solid {
        translation 0 0.045 -0.03
        rotation 1 0 0 1.5708
        children [ DEF WHEEL Shape { geometry Cylinder { height 0.03 radius 0.025 } } ]
        boundingObject USE WHEEL
        physics Physics { density -1 mass 0.05 }
      }
    }
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 1 0 anchor 0 0 -0.03 }
      device [ RotationalMotor { name "right" maxVelocity 20 } ]
      endPoint Solid {
        translation 0 -0.045 -0.03
        rotation 1 0 0 1.5708
        children [ USE WHEEL ]
        name "right wheel"
        boundingObject USE WHEEL
        physics Physics { density -1 mass 0.05 }
      }
    }
  ]
  boundingObject Pose { translation 0 0 -0.03 children [ Sphere { radius 0.02 } ] }
  physics Physics { density -1 mass 0.5 }
  controller "<none>"
}
"""


def _axle_heights(tmp_path: Path, com: bool) -> list[float]:
    """The axle's height (mm) after each of 4 steps of 32 ms once both wheels are asked for 20 rad/s.

    The body, a sphere centred on the axle with the robot's origin 3 cm above it, has no support but
    the wheels: their motors spin it about the axle (Webots' dynamic_light_sensor_rays robot).
    """
    world = tmp_path / "spin.wbt"
    world.write_text(_ROBOT)
    sim = prepare(world, physics_step=1000.0, ode_contacts=True).sim
    robot = next(r for r in sim.robots if r.motors)
    body = mujoco.mj_name2id(sim.model, mujoco.mjtObj.mjOBJ_BODY, "ROBOT")
    sim.step()  # makes the model's substep rules (wbtc.runtime.substeps)
    if not com:
        sim.per_model = sim.per_model[:5] + (None,)  # the same rules without this one
    for _ in range(4):  # settle on the wheels
        sim.step()
    for motor in robot.motors.values():
        motor.apply("setPosition", (float("inf"),))
        motor.apply("setVelocity", (20.0,))
    heights = []
    for _ in range(4):
        sim.step()
        mujoco.mj_forward(sim.model, sim.data)
        heights.append(float(sim.data.xipos[body][2]) * 1000)
    return heights


def test_a_body_spun_on_its_wheels_stays_on_them(tmp_path):
    heights = _axle_heights(tmp_path, com=True)
    # The axle rests 0.2 mm deep in the floor (25 mm wheels, ODE's soft contact) and stays there.
    assert heights == pytest.approx([24.8] * 4, abs=0.05)


def test_without_it_the_spun_body_hops(tmp_path):
    heights = _axle_heights(tmp_path, com=False)
    assert max(heights) > 27.5
