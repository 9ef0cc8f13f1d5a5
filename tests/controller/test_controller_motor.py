"""Motors: initial state from INIT, commands in call order at the next step, Webots' argument checks."""

from __future__ import annotations

import controller_sim
from controller_sim import device, json_lines, make_init

sim = controller_sim.sim  # the fake-simulator fixture (see controller_sim.py)

MOTORS = [
    device(0, "arm", "RotationalMotor", {"maxVelocity": 16.129, "maxTorque": 2.5, "minPosition": -1.0,
                                         "maxPosition": 2.0, "acceleration": 5.0, "controlPID": [20, 0.5, 0.1],
                                         "multiplier": 2.0}, position=0.25, sensor=None, brake=None),
    device(1, "slider", "LinearMotor", {}, position=0.0, sensor=None, brake=None),
]


def test_initial_state_comes_from_the_fields_and_the_joint_position(sim) -> None:
    fake = sim(
        """
        import json
        from controller import Robot, Motor
        robot = Robot()
        arm, slider = robot.getDevice("arm"), Motor("slider")
        for m in (arm, slider):
            print(json.dumps([m.getTargetPosition(), m.getVelocity(), m.getMaxVelocity(), m.getAcceleration(),
                              m.getAvailableTorque(), m.getAvailableForce(), m.getMaxTorque(), m.getMaxForce(),
                              m.getMinPosition(), m.getMaxPosition(), m.getMultiplier(), m.getType(),
                              m.getTorqueFeedbackSamplingPeriod(), m.getBrake(), m.getPositionSensor()]))
        print(json.dumps([arm.target_position, arm.target_velocity, arm.max_velocity, arm.type, slider.max_force]))
        print(arm.getTorqueFeedback(), arm.torque_feedback)
        """,
        make_init(MOTORS),
    )
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    lines = json_lines("\n".join(out.splitlines()[:3]))
    assert lines[0] == [0.25, 16.129, 16.129, 5.0, 2.5, 2.5, 2.5, 2.5, -1.0, 2.0, 2.0, 0, 0, None, None]
    assert lines[1] == [0.0, 10.0, 10.0, -1.0, 10.0, 10.0, 10.0, 10.0, 0.0, 0.0, 1.0, 1, 0, None, None]
    assert lines[2] == [0.25, 16.129, 16.129, 0, 10.0]
    assert out.splitlines()[3] == "nan nan"


def test_commands_arrive_in_call_order_at_the_next_step(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        arm, slider = robot.getDevice("arm"), robot.getDevice("slider")
        arm.setPosition(1.0)
        slider.setPosition(float("inf"))
        slider.setVelocity(-0.5)
        arm.setVelocity(100)
        arm.setAcceleration(-1)
        arm.setAvailableTorque(1.5)
        slider.setAvailableForce(3)
        arm.setControlPID(5, 0, 0)
        arm.enableTorqueFeedback(32)
        slider.setForce(0.25)
        arm.target_position = 0.5
        print(arm.getTargetPosition(), arm.getVelocity(), slider.getVelocity(), arm.getAvailableTorque())
        robot.step()
        print(arm.getTorqueFeedback(), arm.getTorqueFeedbackSamplingPeriod())
        arm.disableTorqueFeedback()
        arm.torque = 0.1
        robot.step()
        """,
        make_init(MOTORS),
    )
    assert fake.step(values={0: 0.75}) == (32, [
        (0, "setPosition", 1.0),
        (1, "setPosition", float("inf")),
        (1, "setVelocity", -0.5),
        (0, "setVelocity", 100.0),
        (0, "setAcceleration", -1.0),
        (0, "setAvailableTorque", 1.5),
        (1, "setAvailableForce", 3.0),
        (0, "setControlPID", 5.0, 0.0, 0.0),
        (0, "enableTorqueFeedback", 32),
        (1, "setForce", 0.25),
        (0, "setPosition", 0.5),
    ])
    assert fake.step() == (32, [(0, "disableTorqueFeedback"), (0, "setTorque", 0.1)])
    rc, out, err = fake.finish()
    assert (rc, err) == (0, "")
    assert out.splitlines() == ["0.5 100.0 -0.5 1.5", "0.75 32"]


def test_invalid_arguments_are_refused_with_webots_messages(sim) -> None:
    fake = sim(
        """
        from controller import Robot
        robot = Robot()
        arm = robot.getDevice("arm")
        arm.setPosition(1.0)
        arm.setVelocity(-2.0)
        arm.setPosition(float("nan"))
        arm.setVelocity(float("nan"))
        arm.setAcceleration(-3)
        arm.setAvailableTorque(-1)
        arm.setAvailableForce(float("nan"))
        arm.setControlPID(0, 0, 0)
        arm.setControlPID(1, -1, 0)
        arm.setControlPID(1, 0, -1)
        arm.setTorque(float("nan"))
        arm.enableTorqueFeedback(-1)
        print(arm.getTargetPosition(), arm.getVelocity(), arm.getAcceleration(), arm.getAvailableTorque())
        robot.step()
        """,
        make_init(MOTORS),
    )
    assert fake.step() == (32, [(0, "setPosition", 1.0)])
    rc, out, err = fake.finish()
    assert rc == 0
    assert out == "1.0 16.129 5.0 2.5\n"
    assert err.splitlines() == [
        "Error: wb_motor_set_velocity() called with negative 'velocity' argument in position control mode (1).",
        "Error: wb_motor_set_position() called with an invalid 'position' argument (NaN).",
        "Error: wb_motor_set_velocity() called with an invalid 'velocity' argument.(NaN)",
        "Error: wb_motor_set_acceleration() called with negative 'acceleration' argument.",
        "Error: wb_motor_set_available_force() called with negative 'force' argument.",
        "Error: wb_motor_set_available_force() called with an invalid 'force' argument (NaN).",
        "Error: wb_motor_set_control_pid() called with negative or zero 'p' argument.",
        "Error: wb_motor_set_control_pid() called with negative 'i' argument.",
        "Error: wb_motor_set_control_pid() called with negative 'd' argument.",
        "Error: wb_motor_set_force() called with an invalid 'force' argument (NaN).",
        "Error: wb_motor_enable_force_feedback() called with negative sampling period.",
    ]


def test_motion_files_drive_motors_each_step(sim, tmp_path) -> None:
    (tmp_path / "wave.motion").write_text(
        "#WEBOTS_MOTION,V1.0,arm,slider,ghost\n00:00:000,Pose1,0.0,0.0,1\n00:00:064,Pose2,1.0,*,1\n"
    )
    fake = sim(
        """
        from controller import Robot, Motion
        robot = Robot()
        wave = Motion("wave.motion")
        bad = Motion("missing.motion")
        print(wave.isValid(), wave.getDuration(), bad.isValid())
        wave.play()
        while not wave.isOver():
            robot.step(32)
        print(wave.getTime(), robot.getDevice("arm").getTargetPosition())
        bad.play()
        """,
        make_init(MOTORS),
    )
    assert fake.step()[1] == [(0, "setPosition", 0.0), (1, "setPosition", 0.0)]
    assert fake.step()[1] == [(0, "setPosition", 0.5)]
    rc, out, err = fake.finish()
    assert rc == 0
    assert out.splitlines() == ["True 64 False", "64 0.5"]  # the last pose is reached, not yet sent
    assert err.splitlines() == [
        "Warning: wbu_motion_new(): ignoring joint 'ghost', specified in file 'wave.motion', but not found in this "
        "robot.",
        "Error: wbu_motion_new(): could not open 'missing.motion' file.",
        "Error: wbu_motion_play() called with NULL 'motion' argument.",
    ]
