"""Port of Webots' tests/protos/controllers/proto_nested_parameter_2 (regression test for Webots issue #4075): a PROTO
instance DEF'd in the default value of another PROTO's MFNode field (DEF TEST_PROTO NestedColorBoxShape) is found by
getFromDef, and setting its color reaches the nested ColorBoxShape, as a 1-pixel camera sees."""

from controller import Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)  # give the controller args

camera = robot.getDevice("camera")
camera.enable(TIME_STEP)

protoNode = robot.getFromDef("TEST_PROTO")
colorField = protoNode.getField("color")

robot.step(TIME_STEP)

valuesA = camera.getImage()
ts_assert_color_in_delta(camera.imageGetRed(valuesA, 1, 0, 0), camera.imageGetGreen(valuesA, 1, 0, 0),
                         camera.imageGetBlue(valuesA, 1, 0, 0), 54, 54, 54,  # initial box color
                         1, "Unexpected initial camera color")

newColor = [0.0, 1.0, 0.0]
colorField.setSFColor(newColor)

robot.step(TIME_STEP)

valuesB = camera.getImage()
print("%d %d %d" % (camera.imageGetRed(valuesB, 1, 0, 0), camera.imageGetBlue(valuesB, 1, 0, 0),
                    camera.imageGetGreen(valuesB, 1, 0, 0)))

ts_assert_color_in_delta(camera.imageGetRed(valuesB, 1, 0, 0), camera.imageGetGreen(valuesB, 1, 0, 0),
                         camera.imageGetBlue(valuesB, 1, 0, 0), 0, 207, 0,  # modified box color
                         1, "Unexpected camera color after changing box color to green.")

ts_send_success()
