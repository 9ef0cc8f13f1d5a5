"""Port of Webots' tests/api/controllers/robot_synchronous_time: a synchronous robot's getTime advances by exactly
the duration of each step (one basic step, then 0, 1, 2, ... steps at once), and step returns 0."""

from controller import Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_assert_int_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

e = 0.0

ts_assert_boolean_equal(robot.getSynchronization(), "Cannot get the synchronization flag")

for _ in range(20):
    r = robot.getTime()
    ts_assert_double_in_delta(r, e, 0.000001, "Regular time test: The time measured is wrong. Expected %f. Received %f.",
                              e, r)
    v = robot.step(TIME_STEP)
    ts_assert_int_equal(v, 0, "Regular time test: The return value of wb_robot_step is wrong. Expected 0. Received %d.", v)
    e += 0.001 * TIME_STEP

for i in range(20):
    r = robot.getTime()
    ts_assert_double_in_delta(r, e, 0.000001, "Multiple time test: The time measured is wrong. Expected %f. Received %f.",
                              e, r)
    v = robot.step(TIME_STEP * i)
    ts_assert_int_equal(v, 0, "Regular time test: The return value of wb_robot_step is wrong. Expected 0. Received %d.", v)
    e += 0.001 * TIME_STEP * i

ts_send_success()
