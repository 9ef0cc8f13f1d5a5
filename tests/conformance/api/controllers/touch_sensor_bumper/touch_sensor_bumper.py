"""Port of Webots' tests/api/controllers/touch_sensor_bumper: a bumper TouchSensor reads 0 while falling and 1 once
it lies on the floor."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 16

robot = Robot()
ts_setup(robot)

ts = robot.getDevice("touch sensor")
ts.enable(TIME_STEP)

for _ in range(5):
    robot.step(TIME_STEP)

value = ts.getValue()
ts_assert_double_in_delta(value, 0.0, 0.0, "The \"bumper\" TouchSensor should return 0.0 when there is no collision.")

for _ in range(20):
    robot.step(TIME_STEP)

value = ts.getValue()
ts_assert_double_in_delta(value, 1.0, 0.0, "The \"bumper\" TouchSensor should return 1.0 when there is a collision.")

ts_send_success()
