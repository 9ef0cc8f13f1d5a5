"""Port of Webots' tests/api/controllers/motor3_velocity: a BallJoint's three motors under velocity control; each
position matches the inertial unit's quaternion, is not wrapped, and a position target brings it back."""

import math

from controller import Robot
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_double_is_bigger,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32  # copied from the .wbt file

robot = Robot()


def test_position_under_velocity_control(sensor_name, motor_name, max_velocity, axis):
    inertial_unit = robot.getDevice("inertial unit")
    inertial_unit.enable(TIME_STEP)

    position_sensor = robot.getDevice(sensor_name)
    motor = robot.getDevice(motor_name)

    position_sensor.enable(TIME_STEP)
    robot.step(TIME_STEP)

    quaternion = inertial_unit.getQuaternion()
    position = position_sensor.getValue()

    original_position = position

    # Run the motor at varying velocities
    motor.setPosition(math.inf)
    motor.setVelocity(0)
    for i in range(100):
        motor.setVelocity(max_velocity * abs(math.cos(i * 2 * math.pi / 100)))
        robot.step(TIME_STEP)
        quaternion = inertial_unit.getQuaternion()
        position = position_sensor.getValue()

    # The new position should match the one provided by the inertial unit
    actual_quaternion = [0.0, 0.0, 0.0, 0.0]
    actual_quaternion[3] = math.cos(position / 2)
    if axis == 1:
        axis = 2
    elif axis == 2:
        axis = 1
    actual_quaternion[axis] = math.sin(position / 2)
    ts_assert_double_in_delta(quaternion[3], actual_quaternion[3], 0.01,
                              "The cos(theta/2) measured by %s (%g) and the inertial unit (%g) are different", sensor_name,
                              actual_quaternion[3], quaternion[3])
    ts_assert_vec3_in_delta(quaternion[0], quaternion[1], quaternion[2], actual_quaternion[0], actual_quaternion[1],
                            actual_quaternion[2], 0.01,
                            "The rotation axis measured by %s (%g, %g, %g) and the inertial unit (%g, %g, %g) are "
                            "different", sensor_name, actual_quaternion[0], actual_quaternion[1], actual_quaternion[2],
                            quaternion[0], quaternion[1], quaternion[2])

    # The position itself should not be normalized to be between -pi and pi
    min_expected_position = max_velocity / 2 * TIME_STEP / 1000.0 * 100.0
    ts_assert_double_is_bigger(position, min_expected_position,
                               "The position measured by %s shoud be at least %g but is only %g", sensor_name,
                               min_expected_position, position)

    # Returning to original position
    motor.setPosition(original_position)
    motor.setVelocity(max_velocity)
    previous_position = previous_position2 = 0.0
    for _ in range(400):
        robot.step(TIME_STEP)
        previous_position2 = previous_position
        previous_position = position
        position = position_sensor.getValue()
        quaternion = inertial_unit.getQuaternion()
        if abs(position - previous_position) < 1e-6 and abs(previous_position - previous_position2) < 1e-6:
            break
    ts_assert_double_in_delta(original_position, position, 0.01,
                              "The position measured by %s (%g) and it's original position (%g) are different",
                              sensor_name, position, original_position)
    ts_assert_double_is_bigger(1e-6, abs(position - previous_position), "The motor associated with %s has not stopped",
                               sensor_name)


ts_setup(robot)
robot.getDevice("rotational motor1").setPosition(0.0)
robot.getDevice("rotational motor2").setPosition(0.0)
robot.getDevice("rotational motor3").setPosition(0.0)

test_position_under_velocity_control("position sensor1", "rotational motor1", 10.0, 0)
test_position_under_velocity_control("position sensor3", "rotational motor3", 10.0, 1)
test_position_under_velocity_control("position sensor2", "rotational motor2", 0.10, 2)

ts_send_success()
