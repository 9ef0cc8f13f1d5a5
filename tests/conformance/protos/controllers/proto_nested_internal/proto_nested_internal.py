"""Port of Webots' tests/protos/controllers/proto_nested_internal: a box defined inside nested PROTOs (a PROTO field
connected with IS to a node in the slot of an internal PROTO) is visible to a 1-pixel camera, and changing the top
PROTO's boxSize regenerates it (the camera then sees the background). With "proto_nested_fixed" only the load is
checked.

Run by the worlds proto_nested_fixed, proto_nested_internal_1 and proto_nested_internal_2 (and, in Webots, the
derived_proto_nested_internal_* ones); the test name comes from controllerArgs, as the C original's ts_setup(argv[1]).
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args
loadTest = sys.argv[1] == "proto_nested_fixed"
colored = sys.argv[1] == "derived_proto_nested_internal_4"

camera = robot.getDevice("camera")
camera.enable(TIME_STEP)
ts_assert_int_equal(camera.getWidth(), 1, "Wrong camera width")
ts_assert_int_equal(camera.getHeight(), 1, "Wrong camera height")

sizeField = None
if not loadTest:
    protoNode = robot.getFromDef("TEST_PROTO")
    sizeField = protoNode.getField("boxSize")

robot.step(TIME_STEP)

redComponent = 207 if colored else 0

values_before = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(values_before, 1, 0, 0), camera.imageGetGreen(values_before, 1, 0, 0),
                         camera.imageGetBlue(values_before, 1, 0, 0), redComponent, 0, 0,  # box
                         1, "Unexpected camera color. The box should be visible.")

if loadTest:
    ts_send_success()

robot.step(TIME_STEP)

new_size = [0.4, 0.4, 1]
sizeField.setSFVec3f(new_size)

robot.step(TIME_STEP)

values_after = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(values_after, 1, 0, 0), camera.imageGetGreen(values_after, 1, 0, 0),
                         camera.imageGetBlue(values_after, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera color after resizing. The box should not be visible.")

ts_send_success()
