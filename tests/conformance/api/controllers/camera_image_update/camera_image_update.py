"""Port of Webots' tests/api/controllers/camera_image_update: no image before the first sample, each camera refreshed
at its own period, and a supervisor's colour change seen at the next refresh (C's NULL image is Python's None)."""

from controller import Supervisor
from ts_assertion import (
    ts_assert_color_in_delta,
    ts_assert_pointer_not_null,
    ts_assert_pointer_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

color_disabled = [0.0, 0.0, 0.0]
color0 = [0.8, 0.8, 0.8]
color1 = [0.0, 0.7, 0.5]
color2 = [0.7, 0.5, 0.7]
color3 = [0.25, 0.25, 0.7]

robot = Supervisor()


def check_camera_image(camera, width, expected_color):
    image = camera.getImage()
    ts_assert_pointer_not_null(image, "Cannot retrieve image pointer.")
    red = camera.imageGetRed(image, width, 0, 0)
    green = camera.imageGetGreen(image, width, 0, 0)
    blue = camera.imageGetBlue(image, width, 0, 0)
    exp_red, exp_green, exp_blue = (int(255.0 * c + 0.49) for c in expected_color)  # round to the closest int
    ts_assert_color_in_delta(red, green, blue, exp_red, exp_green, exp_blue, 20,
                             "Wrong color at time %f for camera %s: expected [%d %d %d] but received [%d %d %d]\n",
                             robot.getTime(), camera.getName(), exp_red, exp_green, exp_blue, red, green, blue)


ts_setup(robot)

color_field = robot.getFromDef("MATERIAL").getField("diffuseColor")

camera0 = robot.getDevice("camera0")
camera1 = robot.getDevice("camera1")
width0 = camera0.getWidth()
width1 = camera1.getWidth()

ts_assert_pointer_null(camera0.getImage(), "Before camera enable and robot step, camera0 should have a NULL image.")
ts_assert_pointer_null(camera1.getImage(), "Before camera enable and robot step, camera1 should have a NULL image.")

camera0.enable(TIME_STEP)
camera1.enable(2 * TIME_STEP)

ts_assert_pointer_null(camera0.getImage(), "After camera enable and before robot step, camera0 should have a NULL image.")
ts_assert_pointer_null(camera1.getImage(), "After camera enable and before robot step, camera1 should have a NULL image.")

robot.step(TIME_STEP)

ts_assert_pointer_not_null(camera0.getImage(), "After camera enable and after robot step, camera0 should have a valid "
                           "image.")
ts_assert_pointer_not_null(camera1.getImage(), "After camera enable and after robot step, camera1 should have a valid "
                           "image.")

check_camera_image(camera0, width0, color0)  # camera0 updated
check_camera_image(camera1, width1, color_disabled)  # camera1 not updated

for new_color, previous in ((color1, color0), (color2, color1), (color3, color2)):
    robot.step(TIME_STEP)
    check_camera_image(camera0, width0, previous)  # camera0 updated
    check_camera_image(camera1, width1, previous)  # camera1 updated
    color_field.setSFColor(new_color)
    robot.step(TIME_STEP)
    check_camera_image(camera0, width0, new_color)  # camera0 updated
    check_camera_image(camera1, width1, previous)  # camera1 not updated

robot.step(TIME_STEP)
check_camera_image(camera0, width0, color3)  # camera0 updated
check_camera_image(camera1, width1, color3)  # camera1 updated

ts_send_success()
