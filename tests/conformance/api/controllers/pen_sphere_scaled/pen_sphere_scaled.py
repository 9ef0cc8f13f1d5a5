"""Port of Webots' tests/api/controllers/pen_sphere_scaled: painting with a Pen on a scaled sphere.

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
    numColorPixels <= 70,
    "The number of pixels painted after the first step should be lower than 70 not %d",
    numColorPixels)

color = getPixelColor(camera, width, 10, 49)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (10, 49) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after first paint call",
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
    oldValue <= numColorPixels and numColorPixels <= 140,
    "The number of pixels painted after the second step should be greater than before (%d) and lower "
    "than 140 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 21, 30)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (21, 30) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after second paint call",
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
    oldValue <= numColorPixels and numColorPixels < 174,
    "The number of pixels painted after the third step should be greater than before (%d) and lower than "
    "174 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 30, 18)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (30, 18) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after third paint call",
    206, 171, 58, *color)

ts_send_success()
