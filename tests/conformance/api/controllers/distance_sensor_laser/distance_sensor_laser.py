"""Port of Webots' tests/api/controllers/distance_sensor_laser: laser distances and the red spot seen by a camera."""

from controller import Camera, Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

ds0 = robot.getDevice("ds0")
ds1 = robot.getDevice("ds1")
camera = robot.getDevice("camera")

ds0.enable(TIME_STEP)
ds1.enable(TIME_STEP)
camera.enable(TIME_STEP)

robot.step(TIME_STEP)

value = ds0.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in laser mode doesn't return the right distance when hitting an object.")

value = ds1.getValue()
ts_assert_double_in_delta(value, 1000.0, 0.001,
                          "The distance sensor in laser mode doesn't return the max range when missing an object.")

robot.step(TIME_STEP)

# The laser beam is drawn where it hits: the camera looking at the spot sees its red.
image = camera.getImage()
channel = Camera.imageGetRed(image, 1, 0, 0)
ts_assert_int_equal(channel, 0xEF, "The laser beam of the distance sensor in laser mode isn't visible from a camera.")
channel = Camera.imageGetGreen(image, 1, 0, 0)
ts_assert_int_equal(channel, 0, "The laser beam of the distance sensor in laser mode isn't visible from a camera.")
channel = Camera.imageGetBlue(image, 1, 0, 0)
ts_assert_int_equal(channel, 0, "The laser beam of the distance sensor in laser mode isn't visible from a camera.")

ts_send_success()
