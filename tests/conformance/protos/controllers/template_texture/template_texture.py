"""Port of Webots' tests/protos/controllers/template_texture: a Lua template PROTO draws a green PNG with the `gd`
module into a file and textures a plane with it; one camera sees that plane green, another the white background.

The C original calls ts_setup(argv[1]), but the only stored world (R2022a) gives the controller no argument: the
port falls back on the controller's name, the test name of Webots' suite in that case.
"""

import sys

from controller import Robot
from ts_assertion import ts_assert_color_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot, sys.argv[1] if len(sys.argv) > 1 else None)  # give the controller args

camera1 = robot.getDevice("camera1")
camera2 = robot.getDevice("camera2")

ts_assert_int_equal(camera1.getWidth(), 1, "Wrong camera1 width")
ts_assert_int_equal(camera1.getHeight(), 1, "Wrong camera1 height")
ts_assert_int_equal(camera2.getWidth(), 1, "Wrong camera2 width")
ts_assert_int_equal(camera2.getHeight(), 1, "Wrong camera2 height")

camera1.enable(TIME_STEP)
camera2.enable(TIME_STEP)

robot.step(TIME_STEP)

image1 = camera1.getImage()
ts_assert_color_in_delta(camera1.imageGetRed(image1, 1, 0, 0), camera1.imageGetGreen(image1, 1, 0, 0),
                         camera1.imageGetBlue(image1, 1, 0, 0), 0, 207, 0,  # TemplateTexture PROTO plane
                         1, "Unexpected camera1 color. The TemplateTexture PROTO should produce a green plane.")

image2 = camera2.getImage()
ts_assert_color_in_delta(camera2.imageGetRed(image2, 1, 0, 0), camera2.imageGetGreen(image2, 1, 0, 0),
                         camera2.imageGetBlue(image2, 1, 0, 0), 255, 255, 255,  # background
                         1, "Unexpected camera side color. The side of the capsule should be visible")

ts_send_success()
