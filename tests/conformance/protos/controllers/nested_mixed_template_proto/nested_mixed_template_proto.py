"""Port of Webots' tests/protos/controllers/nested_mixed_template_proto: regeneration of a template PROTO given as the
parameter of another PROTO: changing the box size regenerates it, and its 'translation' parameter connected with IS is
still redirected after the regeneration (seen by two 1-pixel cameras).

Run by the worlds nested_mixed_template_proto (and its Lua variant) and proto_nested_2 (a non-template SolidCylinder
in a slot of a PROTO with an internal PROTO); the test name comes from controllerArgs, as the C original's
ts_setup(argv[1]); its spaces become underscores because the runner's result lines are space-separated.
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32


def check_object_status(camera, visible, message):
    expected = 0 if visible else 255
    values = camera.getImage()
    ts_assert_color_in_delta(camera.imageGetRed(values, 1, 0, 0), camera.imageGetGreen(values, 1, 0, 0),
                             camera.imageGetBlue(values, 1, 0, 0), expected, expected, expected, 1, message)


robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args

cameraX = robot.getDevice("cameraX")
cameraY = robot.getDevice("cameraY")
cameraX.enable(TIME_STEP)
cameraY.enable(TIME_STEP)
ts_assert_int_equal(cameraX.getWidth(), 1, "Wrong cameraX width")
ts_assert_int_equal(cameraX.getHeight(), 1, "Wrong cameraX height")
ts_assert_int_equal(cameraY.getWidth(), 1, "Wrong cameraY width")
ts_assert_int_equal(cameraY.getHeight(), 1, "Wrong cameraY height")

protoNode = robot.getFromDef("TEST_PROTO")
tField = protoNode.getField("translation")
xField = protoNode.getField("xSize")

robot.step(TIME_STEP)

if sys.argv[1].startswith("nested_mixed_template_proto"):
    check_object_status(cameraX, False, "Unexpected cameraX color. The box should not be visible.")
    check_object_status(cameraY, False, "Unexpected cameraY color. The box should not be visible.")
    xField.setSFFloat(0.5)

    robot.step(TIME_STEP)

    check_object_status(cameraX, True, "Unexpected cameraX color after changing x size. The box should be visible.")
    check_object_status(cameraY, False, "Unexpected cameraY color after changing x size. The box not should be visible.")

    newPosition = [0.0, 0.2, 0.0]
    tField.setSFVec3f(newPosition)

    robot.step(TIME_STEP)

    check_object_status(cameraX, False,
                        "Unexpected cameraX color after changing translation. The box should not be visible.")
    check_object_status(cameraY, True, "Unexpected cameraY color after changing translation. The box should be visible.")

else:  # argv[1] == "proto_nested_2"
    check_object_status(cameraX, True, "Unexpected cameraX color. The cylinder should be visible.")
    check_object_status(cameraY, False, "Unexpected cameraY color. The cylinder should not be visible.")

    newPosition = [0.0, 0.2, 0.0]
    tField.setSFVec3f(newPosition)

    robot.step(TIME_STEP)

    check_object_status(cameraX, False,
                        "Unexpected cameraX color after changing translation. The cylinder should not be visible.")
    check_object_status(cameraY, True,
                        "Unexpected cameraY color after changing translation. The cylinder should be visible.")

ts_send_success()
