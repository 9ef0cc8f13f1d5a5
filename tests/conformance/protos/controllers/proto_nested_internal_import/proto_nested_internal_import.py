"""Port of Webots' tests/protos/controllers/proto_nested_internal_import: a node imported into a PROTO's MFNode
parameter ("sensorsSlot"), which the PROTO passes through IS into the slot of an internal PROTO, appears (a
1-pixel camera sees the box), and resizing the imported box by its DEF name ("BOX") from the supervisor hides it.

The test name comes from controllerArgs, as the C original's ts_setup(argv[1]).
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
slotField = protoNode.getField("sensorsSlot")

robot.step(TIME_STEP)

valuesA = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(valuesA, 1, 0, 0), camera.imageGetGreen(valuesA, 1, 0, 0),
                         camera.imageGetBlue(valuesA, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera color. The box should not be visible.")

robot.step(TIME_STEP)

slotField.importMFNodeFromString(
    0, "DEF SHAPE Shape { appearance Appearance { material Material {} } geometry DEF BOX Box { size 1 1 1 } }")

robot.step(TIME_STEP)

valuesB = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(valuesB, 1, 0, 0), camera.imageGetGreen(valuesB, 1, 0, 0),
                         camera.imageGetBlue(valuesB, 1, 0, 0), 0, 0, 0,  # box
                         1, "Unexpected camera color after importing node. The box should be visible.")

robot.step(TIME_STEP)

boxNode = robot.getFromDef("BOX")
sizeField = boxNode.getField("size")
newSize = [0.5, 1, 1]
sizeField.setSFVec3f(newSize)

robot.step(TIME_STEP)

valuesC = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(valuesC, 1, 0, 0), camera.imageGetGreen(valuesC, 1, 0, 0),
                         camera.imageGetBlue(valuesC, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera color after resizing. The box should not be visible.")

ts_send_success()
