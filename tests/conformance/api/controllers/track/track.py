"""Port of Webots' tests/api/controllers/track: one controller for both robots (the test name comes from
controllerArgs, as the C original's ts_setup(argv[1])). The "tracked robot" drives its two Tracks by position, then
turns on the spot by velocity; the "track brake" robot pushes its invisible Track with a force, then brakes it.

The turned robot's rotation is expected as axis (0, -1, 0), angle 1.097467, as in the upstream version at b98925b8
(and omnilink-tech/omnisim); the older 8364fc97 wrote the same rotation as axis (0, 1, 0), angle -1.097467.
"""

import sys

from controller import Supervisor
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_vec3_equal,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32


def test_track_brake() -> None:
    motor = robot.getDevice("motor")
    brake = robot.getDevice("brake")

    robot_node = robot.getFromDef("ROBOT2")
    position = robot_node.getPosition()
    ts_assert_vec3_equal(position[0], position[1], position[2], 0.0, 0.07, 0.5, "Initial position of robot 2 is wrong.")

    for _ in range(4):
        robot.step(TIME_STEP)

    motor.setForce(20)

    for _ in range(40):
        robot.step(TIME_STEP)

    position = robot_node.getPosition()
    ts_assert_double_in_delta(position[0], 0.031310, 0.00001, "Robot 2 position X after moving straight is wrong.")

    for _ in range(40):
        robot.step(TIME_STEP)

    position = robot_node.getPosition()
    ts_assert_double_in_delta(position[0], 0.062818, 0.00001, "Robot 2 position X after moving straight is wrong.")

    brake.setDampingConstant(500)
    for _ in range(40):
        robot.step(TIME_STEP)

    position = robot_node.getPosition()
    ts_assert_double_in_delta(position[0], 0.082369, 0.00001, "Robot 2 position X after activating the brake is wrong.")


def test_tracked_robot() -> None:
    left_motor = robot.getDevice("left motor")
    right_motor = robot.getDevice("right motor")
    left_sensor = robot.getDevice("left position sensor")
    right_sensor = robot.getDevice("right position sensor")

    left_sensor.enable(TIME_STEP)
    right_sensor.enable(TIME_STEP)

    robot_node = robot.getFromDef("ROBOT1")
    rotation_field = robot_node.getField("rotation")
    position = robot_node.getPosition()
    ts_assert_vec3_equal(position[0], position[1], position[2], 0.0, 0.06, 0.0, "Initial position of tracked robot is wrong.")

    p = 0.0
    robot.step(TIME_STEP)
    for _ in range(20):
        p += 0.01
        right_motor.setPosition(p)
        left_motor.setPosition(p)

        robot.step(TIME_STEP)

    left_sensor_value = left_sensor.getValue()
    right_sensor_value = right_sensor.getValue()
    ts_assert_double_in_delta(left_sensor_value, 0.174772, 0.00001,
                              "Left motor position of tracked robotis wrong after moving straight.")
    ts_assert_double_in_delta(right_sensor_value, left_sensor_value, 0.00001,
                              "Left and right motor position of tracked robot doesn't match after moving straight.")

    position = robot_node.getPosition()
    ts_assert_double_in_delta(position[0], 0.172570, 0.0001, "Tracked robot position X after moving straight is wrong.")
    ts_assert_double_in_delta(position[2], 0.0000, 0.0001, "Tracked robot position Z after moving straight is wrong.")

    orientation = rotation_field.getSFRotation()
    ts_assert_double_in_delta(orientation[3], 0.0, 0.001, "Tracked robot position Z after moving straight is wrong.")

    right_motor.setPosition(float("inf"))
    left_motor.setPosition(float("inf"))
    right_motor.setVelocity(-0.2)
    left_motor.setVelocity(0.2)

    for _ in range(100):
        robot.step(TIME_STEP)

    previous_value = left_sensor_value
    left_sensor_value = left_sensor.getValue()
    ts_assert_double_in_delta(left_sensor_value, previous_value + 0.2 * TIME_STEP / 1000 * 100, 0.00001,
                              "Left motor position of tracked robot is wrong after rotating.")

    offset = left_sensor_value - previous_value
    previous_value = right_sensor_value
    right_sensor_value = right_sensor.getValue()
    ts_assert_double_in_delta(right_sensor_value, previous_value - offset, 0.00001,
                              "Left and right motor position offset of tracked robot doesn't match after rotating.")

    orientation = rotation_field.getSFRotation()
    ts_assert_vec3_in_delta(orientation[0], orientation[1], orientation[2], 0.0, -1.0, 0.0, 0.002,
                            "Tracked robot rotation axis is wrong after rotating.")
    ts_assert_double_in_delta(orientation[3], 1.097467, 0.0001, "Tracked robot rotation angle is wrong after rotating.")

    right_motor.setVelocity(0.0)
    left_motor.setVelocity(0.0)


robot = Supervisor()
ts_setup(robot, sys.argv[1])

if robot.getName() == "tracked robot":
    test_tracked_robot()
else:
    test_track_brake()

ts_send_success()
