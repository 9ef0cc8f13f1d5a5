"""Port of Webots' tests/api/controllers/supervisor_node_set_visibility: Node.setVisibility hides a shape from one
camera only, shows it again, and a removed shape disappears from every camera."""

from controller import Camera, Supervisor
from ts_assertion import ts_assert_color_in_delta, ts_send_success, ts_setup

TIME_STEP = 32


def quick_assert_color(camera, px: int, py: int, expected: int, error_msg: str) -> None:
    image = camera.getImage()
    w = camera.getWidth()

    ts_assert_color_in_delta(Camera.imageGetRed(image, w, px, py), Camera.imageGetGreen(image, w, px, py),
                             Camera.imageGetBlue(image, w, px, py), (expected >> 16) & 0xFF, (expected >> 8) & 0xFF,
                             expected & 0xFF, 1, error_msg)


robot = Supervisor()
ts_setup(robot)

camera0 = robot.getDevice("camera0")
camera1 = robot.getDevice("camera1")

camera0.enable(TIME_STEP)
camera1.enable(TIME_STEP)

robot.step(TIME_STEP)

quick_assert_color(camera0, 31, 31, 0xFF0000, "Both cameras should see the red box at the beginning.\n")
quick_assert_color(camera1, 31, 31, 0xFF0000, "Both cameras should see the red box at the beginning.\n")

camera_node = robot.getFromDef("CAMERA0")
camera1_node = robot.getFromDef("CAMERA1")
red_box_node = robot.getFromDef("RED_BOX")
green_box_node = robot.getFromDef("GREEN_BOX")

red_box_node.setVisibility(camera_node, False)

robot.step(TIME_STEP)

quick_assert_color(camera0, 31, 31, 0x00FF00, "Camera 0 should not see the red box after it was hidden from this camera.\n")
quick_assert_color(camera1, 31, 31, 0xFF0000, "Camera 1 should still see the red box after it was hidden from camera 0.\n")

red_box_node.setVisibility(camera_node, True)

robot.step(TIME_STEP)

quick_assert_color(camera0, 31, 31, 0xFF0000,
                   "Both cameras should see the red box again after it was shown from camera 0.\n")
quick_assert_color(camera1, 31, 31, 0xFF0000,
                   "Both cameras should see the red box again after it was shown from camera 0.\n")

green_box_node.setVisibility(camera1_node, False)
red_box_node.setVisibility(camera_node, False)
red_box_node.remove()

robot.step(TIME_STEP)

quick_assert_color(camera0, 31, 31, 0x00FF00, "Camera 0 should not see the red box after it has been removed.\n")
quick_assert_color(camera1, 31, 31, 0x0000FF,
                   "Camera 1 should only see the background after red box has been removed and green box has been "
                   "hidden.\n")

ts_send_success()
