"""Port of Webots' tests/api/controllers/robot_nested: a parent robot does not own its nested robots' devices."""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_double_equal, ts_assert_pointer_null, ts_send_success, ts_setup

TIME_STEP = 16

robot = Supervisor()
ts_setup(robot, sys.argv[1])

target_velocity = [0.0, 0.0, 1.0, 0.0, 0.0, 0.0]
child_robot = robot.getFromDef("CHILD_ROBOT")
supervisor = robot.getSelf()

# C: wb_robot_get_device returns tag 0 for an unknown device; Python's getDevice returns None.
ts_assert_pointer_null(robot.getDevice("gps"), "The child robot's gps device should not be found by the parent robot")

child_position = supervisor.getPosition()
supervisor.setVelocity(target_velocity)

robot.step(TIME_STEP)

child_position = child_robot.getPosition()
ts_assert_double_equal(child_position[0], 0.0, "The child's tranlation in x should be 0")
ts_assert_double_equal(child_position[1], 0.1, "The child's tranlation in x should be 0.1")
ts_assert_double_equal(child_position[2], 0.016, "The child's tranlation in x should be 0.016")

ts_send_success()
