"""Port of Webots' tests/api/controllers/lidar_vs_range_finder: a one-layer lidar and a cylindrical one-row
range-finder with the same field of view return the same ranges."""

from controller import Robot
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

range_finder = robot.getDevice("range-finder")
lidar = robot.getDevice("lidar")

range_finder_width = range_finder.getWidth()
range_finder_height = range_finder.getHeight()
lidar_width = lidar.getHorizontalResolution()
lidar_height = lidar.getNumberOfLayers()

ts_assert_int_equal(range_finder_width, lidar_width,
                    "The width of the range-finder should be equal to the horizontal resolution of the lidar.")
ts_assert_int_equal(range_finder_height, lidar_height,
                    "The height of the range-finder should be equal to the number of layers of the lidar.")

range_finder.enable(TIME_STEP)
lidar.enable(TIME_STEP)

robot.step(TIME_STEP)

image_range_finder = range_finder.getRangeImage()
ts_assert_pointer_not_null(image_range_finder, "Cannot retrieve range image pointer of the RangeFinder.")
image_lidar = lidar.getRangeImage()
ts_assert_pointer_not_null(image_lidar, "Cannot retrieve range image pointer of the Lidar.")
for i in range(lidar_width):
    ts_assert_double_in_delta(image_range_finder[i], image_lidar[i], 0.05,
                              "Range-finder and lidar do not return the same value (%lf (0,%d) != %lf (%d,0)).",
                              image_range_finder[i], i, image_lidar[i], i)

ts_send_success()
