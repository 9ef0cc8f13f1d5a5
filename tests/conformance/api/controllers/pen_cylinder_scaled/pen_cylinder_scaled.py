"""Port of Webots' tests/api/controllers/pen_cylinder_scaled: painting with a Pen on a rotated and scaled cylinder (the same texture on its faces and its side).

The pen writes one stroke, moves along its slider, writes again, twice; after each stroke the camera must see
no more coloured (not grey) pixels than a bound, and the ink's colour at a given pixel.
"""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_assert_color_in_delta, ts_send_success, ts_setup
from ts_pen import computeNumColorPixels, getPixelColor

TIME_STEP = 32
width = 64
height = 64

robot = Robot()
ts_setup(robot)
numColorPixels = -1

pen = robot.getDevice("pen")
pen.setInkColor(0xFA8A0A, 1.0)
pen.write(True)

camera = robot.getDevice("camera")
camera.enable(TIME_STEP)

motor = robot.getDevice("linear motor")

position_sensor = robot.getDevice("position sensor")
position_sensor.enable(TIME_STEP)

robot.step(TIME_STEP)
robot.step(TIME_STEP)
robot.step(TIME_STEP)
pen.write(False)

# 1) Test initial painted area location
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    numColorPixels < 51,
    "The number of pixels painted after the first step should be lower than 51 not %d",
    numColorPixels)

color = getPixelColor(camera, width, 26, 40)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (26, 40) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after first paint call",
    206, 171, 58, *color)

robot.step(TIME_STEP)

# move pen
pos = position_sensor.getValue()
pos = pos + 0.02
motor.setPosition(pos)

robot.step(TIME_STEP)
# print
pen.write(True)

robot.step(TIME_STEP)
pen.write(False)

# 2) Test second painted area location
oldValue = numColorPixels
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    oldValue <= numColorPixels and numColorPixels < 102,
    "The number of pixels painted after the second step should be greater than before (%d) and lower "
    "than 102 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 43, 25)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (43, 25) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after second paint call",
    206, 171, 58, *color)

robot.step(TIME_STEP)

# move pen
pos = position_sensor.getValue()
pos = pos + 0.02
motor.setPosition(pos)

robot.step(TIME_STEP)
# print
pen.write(True)

robot.step(TIME_STEP)
pen.write(False)

# 3) Test third painted area location
oldValue = numColorPixels
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    oldValue <= numColorPixels and numColorPixels < 112,
    "The number of pixels painted after the third step should be greater than before (%d) and lower than "
    "112 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 49, 14)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (49, 14) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after third paint call",
    206, 171, 58, *color)

ts_send_success()
