"""Port of Webots' tests/protos/controllers/proto_regeneration_multiple_instances: a template PROTO instance given as
a parameter that a PROTO uses twice (two IS to the same MFNode field) is instantiated twice, and regenerating it (its
sphere size) regenerates both copies, as two distance sensors see.

Run by the worlds proto_regeneration_multiple_instances and its Lua variant; the test name comes from controllerArgs,
as the C original's ts_setup(argv[1]); its spaces become underscores because the runner's result lines are
space-separated.
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_double_is_bigger, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args

protoNode = robot.getFromDef("TEST_NODE")
sizeField = protoNode.getField("size")
ds1 = robot.getDevice("ds1")
ds2 = robot.getDevice("ds2")
ds1.enable(TIME_STEP)
ds2.enable(TIME_STEP)

robot.step(2 * TIME_STEP)
robot.step(2 * TIME_STEP)

value = ds1.getValue()
ts_assert_double_is_bigger(500.0, value, "The initial sphere of radius 0.15 is not correctly created.")
value = ds2.getValue()
ts_assert_double_is_bigger(value, 990.0, "The initial sphere has wrong radius.")

sizeField.setSFFloat(0.2)

robot.step(2 * TIME_STEP)

value = ds1.getValue()
ts_assert_double_is_bigger(500.0, value, "The sphere radius after regeneration is smaller than the initial value.")
value = ds2.getValue()
ts_assert_double_is_bigger(500.0, value, "The sphere radius after regeneration has wrong radius.")

ts_send_success()
