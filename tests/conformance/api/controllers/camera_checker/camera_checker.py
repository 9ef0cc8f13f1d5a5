"""Port of Webots' tests/api/controllers/camera_checker: camera FOV, zoom, focus, exposure and motion-blur checks on
sampled pixels, for the camera_color* world named by the controller argument."""

import sys

from controller import Camera, Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_color_in_delta,
    ts_assert_double_equal,
    ts_assert_int_equal,
    ts_assert_int_not_equal,
    ts_send_error_and_exit,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32


def check_pixel_values(camera, samples_positions, samples_expected_colors) -> None:
    image = camera.getImage()
    width = camera.getWidth()
    for i, ((x, y), expected) in enumerate(zip(samples_positions, samples_expected_colors, strict=True)):
        red = Camera.imageGetRed(image, width, x, y)
        green = Camera.imageGetGreen(image, width, x, y)
        blue = Camera.imageGetBlue(image, width, x, y)
        ts_assert_color_in_delta(
            red, green, blue, expected[0], expected[1], expected[2], 2,
            "Wrong color (#%d) at (%d, %d) for camera \"%s\", Received color = (%d, %d, %d), Expected color = (%d, %d, %d)",
            i, x, y, camera.getName(), red, green, blue, expected[0], expected[1], expected[2])


robot = Robot()
ts_assert_boolean_equal(len(sys.argv) == 2, "camera_checker badly used. world name expected as argument.")

world = sys.argv[1]
ts_setup(robot, world)

# As in the C original, the spherical camera found below goes into a block-local variable: this outer one stays unset,
# so the spherical camera's pixels are never checked.
spherical_camera = None
if world == "camera_color_spherical":
    camera = robot.getDevice("cylindrical camera")
    ts_assert_boolean_equal(camera, "Cylindrical camera device cannot be get.")

    local_spherical_camera = robot.getDevice("spherical camera")
    ts_assert_boolean_equal(local_spherical_camera, "Spherical camera device cannot be get.")
    local_spherical_camera.enable(TIME_STEP)
else:
    camera = robot.getDevice("camera")
    ts_assert_boolean_equal(camera, "Camera device cannot be get.")

camera2 = None
if world == "camera_color_compositor":
    camera2 = robot.getDevice("camera2")
    ts_assert_boolean_equal(camera2, "Color compositor camera device cannot be get.")
    camera2.enable(TIME_STEP)

width = camera.getWidth()
height = camera.getHeight()

ts_assert_boolean_equal(width >= 1 and height >= 1, "Unexpected dimension: %dx%d", width, height)

if world == "camera_color":
    fov = camera.getFov()
    ts_assert_double_equal(fov, 0.785398, "Unexpected original FOV: %f", fov)

    camera.setFov(2 * fov)

camera.enable(TIME_STEP)

robot.step(TIME_STEP)

if world == "camera_color":
    ts_assert_double_equal(camera.getMinFov(), 1.56, "Unexpected minimum FOV value: %f", camera.getMinFov())
    ts_assert_double_equal(camera.getMaxFov(), 1.58, "Unexpected maximum FOV value: %f", camera.getMaxFov())
    fov = camera.getFov()
    ts_assert_double_equal(fov, 1.570796, "Unexpected modified FOV value: %f", fov)
else:
    ts_assert_double_equal(camera.getMinFov(), camera.getFov(), "Unexpected minimum FOV value: %f", camera.getMinFov())
    ts_assert_double_equal(camera.getMaxFov(), camera.getFov(), "Unexpected maximum FOV value: %f", camera.getMaxFov())

