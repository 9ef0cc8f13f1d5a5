"""Port of Webots' tests/api/controllers/display_attach_camera: a Display shows an attached camera's image,
its own drawings after detaching, and the camera image again when re-attached."""

from controller import Camera, Robot
from ts_assertion import ts_assert_color_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

WHITE = 0x00FFFFFF
RED = 0x00FF0000
GREEN = 0x0000FF00
BLUE = 0x000000B4


def quick_assert_color(camera, px: int, py: int, expected: int, error_msg: str) -> None:
    image = camera.getImage()
    w = camera.getWidth()
    ts_assert_color_in_delta(Camera.imageGetRed(image, w, px, py), Camera.imageGetGreen(image, w, px, py),
                             Camera.imageGetBlue(image, w, px, py), (expected >> 16) & 0xFF, (expected >> 8) & 0xFF,
                             expected & 0xFF, 1, error_msg)


robot = Robot()
ts_setup(robot)

display = robot.getDevice("display")
camera = robot.getDevice("camera")
attached_camera = robot.getDevice("attached camera")

camera.enable(TIME_STEP)
attached_camera.enable(TIME_STEP)
display.attachCamera(attached_camera)

robot.step(2 * TIME_STEP)

quick_assert_color(camera, 40, 40, BLUE, "Wrong display attaching the camera (blue shape not detected)")

robot.step(TIME_STEP)

display.detachCamera()
display.setColor(WHITE)
display.fillRectangle(0, 0, 80, 80)

robot.step(TIME_STEP)

quick_assert_color(camera, 40, 40, 0xCFCFCF, "Wrong initial display color.")

display.setAlpha(0.0)
display.fillRectangle(0, 0, 80, 80)
display.setAlpha(1.0)
display.setColor(GREEN)
display.fillRectangle(0, 0, 40, 80)

robot.step(TIME_STEP)

quick_assert_color(camera, 20, 40, 0x00CF00, "Wrong display green color after 'wb_display_draw_rectangle'.")
quick_assert_color(camera, 60, 40, RED, "Wrong display red color after 'wb_display_draw_rectangle'.")

display.attachCamera(attached_camera)

robot.step(TIME_STEP)

quick_assert_color(camera, 20, 40, 0x00CF00, "Wrong display attaching the camera (green shape not detected)")
quick_assert_color(camera, 60, 40, BLUE, "Wrong display attaching the camera (blue shape not detected)")

display.detachCamera()

robot.step(TIME_STEP)

quick_assert_color(camera, 20, 40, 0x00CF00, "Wrong display green color after detatching the camera.")
quick_assert_color(camera, 60, 40, RED, "Wrong display red color after detaching the camera.")

display.setColor(WHITE)
display.fillRectangle(0, 0, 80, 80)

robot.step(TIME_STEP)

quick_assert_color(camera, 40, 40, 0xCFCFCF, "Wrong display color after 'wb_display_draw_rectangle'.")

ts_send_success()
