"""Port of Webots' tests/protos/controllers/dummy: a test controller that steps once by the number of milliseconds
given as its argument and reports success, so that the test run lasts at least that long (template_proto_follow_solid
uses it to keep the run going while its other robot's controller restarts).
"""

import sys

from controller import Robot
from ts_assertion import ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)

robot.step(int(sys.argv[1]))

ts_send_success()
