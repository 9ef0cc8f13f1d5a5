"""Port of Webots' tests/physics/controllers/coupled_motor: motors named "NAME::..." are coupled. One robot per
argument: "coupling_test" checks which motors a velocity or position command reaches, "load_test" checks the limits
(maxVelocity, minPosition, maxPosition) that coupled motors share after loading, scaled by their multipliers, and
"physics_test" checks that five coupled joints follow one another's velocity, position and torque commands at their
multipliers' ratios."""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 16
NB_SENSORS = 5
NB_MOTORS = 5

robot = Supervisor()
ts_setup(robot)

test_type = sys.argv[1]

if test_type == "coupling_test":
    motor_group_a = robot.getDevice("motor group a")
    motor_group_a_subgroup_b = robot.getDevice("motor group a::subgroup b")
    motor_group_a_subgroup_c = robot.getDevice("motor group a::subgroup c")
    motor_group_b_subgroup_b = robot.getDevice("motor group b::subgroup b")

    # "motor group a" has no "::", so it is coupled with nothing
    motor_group_a.setVelocity(5)
    motor_group_a.setPosition(5)

    robot.step(TIME_STEP)

    ts_assert_double_equal(motor_group_a.getVelocity(), 5, "Motor 'motor group a' should have velocity 5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_b.getVelocity(), 10,
                           "Motor 'motor group a::subgroup b' should have velocity 10 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_c.getVelocity(), 10,
                           "Motor 'motor group a::subgroup c' should have velocity 10 but does not.")
    ts_assert_double_equal(motor_group_b_subgroup_b.getVelocity(), 10,
                           "Motor 'motor group b::subgroup b' should have velocity 10 but does not.")

    ts_assert_double_equal(motor_group_a.getTargetPosition(), 5,
                           "Motor 'motor group a' should have position 5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_b.getTargetPosition(), 0,
                           "Motor 'motor group a::subgroup b' should have position 0 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_c.getTargetPosition(), 0,
                           "Motor 'motor group a::subgroup c' should have position 0 but does not.")
    ts_assert_double_equal(motor_group_b_subgroup_b.getTargetPosition(), 0,
                           "Motor 'motor group b::subgroup b' should have position 0 but does not.")

    # reaches "motor group a::subgroup b" and "motor group a::subgroup c" only
    motor_group_a_subgroup_c.setVelocity(2.5)
    motor_group_a_subgroup_c.setPosition(2.5)
    robot.step(10 * TIME_STEP)

    ts_assert_double_equal(motor_group_a.getVelocity(), 5, "Motor 'motor group a' should have velocity 5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_b.getVelocity(), 2.5,
                           "Motor 'motor group a::subgroup b' should have velocity 2.5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_c.getVelocity(), 2.5,
                           "Motor 'motor group a::subgroup c' should have velocity 2.5 but does not.")
    ts_assert_double_equal(motor_group_b_subgroup_b.getVelocity(), 10,
                           "Motor 'motor group b::subgroup b' should have velocity 10 but does not.")

    ts_assert_double_equal(motor_group_a.getTargetPosition(), 5,
                           "Motor 'motor group a' should have position 5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_b.getTargetPosition(), 2.5,
                           "Motor 'motor group a::subgroup b' should have position 2.5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_c.getTargetPosition(), 2.5,
                           "Motor 'motor group a::subgroup c' should have position 2.5 but does not.")
    ts_assert_double_equal(motor_group_b_subgroup_b.getTargetPosition(), 0,
                           "Motor 'motor group b::subgroup b' should have position 0 but does not.")

    # reaches only itself
    motor_group_b_subgroup_b.setVelocity(7.5)
    motor_group_b_subgroup_b.setPosition(7.5)
    robot.step(TIME_STEP)

    ts_assert_double_equal(motor_group_a.getVelocity(), 5, "Motor 'motor group a' should have velocity 5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_b.getVelocity(), 2.5,
                           "Motor 'motor group a::subgroup b' should have velocity 2.5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_c.getVelocity(), 2.5,
                           "Motor 'motor group a::subgroup c' should have velocity 2.5 but does not.")
    ts_assert_double_equal(motor_group_b_subgroup_b.getVelocity(), 7.5,
                           "Motor 'motor group b::subgroup b' should have velocity 7.5 but does not.")

    ts_assert_double_equal(motor_group_a.getTargetPosition(), 5,
                           "Motor 'motor group a' should have position 5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_b.getTargetPosition(), 2.5,
                           "Motor 'motor group a::subgroup b' should have position 2.5 but does not.")
    ts_assert_double_equal(motor_group_a_subgroup_c.getTargetPosition(), 2.5,
                           "Motor 'motor group a::subgroup c' should have position 2.5 but does not.")
    ts_assert_double_equal(motor_group_b_subgroup_b.getTargetPosition(), 7.5,
                           "Motor 'motor group b::subgroup b' should have position 7.5 but does not.")

