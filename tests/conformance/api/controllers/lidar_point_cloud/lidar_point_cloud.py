"""Port of Webots' tests/api/controllers/lidar_point_cloud: a 3-layer lidar's range image and point cloud are zero
before its first sample, then agree with each other, per layer, and see an inclined plane."""

import math

from controller import Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_equal,
    ts_assert_double_in_delta,
    ts_assert_double_is_bigger,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_assert_vec3_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

lidar = robot.getDevice("lidar")

resolution = lidar.getHorizontalResolution()
number_of_layers = lidar.getNumberOfLayers()

ts_assert_int_equal(resolution, 512, "The horizontal resolution of the lidar should be '512'.")
ts_assert_int_equal(number_of_layers, 3, "The number of layers of the lidar should be '3'.")

lidar.enable(2 * TIME_STEP)
lidar.enablePointCloud()

robot.step(TIME_STEP)

image_lidar = lidar.getRangeImage()
ts_assert_pointer_not_null(image_lidar, "Cannot retrieve lidar image pointer (at step 1).")
point_cloud = lidar.getPointCloud()
ts_assert_pointer_not_null(point_cloud, "Cannot retrieve point cloud image pointer (at step 1).")
for i in range(resolution * number_of_layers):
    x = point_cloud[i].x
    y = point_cloud[i].y
    z = point_cloud[i].z
    ts_assert_vec3_equal(x, y, z, 0.0, 0.0, 0.0, "Point cloud shouldn't be available one step after enabling the lidar.")
    ts_assert_double_equal(image_lidar[i], 0.0, "Range image shouldn't be available one step after enabling the lidar.")

robot.step(TIME_STEP)

image_lidar = lidar.getRangeImage()
ts_assert_pointer_not_null(image_lidar, "Cannot retrieve lidar image pointer (at step 2).")
point_cloud = lidar.getPointCloud()
ts_assert_pointer_not_null(point_cloud, "Cannot retrieve point cloud image pointer (at step 2).")
point_cloud_found = False
range_image_found = False
for i in range(resolution * number_of_layers):
    x = point_cloud[i].x
    y = point_cloud[i].y
    z = point_cloud[i].z
    if x != 0.0 or y != 0.0 or z != 0.0:
        point_cloud_found = True
    if image_lidar[i] != 0.0:
        range_image_found = True
    if point_cloud_found and range_image_found:
        break
ts_assert_boolean_equal(point_cloud_found, "Point cloud should should be available two steps after enabling the lidar.")
ts_assert_boolean_equal(range_image_found, "Range image should should be available two steps after enabling the lidar.")

image_lidar = lidar.getRangeImage()
ts_assert_pointer_not_null(image_lidar, "Cannot retrieve lidar image pointer (at step 3).")
point_cloud = lidar.getPointCloud()
ts_assert_pointer_not_null(point_cloud, "Cannot retrieve point cloud image pointer (at step 3).")
for i in range(resolution * number_of_layers):
    x = point_cloud[i].x
    y = point_cloud[i].y
    z = point_cloud[i].z
    if not math.isinf(x) and not math.isinf(y) and not math.isinf(z):
        d = math.sqrt(x * x + y * y + z * z)
        ts_assert_double_in_delta(image_lidar[i], d, 0.05,
                                  "Point cloud and range image does not correspond, Received value = %f, Expected value = %f",
                                  image_lidar[i], d)

layer_image_lidar = lidar.getLayerRangeImage(2)
ts_assert_pointer_not_null(layer_image_lidar, "Cannot retrieve lidar image pointer for layer 2.")
layer_point_cloud = lidar.getLayerPointCloud(2)
ts_assert_pointer_not_null(layer_point_cloud, "Cannot retrieve point cloud pointer for layer 2.")
for i in range(resolution):
    ts_assert_double_in_delta(layer_image_lidar[i], image_lidar[i + 2 * resolution], 0.001,
                              "Layer image is not equivalent to raw image.")
    ts_assert_double_in_delta(layer_point_cloud[i].x, point_cloud[i + 2 * resolution].x, 0.001,
                              "Layer point cloud is not equivalent to raw point cloud.")

layer0_image_lidar = lidar.getLayerRangeImage(0)
ts_assert_pointer_not_null(layer0_image_lidar, "Cannot retrieve lidar image pointer for layer 0.")
layer1_image_lidar = lidar.getLayerRangeImage(1)
ts_assert_pointer_not_null(layer1_image_lidar, "Cannot retrieve lidar image pointer for layer 1.")
ts_assert_double_is_bigger(layer0_image_lidar[450], layer1_image_lidar[450],
                           "Lidar layer 0 should see the inclined plan farther than lidar 1.")

ts_send_success()
