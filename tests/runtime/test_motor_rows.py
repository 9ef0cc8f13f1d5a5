"""ODE's motor rows under `--ode-contacts` (wbtc.runtime.motor_rows).

Webots drives a joint through ODE's joint motor: a constraint row asking for the motor's velocity by
the end of the step, its force bounded by the available torque, solved with everything else. Checked
here: a motor holds its load where it is (wbtc's default servo gives way a little); a motor on a damped
joint gives its whole torque against the damping, and reaches its velocity when its torque allows
(the damping is ODE's implicit row, solved with the motor's in wbtc.runtime.ode_solve, not MuJoCo's
damping integrated after the solve); a chain of light links, no contacts, keeps the velocities asked
for (MuJoCo's Newton solver alone leaves such hard rows far from settled: ode_solve solves their
islands).
"""

from pathlib import Path

import pytest

from wbtc.runtime.launch import prepare

_ARM = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
Robot {
  children [
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 1 0 dampingConstant %(damping)s }
      device [ RotationalMotor { name "shoulder" maxTorque 10 maxVelocity 20 } ]
      endPoint Solid {
        translation 0.5 0 0
        children [ DEF ARM Shape { geometry Box { size 0.2 0.05 0.05 } } ]
        physics Physics { density -1 mass 1 centerOfMass [ 0 0 0 ] }
      }
    }
  ]
}
"""


def _arm(tmp_path: Path, physics_step: float, ode_contacts: bool = True, damping: float = 0.0):
    world = tmp_path / "arm.wbt"
    world.write_text(_ARM % {"damping": damping})
    sim = prepare(world, physics_step=physics_step, ode_contacts=ode_contacts).sim
    motor = next(m for r in sim.robots for m in r.motors.values())
    motor.enable_feedback(32, sim.time_ms)
    return sim, motor


def _held(tmp_path: Path, physics_step: float, ode_contacts: bool = True) -> tuple[float, float]:
    """The arm's angle (rad) and the motor's torque feedback (N m) after 2 s."""
    sim, motor = _arm(tmp_path, physics_step, ode_contacts)
    for _ in range(63):
        sim.step()
    return float(sim.data.qpos[motor.qpos_adr]), motor.feedback(sim.data)


@pytest.mark.parametrize("physics_step", [2.0, 1000.0])
def test_a_motor_row_holds_its_load_where_it_was(tmp_path, physics_step):
    # A 1 kg arm, its centre of mass 0.5 m from a horizontal hinge, starts level: gravity pulls with
    # 4.905 N m, within the motor's 10 N m. Position control at the initial position asks for 0 rad/s,
    # and the row gives what that takes.
    # ODE's row is hard but for WorldInfo's CFM (1e-5): it ends each step CFM x its force short of the
    # velocity asked, so the arm rests where the PID's command (P = 10) makes up for that.
    angle, torque = _held(tmp_path, physics_step)
    assert abs(angle) == pytest.approx(1e-5 * 0.5 * 9.81 / 10, rel=1e-6)
    assert abs(torque) == pytest.approx(0.5 * 9.81, rel=1e-9)


def test_the_default_servo_gives_way_a_little(tmp_path):
    # wbtc's default motor is a velocity servo: it needs a velocity error to push, so the arm sags until
    # the PID's velocity command makes up for it (1.26e-4 rad with one 32 ms step).
    angle, torque = _held(tmp_path, 1000.0, ode_contacts=False)
    assert 1e-4 < abs(angle) < 2e-4
    assert abs(torque) == pytest.approx(0.5 * 9.81, rel=1e-6)


_TURNTABLE = """#VRML_SIM R2023b utf8
WorldInfo { basicTimeStep 32 }
Robot {
  children [
    HingeJoint {
      jointParameters HingeJointParameters { axis 0 0 1 dampingConstant 10 }
      device [ RotationalMotor { name "table" maxTorque 10 maxVelocity 20 } ]
      endPoint Solid {
        translation 0.5 0 0
        children [ DEF TABLE Shape { geometry Box { size 0.2 0.05 0.05 } } ]
        boundingObject USE TABLE
        physics Physics { density -1 mass 1 centerOfMass [ 0 0 0 ] }
      }
    }
  ]
}
"""


@pytest.mark.parametrize("physics_step", [2.0, 1000.0])
def test_a_motor_row_gives_its_whole_torque_against_the_damping(tmp_path, physics_step):
    # A 1 kg arm turning about a vertical hinge damped by 10 N m s/rad, asked for 20 rad/s: that takes
    # more than the motor's 10 N m, so ODE's row gives exactly 10 N m and the damper, solved with it,
    # takes d v' at the velocity v' the step ends with: I (v' - v) / h = 10 - d v'.
    world = tmp_path / "turntable.wbt"
    world.write_text(_TURNTABLE)
    sim = prepare(world, physics_step=physics_step, ode_contacts=True).sim
    motor = next(m for r in sim.robots for m in r.motors.values())
    motor.enable_feedback(32, sim.time_ms)
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (20.0,))
    inertia = 1.0 * (0.2**2 + 0.05**2) / 12 + 1.0 * 0.5**2  # the box about its own axis, then moved 0.5 m
    h = min(physics_step, 32.0) / 1000.0
    velocity = 0.0
    for _ in range(3):
        sim.step()
        for _ in range(round(0.032 / h)):
            velocity = (inertia * velocity + h * 10.0) / (inertia + h * 10.0)
        assert float(sim.data.qvel[motor.dof_adr]) == pytest.approx(velocity, rel=1e-6)
        assert motor.feedback(sim.data) == pytest.approx(10.0, rel=1e-6)


def _link(depth: int) -> str:
    """A 10 g, 10 cm box hinged 10 cm from its parent, with the next link inside it (Webots' test chain)."""
    inner = _link(depth - 1) if depth > 1 else ""
    return f"""HingeJoint {{
      jointParameters HingeJointParameters {{ axis 1 0 0 }}
      device [ RotationalMotor {{ name "motor{depth}" }} ]
      endPoint Solid {{
        translation 0 0.1 0
        name "link{depth}"
        children [ DEF BOX{depth} Shape {{ geometry Box {{ size 0.1 0.1 0.1 }} }} {inner} ]
        boundingObject USE BOX{depth}
        physics Physics {{ density -1 mass 0.01 }}
      }}
    }}"""


def test_a_chain_of_light_links_keeps_the_velocities_asked(tmp_path):
    # Five 10 g links, each hinged on the last, no contacts, one 16 ms step per basic step as in
    # Webots' collapse_invisible_parameter_nodes test: MuJoCo's Newton solver left the five hard rows
    # unsettled (the first joint at 530 rad/s after one step where 0.1 was asked), so their island is
    # solved as ODE's LCP even without a contact.
    world = tmp_path / "chain.wbt"
    world.write_text(f"#VRML_SIM R2023b utf8\nWorldInfo {{ basicTimeStep 16 }}\nRobot {{ children [ {_link(5)} ] }}\n")
    sim = prepare(world, physics_step=1000.0, ode_contacts=True).sim
    motors = sorted((m for r in sim.robots for m in r.motors.values()), key=lambda m: m.dof_adr)
    wanted = [0.1 * (k + 1) for k in range(5)]
    for motor, velocity in zip(motors, wanted, strict=True):
        motor.apply("setPosition", (float("inf"),))
        motor.apply("setVelocity", (velocity,))
    for _ in range(20):
        sim.step()
        reached = [float(sim.data.qvel[m.dof_adr]) for m in motors]
        # Short of each by ODE's CFM (1e-5) times the row's force, gravity's torque on the links beyond
        # (0.33 N m at the first joint: 3.3e-6 rad/s), as in ODE.
        assert reached == pytest.approx(wanted, abs=5e-6)


@pytest.mark.parametrize("physics_step", [2.0, 1000.0])
def test_a_motor_row_reaches_its_velocity_against_the_damping(tmp_path, physics_step):
    # The same turntable with 100 N m available, asked for 2 rad/s: within the torque, so ODE's motor
    # reaches 2 rad/s in the first step against the damping solved with it (d v' = 20 N m). MuJoCo's
    # implicit damping after the solve left it at 2 I / (I + h d) = 0.88 rad/s with one 32 ms step.
    world = tmp_path / "turntable.wbt"
    world.write_text(_TURNTABLE.replace("maxTorque 10", "maxTorque 100"))
    sim = prepare(world, physics_step=physics_step, ode_contacts=True).sim
    motor = next(m for r in sim.robots for m in r.motors.values())
    motor.enable_feedback(32, sim.time_ms)
    motor.apply("setPosition", (float("inf"),))
    motor.apply("setVelocity", (2.0,))
    for step in range(3):
        sim.step()
        # 2 rad/s less ODE's CFM (1e-5) times the row's force (20 to 36 N m): 4e-4 rad/s at most.
        assert float(sim.data.qvel[motor.dof_adr]) == pytest.approx(2.0, abs=4e-4)
        if step > 0:  # at speed: the damper's torque at 2 rad/s
            assert motor.feedback(sim.data) == pytest.approx(10.0 * 2.0, rel=1e-3)