if test_type == "load_test":
    # same multiplier: the first motor's maxVelocity (5) holds for the three
    for i in range(0, 3):
        motor = robot.getDeviceByIndex(i)
        ts_assert_double_equal(motor.getVelocity(), 5, "Motor A: 'maxVelocity' should be 5 but isn't.")
    # same multiplier, the first motor's limits [0, 0] (none) hold for the three
    for i in range(3, 6):
        motor = robot.getDeviceByIndex(i)
        ts_assert_double_equal(motor.getMinPosition(), 0, "Motor B: 'minPosition' should be 0 but isn't.")
        ts_assert_double_equal(motor.getMaxPosition(), 0, "Motor B: 'maxPosition' should be 0 but isn't.")
    # same multiplier, the first motor's limits [-5, 10] hold for the three
    for i in range(6, 9):
        motor = robot.getDeviceByIndex(i)
        ts_assert_double_equal(motor.getMinPosition(), -5, "Motor C: 'minPosition' should be -5 but isn't.")
        ts_assert_double_equal(motor.getMaxPosition(), 10, "Motor C: 'maxPosition' should be 10 but isn't.")
    # multipliers 2, 0.5, 4: limits scaled from the first motor's
    motor = robot.getDeviceByIndex(9)
    ts_assert_double_equal(motor.getMinPosition(), -2, "Motor D: 'minPosition' should be -2 but isn't.")
    ts_assert_double_equal(motor.getMaxPosition(), 4, "Motor D: 'maxPosition' should be 4 but isn't.")
    ts_assert_double_equal(motor.getMaxVelocity(), 10, "Motor D: 'maxVelocity' should be 10 but isn't.")
    motor = robot.getDeviceByIndex(10)
    ts_assert_double_equal(motor.getMinPosition(), -0.5, "Motor D: 'minPosition' should be -0.5 but isn't.")
    ts_assert_double_equal(motor.getMaxPosition(), 1, "Motor D: 'maxPosition' should be 1 but isn't.")
    ts_assert_double_equal(motor.getMaxVelocity(), 2.5, "Motor D: 'maxVelocity' should be 2.5 but isn't.")
    motor = robot.getDeviceByIndex(11)
    ts_assert_double_equal(motor.getMinPosition(), -4, "Motor D: 'minPosition' should be -4 but isn't.")
    ts_assert_double_equal(motor.getMaxPosition(), 8, "Motor D: 'maxPosition' should be 8 but isn't.")
    ts_assert_double_equal(motor.getMaxVelocity(), 20, "Motor D: 'maxVelocity' should be 20 but isn't.")
    # multipliers 2, -0.5, -4: a negative multiplier swaps the scaled limits
    motor = robot.getDeviceByIndex(12)
    ts_assert_double_equal(motor.getMinPosition(), -2, "Motor E: 'minPosition' should be -2 but isn't.")
    ts_assert_double_equal(motor.getMaxPosition(), 4, "Motor E: 'maxPosition' should be 4 but isn't.")
    ts_assert_double_equal(motor.getMaxVelocity(), 10, "Motor E: 'maxVelocity' should be 10 but isn't.")
    motor = robot.getDeviceByIndex(13)
    ts_assert_double_equal(motor.getMinPosition(), -1, "Motor E: 'minPosition' should be -1 but isn't.")
    ts_assert_double_equal(motor.getMaxPosition(), 0.5, "Motor E: 'maxPosition' should be 0.5 but isn't.")
    ts_assert_double_equal(motor.getMaxVelocity(), 2.5, "Motor E: 'maxVelocity' should be 2.5 but isn't.")
    motor = robot.getDeviceByIndex(14)
    ts_assert_double_equal(motor.getMinPosition(), -8, "Motor E: 'minPosition' should be -8 but isn't.")
    ts_assert_double_equal(motor.getMaxPosition(), 4, "Motor E: 'maxPosition' should be 4 but isn't.")
    ts_assert_double_equal(motor.getMaxVelocity(), 20, "Motor E: 'maxVelocity' should be 20 but isn't.")

