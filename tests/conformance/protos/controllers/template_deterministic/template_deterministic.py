"""Port of Webots' tests/protos/controllers/template_deterministic: two instances of a deterministic procedural
PROTO (wbrandom without a seed) get the same box size, two non-deterministic ones seeded differently do not, and a
deterministic one differs from a non-deterministic one, as seen by four distance sensors.

Run by template_deterministic.wbt (JavaScript templates) and template_deterministic_lua.wbt (Lua templates). The test
name comes from controllerArgs, as the C original's ts_setup(argv[1]); its spaces become underscores because the
runner's result lines are space-separated ("template_deterministic (lua)" -> "template_deterministic_(lua)").
"""

import sys

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_double_not_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot, sys.argv[1])

# get and enable the acc
ds_deterministic1 = robot.getDevice("deterministic 1")
ds_deterministic2 = robot.getDevice("deterministic 2")
ds_non_deterministic1 = robot.getDevice("non deterministic 1")
ds_non_deterministic2 = robot.getDevice("non deterministic 2")

ds_deterministic1.enable(TIME_STEP)
ds_deterministic2.enable(TIME_STEP)
ds_non_deterministic1.enable(TIME_STEP)
ds_non_deterministic2.enable(TIME_STEP)

robot.step(TIME_STEP)

# check that both 'deterministic' PROTO nodes are equivalent
ts_assert_double_equal(ds_deterministic1.getValue(), ds_deterministic2.getValue(),
                       "Deterministic procedural PROTO nodes should have the same size (%lf != %lf)",
                       ds_deterministic1.getValue(), ds_deterministic2.getValue())

# check that both 'non-deterministic' PROTO nodes are not equivalent
ts_assert_double_not_equal(ds_non_deterministic1.getValue(), ds_non_deterministic2.getValue(),
                           "Non-deterministic procedural PROTO nodes should have different sizes (%lf = %lf)",
                           ds_non_deterministic1.getValue(), ds_non_deterministic2.getValue())

# Make sure deterministic and non-deterministic PROTO nodes are not equivalent
ts_assert_double_not_equal(
    ds_deterministic1.getValue(), ds_non_deterministic2.getValue(),
    "Non-deterministic and deterministic procedural PROTO nodes should have different sizes (%lf = %lf)",
    ds_deterministic1.getValue(), ds_non_deterministic2.getValue())

ts_send_success()