if world == "camera_color":
    samples_positions = (
        (width // 6 - height // 12, height // 4 - height // 8),
        (width - height // 12, height // 4 - height // 8),
        (width // 6 - height // 12, height - height // 8),
        (width - height // 12, height - height // 8))
    # brown, cyan, white, dark gray squares of the colour chart
    samples_expected_colors = ((122, 75, 65), (153, 200, 191), (202, 202, 202), (54, 54, 54))
    check_pixel_values(camera, samples_positions, samples_expected_colors)

elif world == "camera_color_spherical":
    samples_positions = ((22, 6), (230, 9), (19, 115), (234, 115), (146, 11), (81, 104))
    # yellow, red, yellow, red, pink, green-ish
    samples_expected_colors = ((207, 207, 0), (207, 0, 0), (207, 207, 0), (207, 0, 0), (203, 83, 124), (173, 198, 63))
    check_pixel_values(camera, samples_positions, samples_expected_colors)

    if spherical_camera is not None:
        samples_positions = ((22, 6), (87, 32), (118, 38), (204, 63), (146, 11), (88, 95))
        # gray, pink, purple, blue, gray, pink
        samples_expected_colors = ((175, 175, 175), (202, 93, 185), (98, 59, 131), (41, 62, 171), (147, 147, 147),
                                   (202, 93, 185))
        check_pixel_values(spherical_camera, samples_positions, samples_expected_colors)

elif world == "camera_color_compositor":
    image = camera.getImage()
    red = Camera.imageGetRed(image, width, 31, 31)
    blue = Camera.imageGetBlue(image, width, 31, 31)
    ts_assert_int_equal(
        red, 255, "Compositor not working, the image should be fully red, received %d instead of 255 for the red component",
        red)
    ts_assert_int_equal(
        blue, 0, "Compositor not working, the image should be fully red, received %d instead of 0 for the blue component",
        blue)
    image2 = camera2.getImage()
    red2 = Camera.imageGetRed(image2, camera2.getWidth(), 31, 31)
    blue2 = Camera.imageGetBlue(image2, camera2.getWidth(), 31, 31)
    ts_assert_int_equal(
        red2, red,
        "Compositor from PROTO camera not working, both images should be the same, red component are not equal (%d != %d)",
        red2, red)
    ts_assert_int_equal(
        blue2, blue,
        "Compositor from PROTO camera not working, both images should be the same, blue component are not equal (%d != %d)",
        blue2, blue)

elif world == "camera_color_motion_blur":
    image = camera.getImage()
    red = Camera.imageGetRed(image, width, 31, 31)
    ts_assert_int_equal(red, 224, "Image should be red, received %d instead of 224 for the red component", red)
    for _ in range(10):  # the red box falls
        robot.step(TIME_STEP)
    image = camera.getImage()
    red_gradient = (87, 115, 150, 188, 224)
    for i, expected in enumerate(red_gradient):
        red = Camera.imageGetRed(image, width, 31, 5 + i * 13)
        ts_assert_int_equal(red, expected, "Pixel red level should be %d, but is %d", expected, red)
    ts_assert_int_not_equal(red, 0, "Image should still contain some red")
    for _ in range(10):  # the red trail fades out
        robot.step(TIME_STEP)
    image = camera.getImage()
    red = Camera.imageGetRed(image, width, 31, 31)
    ts_assert_boolean_equal(0 <= red <= 8, "Image should not contain any red anymore, red level is %d", red)

elif world == "camera_color_focus":
    image = camera.getImage()
    ts_assert_int_equal(Camera.imageGetRed(image, width, 31, 30), 0,
                        "Upper part of the image should not contain any red without focus")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 30), 255,
                        "Upper part of the image should be entirely blue without focus")
    ts_assert_int_equal(Camera.imageGetRed(image, width, 31, 32), 227,
                        "Lower part of the image should be entirely red without focus")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 32), 0,
                        "Lower part of the image should not contain any blue without focus")
    focus = (camera.getMaxFocalDistance() + camera.getMinFocalDistance()) / 2
    camera.setFocalDistance(focus)
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    image = camera.getImage()
    ts_assert_int_not_equal(Camera.imageGetRed(image, width, 31, 30), 0,
                            "Upper part of the image should contain some red with focus")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 30), 255,
                        "Upper part of the image should be entirely blue with focus")
    ts_assert_int_not_equal(Camera.imageGetRed(image, width, 31, 32), 227,
                            "Lower part of the image should not be entirely red with focus")
    ts_assert_int_not_equal(Camera.imageGetBlue(image, width, 31, 32), 0,
                            "Lower part of the image should contain some blue with focus")

elif world == "camera_color_exposure":
    image = camera.getImage()
    ts_assert_double_equal(camera.getExposure(), 0.5, "Unexpected exposure value: %f", camera.getExposure())
    ts_assert_int_equal(Camera.imageGetRed(image, width, 31, 30), 0, "Upper part of the image should not contain any red")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 30), 255,
                        "Upper part of the image should be entirely blue without focus")
    ts_assert_int_equal(Camera.imageGetRed(image, width, 31, 32), 190, "Lower part of the image should be dark red")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 32), 0,
                        "Lower part of the image should not contain any blue")

    camera.setExposure(5)
    robot.step(TIME_STEP)
    ts_assert_double_equal(camera.getExposure(), 5, "Unexpected exposure value: %f", camera.getExposure())

    image = camera.getImage()
    ts_assert_int_equal(Camera.imageGetRed(image, width, 31, 30), 0, "Upper part of the image should not contain any red")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 30), 255, "Upper part of the image should be entirely blue")
    ts_assert_int_equal(Camera.imageGetRed(image, width, 31, 32), 255, "Lower part of the image should be red saturated")
    ts_assert_int_equal(Camera.imageGetBlue(image, width, 31, 32), 0,
                        "Lower part of the image should not contain any blue")
else:
    ts_send_error_and_exit("camera_checker doesn't support this world: %s", world)

ts_send_success()
