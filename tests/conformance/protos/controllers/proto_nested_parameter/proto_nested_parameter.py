"""Port of Webots' tests/protos/controllers/proto_nested_parameter (regression test for Webots issue 908): a PROTO
instance given as the MFNode parameter of a template PROTO keeps following the changes of its own fields (boxSize,
translation) and of the parent's translation, which regenerates the parent, as a 1-pixel camera sees.

Run by the worlds proto_nested_parameter and its Lua variant; the test name comes from controllerArgs, as the C
original's ts_setup(argv[1]); its spaces become underscores because the runner's result lines are space-separated.
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args

camera = robot.getDevice("camera")
camera.enable(TIME_STEP)
ts_assert_int_equal(camera.getWidth(), 1, "Wrong camera width")
ts_assert_int_equal(camera.getHeight(), 1, "Wrong camera height")

protoNode = robot.getFromDef("TEST_PROTO")
translationField = protoNode.getField("translation")

parameterNode = robot.getFromDef("TEST_PARAMETER")
parameterTranslationField = parameterNode.getField("translation")
sizeField = parameterNode.getField("boxSize")
robot.step(TIME_STEP)

valuesA = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(valuesA, 1, 0, 0), camera.imageGetGreen(valuesA, 1, 0, 0),
                         camera.imageGetBlue(valuesA, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera color. Box should be located at position (-1, -1, -1).")

parentTranslation = [0, 0, 0]
translationField.setSFVec3f(parentTranslation)

robot.step(TIME_STEP)

valuesB = camera.getImage()
ts_assert_color_in_delta(
    camera.imageGetRed(valuesB, 1, 0, 0), camera.imageGetGreen(valuesB, 1, 0, 0),
    camera.imageGetBlue(valuesB, 1, 0, 0), 0, 0, 0,  # box
    1, "Unexpected camera color after changing parent translation. Box should be located at position (0, 0, 0).")

size = [0.5, 0.5, 1]
sizeField.setSFVec3f(size)

robot.step(TIME_STEP)

valuesC = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(valuesC, 1, 0, 0), camera.imageGetGreen(valuesC, 1, 0, 0),
                         camera.imageGetBlue(valuesC, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera color after resizing the Box. Box should not be visible in the camera "
                         "image.")

parameterTranslation = [-0.25, 0.25, 0]
parameterTranslationField.setSFVec3f(parameterTranslation)

robot.step(TIME_STEP)

valuesD = camera.getImage()
ts_assert_color_in_delta(
    camera.imageGetRed(valuesD, 1, 0, 0), camera.imageGetGreen(valuesD, 1, 0, 0),
    camera.imageGetBlue(valuesD, 1, 0, 0), 0, 0, 0,  # box
    1, "Unexpected camera color after changing parameter translation. Box should be visible in the camera image.")

ts_send_success()
