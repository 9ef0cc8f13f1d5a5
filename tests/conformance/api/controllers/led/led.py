"""Port of Webots' tests/api/controllers/led: RGB LEDs colour their Phong and PBR shapes and their SpotLight."""

from controller import Robot
from ts_assertion import ts_assert_int_equal, ts_assert_int_is_bigger, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)
led_phong = robot.getDevice("phong")
led_pbr = robot.getDevice("pbr")
led_light = robot.getDevice("light")
camera = robot.getDevice("camera")
led_phong.set(0xFF0000)
led_pbr.set(0xFF0000)
led_light.set(0xFF0000)
camera.enable(TIME_STEP)
robot.step(TIME_STEP)
robot.step(TIME_STEP)

ts_assert_int_equal(led_phong.get(), 0xFF0000, "The phong LED has the wrong stored color.")
ts_assert_int_equal(led_pbr.get(), 0xFF0000, "The pbr LED has the wrong stored color.")
ts_assert_int_equal(led_light.get(), 0xFF0000, "The light LED has the wrong stored color.")

image = camera.getImage()
phong_red = camera.imageGetRed(image, 128, 19, 64)
pbr_red = camera.imageGetRed(image, 128, 64, 64)
light_red = camera.imageGetRed(image, 128, 103, 61)
phong_green = camera.imageGetGreen(image, 128, 19, 64)
phong_blue = camera.imageGetBlue(image, 128, 19, 64)
pbr_green = camera.imageGetGreen(image, 128, 64, 64)
pbr_blue = camera.imageGetBlue(image, 128, 64, 64)

# Fuzzy colour checks, for HDR.
ts_assert_int_is_bigger(phong_red, 0xAA, "The phong material should be bright red")
ts_assert_int_is_bigger(pbr_red, 0xAA, "The pbr material should be bright red")
ts_assert_int_is_bigger(light_red, 0x80, "The spotlight's illuminated circle should be bright red")
# The spheres are only red.
ts_assert_int_equal(phong_green, 0x00, "The phong material should have no green")
ts_assert_int_equal(phong_blue, 0x00, "The phong material should have no blue")
ts_assert_int_equal(pbr_green, 0x00, "The pbr material should have no green")
ts_assert_int_equal(pbr_blue, 0x00, "The pbr material should have no blue")

ts_send_success()
