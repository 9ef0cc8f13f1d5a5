"""Port of Webots' tests/api/controllers/robot_nested_child: a nested robot does not own its parent's devices."""

import sys

from controller import Robot
from ts_assertion import ts_assert_pointer_null, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot, sys.argv[1])

# C: wb_robot_get_device returns tag 0 for an unknown device; Python's getDevice returns None.
ts_assert_pointer_null(robot.getDevice("gyro"), "The parent robot's gyro device should not be found by the child robot")

ts_send_success()
