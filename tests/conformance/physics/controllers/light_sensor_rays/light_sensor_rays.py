"""Port of Webots' tests/physics/controllers/light_sensor_rays: light sensors read a fixed and a falling spot light
with the right irradiance step after step, whether the sensors stand still ("static" robot) or are driven by wheels
during the physics step ("dynamic" robot)."""

import sys

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup


def check_sensor_value(sensor, expected, message):
    value = sensor.getValue()
    ts_assert_double_in_delta(value, expected, 1.0, message, expected, value)


robot = Robot()
ts_setup(robot, sys.argv[1])

expected_static_value = 0.0
expected_dynamic_value = 0.0
time_step = int(robot.getBasicTimeStep())
dynamic = robot.getName() != "static"

ls_s = robot.getDevice("light sensor static")
ls_d = robot.getDevice("light sensor dynamic")
ls_s.enable(time_step)
ls_d.enable(time_step)

# The "static" robot has no wheels: Webots' C calls on a null tag only print a warning.
left_motor = robot.getDevice("left wheel motor")
right_motor = robot.getDevice("right wheel motor")
for motor in (left_motor, right_motor):
    if motor is not None:
        motor.setPosition(float("inf"))
        motor.setVelocity(0)

robot.step(5 * time_step)

if dynamic:
    left_motor.setVelocity(20)
    right_motor.setVelocity(20)

expected_static_value = 999.0
check_sensor_value(ls_s, expected_static_value, "The light sensor doesn't return the correct initial measurement of "
                   "static light: expected %f, measured %f.")

if dynamic:
    expected_dynamic_value = 958.0
check_sensor_value(ls_d, expected_dynamic_value, "The light sensor doesn't return the correct initial measurement of "
                   "dynamic light: expected %f, measured %f.")

robot.step(time_step)

if dynamic:
    expected_static_value = 0.0
check_sensor_value(ls_s, expected_static_value, "The light sensor doesn't return the correct measurement of static "
                   "light after 1 step: expected %f, measured %f.")

expected_dynamic_value = 841.0 if dynamic else 208.0
check_sensor_value(ls_d, expected_dynamic_value, "The light sensor doesn't return the correct measurement of dynamic "
                   "light after 1 step: expected %f, measured %f.")

robot.step(time_step)

static_expected = 0.0 if dynamic else 999.0
check_sensor_value(ls_s, static_expected, "The light sensor doesn't return the correct measurement of static light "
                   "after 2 steps: expected %f, measured %f.")

expected_dynamic_value = 737.0 if dynamic else 707.0
check_sensor_value(ls_d, expected_dynamic_value, "The light sensor doesn't return the correct measurement of dynamic "
                   "light after 2 steps: expected %f, measured %f.")

ts_send_success()
