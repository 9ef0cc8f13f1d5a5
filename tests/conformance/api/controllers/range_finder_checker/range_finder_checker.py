"""Port of Webots' tests/api/controllers/range_finder_checker: depths sampled in the range_finder (planar) and
range_finder_spherical (cylindrical) worlds, named by the controller argument, then saving the image."""

import math
import sys

from controller import RangeFinder, Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_send_error_and_exit,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
INFINITY = math.inf

robot = Robot()
ts_assert_boolean_equal(len(sys.argv) == 2, "range_finder_checker badly used. world name expected as argument.")

ts_setup(robot, sys.argv[1])

range_finder = robot.getDevice("range-finder")
ts_assert_boolean_equal(range_finder, "RangeFinder device cannot be get.")

width = range_finder.getWidth()
height = range_finder.getHeight()

ts_assert_boolean_equal(width >= 1 and height >= 1, "Unexpected dimension: %dx%d", width, height)

range_finder.enable(TIME_STEP)

robot.step(TIME_STEP)

if sys.argv[1] == "range_finder":
    image = range_finder.getRangeImage()
    samples_positions = (
        (width // 2, 0),
        (0, height // 2),
        (width // 2, height // 2),
        (width - 1, height // 2),
        (width // 2, height - 1))
    # no hit, no hit, the transparent plane, a plane, the ElevationGrid
    samples_expected_values = (INFINITY, INFINITY, 2.0, 2.0, 2.0)
    for (x, y), expected in zip(samples_positions, samples_expected_values, strict=True):
        v = RangeFinder.rangeImageGetDepth(image, width, x, y)
        ts_assert_double_in_delta(v, expected, 0.015, "Wrong value at (%d, %d), Received value = %f, Expected value = %f",
                                  x, y, v, expected)
elif sys.argv[1] == "range_finder_spherical":
    image = range_finder.getRangeImage()
    samples_positions = (
        (0, height // 2),
        (width // 4, height // 2),
        (width // 2, height // 2),
        (3 * width // 4, height // 2),
        (width - 1, height // 2))
    # the plane behind, no hit, the plane in front, no hit, the plane behind
    samples_expected_values = (2.0, INFINITY, 2.0, INFINITY, 2.0)
    for (x, y), expected in zip(samples_positions, samples_expected_values, strict=True):
        v = RangeFinder.rangeImageGetDepth(image, width, x, y)
        ts_assert_double_in_delta(v, expected, 0.015, "Wrong value at (%d, %d), Received value = %f, Expected value = %f",
                                  x, y, v, expected)
else:
    ts_send_error_and_exit("range_finder_checker doesn't support this world: %s", sys.argv[1])

ts_assert_boolean_equal(range_finder.saveImage("test.hdr", 100) != -1,
                        "range_finder image did not save correctly (wb_range_finder_save_image returned -1)")

ts_send_success()
