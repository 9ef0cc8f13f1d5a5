"""Port of Webots' tests/api/controllers/range_finder_horizontal_spherical_projection: a 360-degree cylindrical
range-finder looking at a floor reads the same depth at its sub-cameras' centres and junctions."""

from controller import RangeFinder, Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

range_finder = robot.getDevice("range-finder")
width = range_finder.getWidth()
height = range_finder.getHeight()

range_finder.enable(TIME_STEP)

robot.step(TIME_STEP)

image = range_finder.getRangeImage()
for i in range(4):
    x1 = int(width * ((i * 2.0 + 1.0) / 8.0) - 1)
    x2 = int(width * ((i * 2.0 + 2.0) / 8.0) - 1)
    sub_cameras_junction_depth = RangeFinder.rangeImageGetDepth(image, width, x1, height - 10)
    sub_camera_center_depth = RangeFinder.rangeImageGetDepth(image, width, x2, height - 10)
    ts_assert_double_in_delta(
        sub_cameras_junction_depth, sub_camera_center_depth, 0.05,
        "Depths at the sub-camera center and sub-cameras junction are not equal (%lf (%d,%d) != %lf (%d,%d)).",
        sub_cameras_junction_depth, x1, height - 10, sub_camera_center_depth, x2, height - 10)

ts_send_success()
