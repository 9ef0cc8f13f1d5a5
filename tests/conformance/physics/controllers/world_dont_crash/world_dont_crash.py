"""Port of Webots' tests/physics/controllers/world_dont_crash: the world (named by the controller argument) runs for
5 simulated seconds without the simulator crashing."""

import sys

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot, sys.argv[1] if len(sys.argv) > 1 else None)

ts_assert_boolean_equal(len(sys.argv) == 2, "world_dont_crash badly used. world name expected as argument.")

while robot.step(TIME_STEP) != -1:
    if robot.getTime() > 5.0:
        break

ts_send_success()
