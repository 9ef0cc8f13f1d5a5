"""Port of Webots' tests/api/controllers/motor2: the second motor of a Hinge2Joint, reached through its position
sensor: getters before enabling, PID position control with a limited torque and acceleration, then torque control.

The stored upstream controller first drives a "position sensor1" and reads an "inertial unit" that the stored world
(R2023b, at 7e9af36d) does not have; this port follows the version of the controller that matches that world, with
only "position sensor2" and its motor, as kept in omnilink-tech/omnisim (a Webots fork,
tests/api/controllers/motor2/motor2.c) and in cyberbotics/webots at d48919e9.
"""

import math

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

NAN = float("nan")
ACCELERATION = 5
CONTROL_P, CONTROL_I, CONTROL_D = 15, 5, 1
TORQUE = 0.5
NUMBER_OF_STEPS = 20
TIME_STEP = 32  # as in the world file
MAX_POS, MIN_POS = 1.58, -1.53
# Webots' values from an earlier simulation
REFERENCE_POSITION, REFERENCE_TORQUE, REFERENCE_TORQUE_2 = 0.137485, 0.500022, 1.15779e-07

robot = Robot()
ts_setup(robot)
position_sensor2 = robot.getDevice("position sensor2")
motor2 = position_sensor2.getMotor()
robot.step(TIME_STEP)

position = position_sensor2.getValue()
ts_assert_double_equal(position, NAN, "The position value measured by the position sensor 2 should be NaN and not %g "
                       "before the device is enabled", position)
torque_feedback = motor2.getTorqueFeedback()
ts_assert_double_equal(torque_feedback, NAN, "The torque feedback value measured by the motor 2 should be NaN and not %g "
                       "before the device is enabled", torque_feedback)
feedback_sampling_period = motor2.getTorqueFeedbackSamplingPeriod()
ts_assert_double_equal(feedback_sampling_period, 0, "The torque feedback sampling period value measured by the motor 2 "
                       "should be 0 and not %g before the device is enabled", feedback_sampling_period)
max_position = motor2.getMaxPosition()
ts_assert_double_equal(max_position, MAX_POS, "The max position value measured by the motor 2 should be %g and not %g",
                       MAX_POS, max_position)
min_position = motor2.getMinPosition()
ts_assert_double_equal(min_position, MIN_POS, "The min position value measured by the motor 2 should be %g and not %g",
                       MIN_POS, min_position)

position_sensor2.enable(TIME_STEP)
motor2.enableTorqueFeedback(TIME_STEP)
motor2.setControlPID(CONTROL_P, CONTROL_I, CONTROL_D)
motor2.setAvailableTorque(TORQUE)
motor2.setAcceleration(ACCELERATION)
motor2.setPosition(math.pi / 2)
robot.step(TIME_STEP)

target_position = motor2.getTargetPosition()
ts_assert_double_equal(target_position, math.pi / 2, "The target position value measured by the motor 2 should be %g "
                       "and not %g", math.pi / 2, target_position)
for _ in range(NUMBER_OF_STEPS):
    robot.step(TIME_STEP)

position = position_sensor2.getValue()
ts_assert_double_in_delta(position, REFERENCE_POSITION, 0.001, "The position value measured by the position sensor 2 "
                          "should be %g and not %g", REFERENCE_POSITION, position)
torque = motor2.getTorqueFeedback()
ts_assert_double_in_delta(torque, REFERENCE_TORQUE, 0.0001, "The first torque feedback value measured by the motor 2 "
                          "should be %g and not %g", REFERENCE_TORQUE, torque)

robot.step(TIME_STEP)
motor2.setTorque(TORQUE)
for _ in range(NUMBER_OF_STEPS):
    robot.step(TIME_STEP)

torque2 = motor2.getTorqueFeedback()
ts_assert_double_in_delta(torque2, REFERENCE_TORQUE_2, 0.0001, "The second torque feedback value measured by the motor 2 "
                          "should be %g and not %g", REFERENCE_TORQUE_2, torque2)

ts_send_success()
