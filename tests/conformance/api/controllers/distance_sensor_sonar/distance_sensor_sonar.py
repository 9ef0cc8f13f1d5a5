"""Port of Webots' tests/api/controllers/distance_sensor_sonar: a sonar reads the nearest hit of its rays."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

us = [("ds0", 0.1), ("ds1", 1.0), ("ds2", 0.05), ("ds3", 0.218207)]
tags = {}
for name, _ in us:
    tags[name] = robot.getDevice(name)
    tags[name].enable(TIME_STEP)

robot.step(TIME_STEP)
robot.step(TIME_STEP)

for name, expected in us:
    value = tags[name].getValue()
    ts_assert_double_in_delta(value, expected, 0.00001,
                              "The distance sensor '%s' (sonar) doesn't return the right distance when hitting an object.",
                              name)

ts_send_success()
