"""Port of Webots' tests/protos/controllers/nested: a PROTO that instantiates a nested template PROTO whose Capsule
has no top or bottom (template parameter FALSE passed down through IS): a top camera sees the white background through
the missing top, a side camera sees the (black, unlit) side of the capsule.

Run by several worlds (template_nested, template_direct_nested and their Lua variants); the test name comes from
controllerArgs, as the C original's ts_setup(argv[1]); its spaces become underscores because the runner's result
lines are space-separated ("template_direct_nested (lua)" -> "template_direct_nested_(lua)").
"""

import sys

from controller import Robot
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot, sys.argv[1])  # give the controller args

top_camera = robot.getDevice("top camera")
side_camera = robot.getDevice("side camera")

ts_assert_int_equal(top_camera.getWidth(), 1, "Wrong top camera width")
ts_assert_int_equal(top_camera.getHeight(), 1, "Wrong top camera height")
ts_assert_int_equal(side_camera.getWidth(), 1, "Wrong side camera width")
ts_assert_int_equal(side_camera.getHeight(), 1, "Wrong side camera height")

top_camera.enable(TIME_STEP)
side_camera.enable(TIME_STEP)

robot.step(TIME_STEP)

top_values = top_camera.getImage()
ts_assert_color_in_delta(top_camera.imageGetRed(top_values, 1, 0, 0), top_camera.imageGetGreen(top_values, 1, 0, 0),
                         top_camera.imageGetBlue(top_values, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera top color. The top of the capsule should be invisible")

side_values = side_camera.getImage()
ts_assert_color_in_delta(side_camera.imageGetRed(side_values, 1, 0, 0), side_camera.imageGetGreen(side_values, 1, 0, 0),
                         side_camera.imageGetBlue(side_values, 1, 0, 0), 0, 0, 0,  # capsule
                         1, "Unexpected camera side color. The side of the capsule should be visible")

ts_send_success()
