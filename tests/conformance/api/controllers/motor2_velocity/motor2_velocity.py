"""Port of Webots' tests/api/controllers/motor2_velocity: a Hinge2Joint's two motors under velocity control; the
position is not wrapped to [-pi, pi] and matches the inertial unit's angle, and a position target brings it back.

The stored C source assigns the inertial unit's reading to an undeclared `rpy` in its second loop; the port reads
it into `roll_pitch_yaw`, which is what the loop evidently means (the value is not checked after that loop).
"""

import math

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_double_is_bigger, ts_send_success, ts_setup

VELOCITY = 10.0
TIME_STEP = 32  # copied from the .wbt file

robot = Robot()


def test_position_under_velocity_control(motor, position_sensor, axis):
    inertial_unit = robot.getDevice("inertial unit")
    inertial_unit.enable(TIME_STEP)
    position_sensor.enable(TIME_STEP)
    robot.step(TIME_STEP)

    roll_pitch_yaw = inertial_unit.getRollPitchYaw()
    position = position_sensor.getValue()

    original_position = position

    # Run the motor at varying velocities
    motor.setPosition(math.inf)
    motor.setVelocity(0)
    for i in range(100):
        motor.setVelocity(VELOCITY * abs(math.cos(i * 2 * math.pi / 100)))
        robot.step(TIME_STEP)
        roll_pitch_yaw = inertial_unit.getRollPitchYaw()

    # The new position should match the one provided by the inertial unit
    position = position_sensor.getValue()
    normalized_position = math.fmod(position, 2 * math.pi)
    if normalized_position > math.pi:
        normalized_position -= 2 * math.pi
    ts_assert_double_in_delta(roll_pitch_yaw[axis], normalized_position, 0.01,
                              "The normalized rotation measured by position sensor (%g) and the inertial unit (%g) are "
                              "different", normalized_position, roll_pitch_yaw[axis])

    # The position itself should not be normalized to be between -pi and pi
    ts_assert_double_is_bigger(position, 2 * math.pi, "The position shoud be at least %g but is only %g", 2 * math.pi,
                               position)

    # Returning to original position
    motor.setPosition(original_position)
    motor.setVelocity(VELOCITY)
    prev_position = position
    for _ in range(400):
        robot.step(TIME_STEP)
        prev_position = position
        position = position_sensor.getValue()
        roll_pitch_yaw = inertial_unit.getRollPitchYaw()
        if abs(position - prev_position) < 1e-6:
            break
    ts_assert_double_in_delta(original_position, position, 0.01,
                              "The motor's position (%g) and it's original position (%g) are different", position,
                              original_position)
    ts_assert_double_is_bigger(1e-6, abs(position - prev_position), "The motor has not stopped")


ts_setup(robot)

position_sensor = robot.getDevice("position sensor1")
motor = position_sensor.getMotor()
test_position_under_velocity_control(motor, position_sensor, 2)

position_sensor2 = robot.getDevice("position sensor2")
motor2 = position_sensor2.getMotor()
test_position_under_velocity_control(motor2, position_sensor2, 1)

ts_send_success()
