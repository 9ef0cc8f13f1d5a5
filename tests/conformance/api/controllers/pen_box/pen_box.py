"""Port of Webots' tests/api/controllers/pen_box: painting with a Pen on a rotated box (the same texture on each face).

The pen writes one stroke, moves along its slider, writes again, twice; after each stroke the camera must see
no more coloured (not grey) pixels than a bound, and the ink's colour at a given pixel. The ink colours are those of
the upstream version at 986b3e38 (as omnilink-tech/omnisim keeps it: (185, 152, 60), (185, 151, 50), (185, 151, 51));
the older 8364fc97 expected (206, 171, 58) at all three pixels with the same world, before a change of Webots' rendering.
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
pen.write(False)

# 1) Test initial painted area location
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    numColorPixels <= 20,
    "The number of pixels painted after the first step should be lower than 20 not %d",
    numColorPixels)

color = getPixelColor(camera, width, 13, 56)
ts_assert_color_in_delta(
    *color, 185, 152, 60, 15,
    "Pixel (13, 56) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after first paint call",
    185, 152, 60, *color)

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
    oldValue <= numColorPixels and numColorPixels <= 40,
    "The number of pixels painted after the second step should be greater than before (%d) and lower "
    "than 40 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 28, 39)
ts_assert_color_in_delta(
    *color, 185, 151, 50, 15,
    "Pixel (28, 39) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after second paint call",
    185, 151, 50, *color)

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
    oldValue <= numColorPixels and numColorPixels <= 60,
    "The number of pixels painted after the third step should be greater than before (%d) and lower than "
    "60 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 34, 25)
ts_assert_color_in_delta(
    *color, 185, 151, 51, 15,
    "Pixel (34, 25) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after third paint call",
    185, 151, 51, *color)

ts_send_success()