if test_type == "physics_test":
    sensors = []
    for i in range(NB_SENSORS):
        sensor = robot.getDevice("sensor%d" % (i + 1))
        sensor.enable(TIME_STEP)
        sensors.append(sensor)

    motors = [robot.getDeviceByIndex(2 * i + 1) for i in range(NB_MOTORS)]

    positions = [0.0] * NB_SENSORS

    def read_positions():
        for i in range(NB_SENSORS):
            positions[i] = sensors[i].getValue()

    tolerance = 1e-4
    k = 0

    # velocity control of motors[0]
    motors[0].setPosition(float("inf"))
    motors[0].setVelocity(0.4)

    while robot.step(TIME_STEP) != -1 and k < 250:
        if k == 50:
            motors[0].setVelocity(-0.4)
        if k == 100:
            motors[0].setVelocity(0.2)
        if k == 150:
            motors[0].setVelocity(-0.2)
        if k == 202:
            motors[0].setVelocity(0)

        read_positions()

        ts_assert_double_in_delta(positions[1], positions[0] * 0.5, tolerance,
                                  "Velocity control: wrong position[1] when controlling motor[0].")
        ts_assert_double_in_delta(positions[2], positions[0] * 4.0, tolerance,
                                  "Velocity control: wrong position[2] when controlling motor[0].")
        ts_assert_double_in_delta(positions[3], positions[0] * -0.5, tolerance,
                                  "Velocity control: wrong position[3] when controlling motor[0].")
        ts_assert_double_in_delta(positions[4], positions[0] * -4.0, tolerance,
                                  "Velocity control: wrong position[4] when controlling motor[0].")
        k += 1

    # velocity control of motors[4]
    motors[4].setVelocity(0.4)

    k = 0
    while robot.step(TIME_STEP) != -1 and k < 250:
        if k == 50:
            motors[4].setVelocity(-0.4)
        if k == 100:
            motors[4].setVelocity(0.2)
        if k == 150:
            motors[4].setVelocity(-0.2)
        if k == 202:
            motors[4].setVelocity(0)

        read_positions()

        ts_assert_double_in_delta(positions[0], positions[4] * -0.25, tolerance,
                                  "Velocity control: wrong position[0] when controlling motor[4].")
        ts_assert_double_in_delta(positions[1], positions[4] * -0.125, tolerance,
                                  "Velocity control: wrong position[1] when controlling motor[4].")
        ts_assert_double_in_delta(positions[2], positions[4] * -1, tolerance,
                                  "Velocity control: wrong position[2] when controlling motor[4].")
        ts_assert_double_in_delta(positions[3], positions[4] * 0.125, tolerance,
                                  "Velocity control: wrong position[3] when controlling motor[4].")
        k += 1

    # position control of motors[0]
    motors[0].setVelocity(10)
    motors[0].setPosition(1.5708)

    k = 0
    tolerance = 1e-7
    while robot.step(TIME_STEP) != -1 and k < 301:
        if k == 101:
            motors[0].setPosition(-0.7854)
        if k == 201:
            motors[0].setPosition(0)

        read_positions()

        if k > 0 and k % 100 == 0:
            ts_assert_double_in_delta(positions[1], positions[0] * 0.5, tolerance,
                                      "Position control: wrong position[1] when controlling motor[0].")
            ts_assert_double_in_delta(positions[2], positions[0] * 4.0, tolerance,
                                      "Position control: wrong position[2] when controlling motor[0].")
            ts_assert_double_in_delta(positions[3], positions[0] * -0.5, tolerance,
                                      "Position control: wrong position[3] when controlling motor[0].")
            ts_assert_double_in_delta(positions[4], positions[0] * -4.0, tolerance,
                                      "Position control: wrong position[4] when controlling motor[0].")
        k += 1

    # position control of motors[4]
    motors[4].setPosition(-1.5708)

    k = 0
    while robot.step(TIME_STEP) != -1 and k < 301:
        if k == 101:
            motors[4].setPosition(0.7854)
        if k == 201:
            motors[4].setPosition(0.0)

        read_positions()

        if k > 0 and k % 100 == 0:
            ts_assert_double_in_delta(positions[0], positions[4] * -0.25, tolerance,
                                      "Position control: wrong position[0] when controlling motor[4].")
            ts_assert_double_in_delta(positions[1], positions[4] * -0.125, tolerance,
                                      "Position control: wrong position[1] when controlling motor[4].")
            ts_assert_double_in_delta(positions[2], positions[4] * -1, tolerance,
                                      "Position control: wrong position[2] when controlling motor[4].")
            ts_assert_double_in_delta(positions[3], positions[4] * 0.125, tolerance,
                                      "Position control: wrong position[3] when controlling motor[4].")
        k += 1

    # torque control of motors[0]
    test_robot = robot.getFromDef("PHYSICS_TEST")
    test_robot.resetPhysics()
    robot.step(TIME_STEP)
    motors[0].setTorque(0.004)

    k = 0
    tolerance = 1e-2
    while robot.step(TIME_STEP) != -1 and k < 50:
        if k == 50:
            motors[0].setTorque(-0.004)
        if k == 100:
            motors[0].setTorque(0.001)
        if k == 150:
            motors[0].setTorque(-0.002)
        if k == 200:
            motors[0].setTorque(0)

        read_positions()

        ts_assert_double_in_delta(positions[1], positions[0] * 0.5, tolerance,
                                  "Torque control: wrong position[1] when controlling motor[0].")
        ts_assert_double_in_delta(positions[2], positions[0] * 4.0, tolerance,
                                  "Torque control: wrong position[2] when controlling motor[0].")
        ts_assert_double_in_delta(positions[3], positions[0] * -0.5, tolerance,
                                  "Torque control: wrong position[3] when controlling motor[0].")
        ts_assert_double_in_delta(positions[4], positions[0] * -4.0, tolerance,
                                  "Torque control: wrong position[4] when controlling motor[0].")
        k += 1

    # torque control of motors[4]
    test_robot.resetPhysics()
    robot.step(TIME_STEP)
    motors[4].setTorque(0.001)

    k = 0
    tolerance = 1e-3
    while robot.step(TIME_STEP) != -1 and k < 250:
        if k == 50:
            motors[4].setTorque(-0.002)
        if k == 100:
            motors[4].setTorque(0.0005)
        if k == 150:
            motors[4].setTorque(-0.001)
        if k == 200:
            motors[4].setTorque(0)

        read_positions()

        ts_assert_double_in_delta(positions[0], positions[4] * -0.25, tolerance,
                                  "Torque control: wrong position[0] when controlling motor[4].")
        ts_assert_double_in_delta(positions[1], positions[4] * -0.125, tolerance,
                                  "Torque control: wrong position[1] when controlling motor[4].")
        ts_assert_double_in_delta(positions[2], positions[4] * -1, tolerance,
                                  "Torque control: wrong position[2] when controlling motor[4].")
        ts_assert_double_in_delta(positions[3], positions[4] * 0.125, tolerance,
                                  "Torque control: wrong position[3] when controlling motor[4].")
        k += 1

ts_send_success()
