"""Port of Webots' tests/api/controllers/lidar_rotating: a rotating lidar's image agrees with a fixed lidar's where
their fields of view overlap."""

import math

from controller import Robot
from ts_assertion import (
    ts_assert_double_is_bigger,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

fixed_lidar = robot.getDevice("lidar")
rotating_lidar = robot.getDevice("rotating lidar")

fixed_lidar_resolution = fixed_lidar.getHorizontalResolution()
rotating_lidar_resolution = rotating_lidar.getHorizontalResolution()

ts_assert_int_equal(4 * fixed_lidar_resolution, rotating_lidar_resolution,
                    "The resolution of the rotating lidar should be 4 times bigger than the resolution of the fixed one.")

fixed_lidar.enable(TIME_STEP)
rotating_lidar.enable(TIME_STEP)

for _ in range(50):
    robot.step(TIME_STEP)

image_fixed_lidar = fixed_lidar.getRangeImage()
ts_assert_pointer_not_null(image_fixed_lidar, "Cannot retrieve range image pointer of the 'fixed' lidar.")
image_rotating_lidar = rotating_lidar.getRangeImage()
ts_assert_pointer_not_null(image_rotating_lidar, "Cannot retrieve range image pointer of the 'rotating' lidar.")
diff_sum = 0.0

for i in range(fixed_lidar_resolution):
    if not math.isinf(image_rotating_lidar[i]) and not math.isinf(image_fixed_lidar[i]):
        diff_sum += abs(image_rotating_lidar[i] - image_fixed_lidar[i])

ts_assert_double_is_bigger(15, diff_sum,
                           "There is too much difference in the image resulting from the fixed and from the rotating lidar, "
                           "overlapping part should be very similar")

ts_send_success()
