"""Port of Webots' tests/api/controllers/pen_capsule_scaled: painting with a Pen on a rotated and scaled capsule.

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
    numColorPixels <= 30,
    "The number of pixels painted after the first step should be lower than 30 not %d",
    numColorPixels)

color = getPixelColor(camera, width, 4, 40)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (4, 40) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after first paint call",
    206, 171, 58, *color)

robot.step(TIME_STEP)

# move pen
pos = position_sensor.getValue()
pos = pos + 0.02
motor.setPosition(pos)

# wait until movement is complete
i = 0
while True:  # C's do { ... } while (fabs(pos - effectivePos) > 0.002 && i < 10)
    robot.step(TIME_STEP)
    effectivePos = position_sensor.getValue()
    i += 1
    if not (abs(pos - effectivePos) > 0.002 and i < 10):
        break

robot.step(TIME_STEP)
# print
pen.write(True)

robot.step(TIME_STEP)
pen.write(False)

# 2) Test second painted area location
oldValue = numColorPixels
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    oldValue <= numColorPixels and numColorPixels <= 80,
    "The number of pixels painted after the second step should be greater than before (%d) and lower "
    "than 80 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 13, 31)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (13, 31) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after second paint call",
    206, 171, 58, *color)

robot.step(TIME_STEP)

# move pen
pos = position_sensor.getValue()
pos = pos + 0.03
motor.setPosition(pos)

# wait until movement is complete
i = 0
while True:  # C's do { ... } while (fabs(pos - effectivePos) > 0.002 && i < 10)
    robot.step(TIME_STEP)
    effectivePos = position_sensor.getValue()
    i += 1
    if not (abs(pos - effectivePos) > 0.002 and i < 10):
        break

robot.step(TIME_STEP)
# print
pen.write(True)

robot.step(TIME_STEP)
pen.write(False)

# 3) Test third painted area location
oldValue = numColorPixels
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    oldValue <= numColorPixels and numColorPixels <= 150,
    "The number of pixels painted after the third step should be greater than before (%d) and lower than "
    "150 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 32, 16)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 15,
    "Pixel (32, 16) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after third paint call",
    206, 171, 58, *color)

ts_send_success()
