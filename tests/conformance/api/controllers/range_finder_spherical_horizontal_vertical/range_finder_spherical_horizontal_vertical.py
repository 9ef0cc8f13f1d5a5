"""Port of Webots' tests/api/controllers/range_finder_spherical_horizontal_vertical: a one-row cylindrical
range-finder and a one-column one turned by 90 degrees return the same depths."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

horizontal_range_finder = robot.getDevice("horizontal_range_finder")
vertical_range_finder = robot.getDevice("vertical_range_finder")

width = horizontal_range_finder.getWidth()
height = vertical_range_finder.getHeight()
ts_assert_int_equal(width, height,
                    "The width of the horizontal range-finder should be equal to the height of the vertical range-finder.")

horizontal_range_finder.enable(TIME_STEP)
vertical_range_finder.enable(TIME_STEP)

robot.step(TIME_STEP)

image_horizontal = horizontal_range_finder.getRangeImage()
image_vertical = vertical_range_finder.getRangeImage()
for i in range(width):
    ts_assert_double_in_delta(image_horizontal[i], image_vertical[i], 0.05,
                              "Horizontal and vertical range-finder do not return the same value (%lf (0,%d) != %lf (%d,0)).",
                              image_horizontal[i], i, image_vertical[i], i)

ts_send_success()
