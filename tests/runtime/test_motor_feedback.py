"""Torque feedback as Webots' joint feedback: under torque control only the joint's stops; a motor that cannot
reach its velocity within a step gives its whole torque, as ODE's force-limited motor."""

from pathlib import Path

import pytest

from wbtc.pipeline import compile_world
from wbtc.runtime.commands import apply_commands
from wbtc.runtime.simulation import Simulation

#: One arm on a hinge about z, no gravity: (basicTimeStep, joint parameters, maxTorque, inertia about z).
ARM = """#VRML_SIM R2025a utf8
WorldInfo {{
  basicTimeStep {step}
  gravity 0
}}
Robot {{
  children [
    HingeJoint {{
      jointParameters HingeJointParameters {{
        axis 0 0 1
        {joint}
      }}
      device [
        RotationalMotor {{
          maxVelocity 20
          maxTorque {torque}
        }}
      ]
      endPoint Solid {{
        physics Physics {{
          density -1
          mass 1
          centerOfMass [ 0 0 0 ]
          inertiaMatrix [ {inertia} {inertia} {inertia}, 0 0 0 ]
        }}
      }}
    }}
  ]
  controller "<none>"
}}
"""


def _simulation(folder: Path, **fields: object) -> Simulation:
    world = folder / "arm.wbt"
    world.write_text(ARM.format(**fields))
    result, _ = compile_world(world)
    return Simulation(result, noise=False)


@pytest.fixture
def sim(tmp_path: Path):
    simulation = _simulation(tmp_path, step=16, joint="maxStop 0.2", torque=10, inertia=1)
    yield simulation
    simulation.close()


def _feedback(sim: Simulation, steps: int) -> list[float]:
    motor = sim.robots[0].motors[0]
    values = []
    for _ in range(steps):
        sim.step()
        motor.sample_feedback(sim.data, sim.time_ms)
        values.append(motor.feedback_value)
    return values


def test_under_torque_control_a_free_joint_reads_no_torque_then_its_stop(sim):
    robot = sim.robots[0]
    apply_commands(sim, robot, [(0, "enableTorqueFeedback", 16), (0, "setTorque", 0.5)])
    # 0.5 N m on 1 kg m^2: 0.5 rad/s^2, the stop at 0.2 rad reached after about 0.9 s (56 steps).
    free = _feedback(sim, 40)
    assert max(abs(v) for v in free) == 0.0  # Webots: about 1e-7, the command is not joint feedback
    held = _feedback(sim, 60)[-10:]
    assert sim.data.qpos[0] == pytest.approx(0.2, abs=2e-3)
    # Resting on its stop, the joint holds the motor's torque back: the stop pushes down, -0.5 N m.
    assert [round(v, 3) for v in held] == [-0.5] * 10




@pytest.mark.parametrize(("damping", "first"), [(10.0, 30.0), (0.0, 3.125)])
def test_a_motor_that_cannot_reach_its_velocity_in_a_step_gives_its_whole_torque(tmp_path, damping, first):
    # 20 rad/s within one 32 ms step takes 0.005 x 20 / 0.032 = 3.125 N m on the free arm: ODE's motor gives just
    # that. Against a damping of 10 it would take 200 N m more: ODE's motor gives its maxTorque, 30, the whole step
    # (wbtc's capped servo used to ease off as the arm sped up: 25.5 on average).
    simulation = _simulation(tmp_path, step=32, joint=f"dampingConstant {damping}", torque=30, inertia=0.005)
    try:
        apply_commands(simulation, simulation.robots[0], [(0, "enableTorqueFeedback", 32),
                                                          (0, "setPosition", float("inf")), (0, "setVelocity", 20.0)])
        values = _feedback(simulation, 2)
        assert values[0] == pytest.approx(first, rel=0.02)
        if damping:
            # 30 N m against 10 N m s/rad: the arm runs at 3 rad/s, and the motor keeps giving all it has.
            assert values[1] == pytest.approx(30.0, abs=1e-6)
            assert simulation.data.qvel[0] == pytest.approx(3.0, abs=0.01)
        else:
            assert simulation.data.qvel[0] == pytest.approx(20.0, abs=0.05)
    finally:
        simulation.close()


@pytest.mark.parametrize("velocity", [0.4, 1.6, 6.4])
def test_a_free_servo_within_its_torque_turns_at_its_velocity_from_the_first_step(tmp_path, velocity):
    # 1.6 rad/s on 0.00167 kg m^2 takes 0.17 N m over a 16 ms step, far below maxTorque 10, so ODE's motor turns
    # the joint by exactly v x 16 ms in the first step. wbtc's servo asks gain x 1.6 = 133 N m at the start of
    # the substep, but feels only I x dv / h = 1.33 N m of it (its damping is implicit): its gain is no longer
    # capped at 10 / 1.6, which lagged the joint by v^2 / 2a (0.43 mrad at 1.6 rad/s: api coupled_motor). What is
    # left is the servo's own lag, 1 / (1 + SERVO_GAIN) of the first 2 ms substep: v x 1.98e-5 s.
    simulation = _simulation(tmp_path, step=16, joint="", torque=10, inertia=0.001667)
    try:
        apply_commands(simulation, simulation.robots[0], [(0, "setPosition", float("inf")),
                                                          (0, "setVelocity", velocity)])
        simulation.step()
        assert simulation.data.qpos[0] == pytest.approx(velocity * 0.016, abs=velocity * 3e-5)
        simulation.step()
        assert simulation.data.qpos[0] == pytest.approx(velocity * 0.032, abs=velocity * 3e-5)
    finally:
        simulation.close()


def test_a_servo_capped_by_its_torque_still_gives_no_more_than_it(tmp_path):
    # 20 rad/s on 0.005 kg m^2 within the first 2 ms substep would take 50 N m; maxTorque 1 allows 1 N m: the arm
    # speeds up at 1 / 0.005 = 200 rad/s^2 (ODE's force-limited motor: 3.2 rad/s after the 16 ms step).
    simulation = _simulation(tmp_path, step=16, joint="", torque=1, inertia=0.005)
    try:
        apply_commands(simulation, simulation.robots[0], [(0, "setPosition", float("inf")), (0, "setVelocity", 20.0)])
        simulation.step()
        assert simulation.data.qvel[0] == pytest.approx(3.2, abs=0.01)
    finally:
        simulation.close()
