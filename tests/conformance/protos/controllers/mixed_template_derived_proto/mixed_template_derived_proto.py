"""Port of Webots' tests/protos/controllers/mixed_template_derived_proto: a template PROTO derived from a template
PROTO, whose parameters reach the base by template value (dxSize), by IS (dySize, translation); two 1-pixel
cameras see the box appear as each size grows and disappear when it is moved away.

Run by mixed_template_derived_proto.wbt and its Lua variant; the test name comes from controllerArgs, as the C
original's ts_setup(argv[1]).
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])

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
xField = protoNode.getField("dxSize")
yField = protoNode.getField("dySize")


def check(camera, expected, message):
    values = camera.getImage()
    ts_assert_color_in_delta(camera.imageGetRed(values, 1, 0, 0), camera.imageGetGreen(values, 1, 0, 0),
                             camera.imageGetBlue(values, 1, 0, 0), expected, expected, expected, 1, message)


BACKGROUND = 255
BOX = 0

robot.step(TIME_STEP)

check(cameraX, BACKGROUND, "Unexpected cameraX color. The box should not be visible.")
check(cameraY, BACKGROUND, "Unexpected cameraY color. The box should not be visible.")

yField.setSFFloat(0.5)

robot.step(TIME_STEP)

check(cameraX, BACKGROUND, "Unexpected cameraX after changing y size. The box should not be visible.")
check(cameraY, BOX, "Unexpected cameraY color after changing y size. The box should be visible.")

xField.setSFFloat(0.5)

robot.step(TIME_STEP)

check(cameraX, BOX, "Unexpected cameraX after changing x size. The box should be visible.")
check(cameraY, BOX, "Unexpected cameraY color after changing x size. The box should be visible.")

robot.step(TIME_STEP)

newTranslation = [-2, -2, -2]
tField.setSFVec3f(newTranslation)

robot.step(TIME_STEP)

check(cameraX, BACKGROUND, "Unexpected cameraX after changing translation. The box should not be visible.")
check(cameraY, BACKGROUND, "Unexpected cameraY color after changing translation. The box should not be visible.")

ts_send_success()
