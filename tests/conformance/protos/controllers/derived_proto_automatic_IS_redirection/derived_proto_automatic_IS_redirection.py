"""Port of Webots' tests/protos/controllers/derived_proto_automatic_IS_redirection: a template PROTO's parameter
`size` that its body never associates with IS is not redirected to the `size` of the node it is built on (BoxShape):
the box keeps its 0.1 size, before and after the parameter changes, so a 1-pixel camera sees the white background.

Run by derived_proto_automatic_IS_redirection.wbt and its Lua variant; the test name comes from controllerArgs,
as the C original's ts_setup(argv[1]).
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])

camera = robot.getDevice("camera")
camera.enable(TIME_STEP)
ts_assert_int_equal(camera.getWidth(), 1, "Wrong camera width")
ts_assert_int_equal(camera.getHeight(), 1, "Wrong camera height")

protoNode = robot.getFromDef("TEST_PROTO")
sizeField = protoNode.getField("size")

robot.step(TIME_STEP)

values_before = camera.getImage()
ts_assert_color_in_delta(
    camera.imageGetRed(values_before, 1, 0, 0), camera.imageGetGreen(values_before, 1, 0, 0),
    camera.imageGetBlue(values_before, 1, 0, 0), 255, 255, 255,  # background
    1, "Unexpected camera color due to incorrect automatic derived parameter association: the box should be smaller.")

robot.step(TIME_STEP)

new_size = [1.0, 1.0, 0.5]
sizeField.setSFVec3f(new_size)

robot.step(TIME_STEP)

values_after = camera.getImage()
ts_assert_color_in_delta(
    camera.imageGetRed(values_after, 1, 0, 0), camera.imageGetGreen(values_after, 1, 0, 0),
    camera.imageGetBlue(values_after, 1, 0, 0), 255, 255, 255,  # background
    1, "Unexpected camera color due to incorrect automatic derived parameter association: the box size should not change.")

ts_send_success()
