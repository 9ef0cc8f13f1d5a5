"""Port of Webots' tests/api/controllers/pen_capsule: painting with a Pen on a rotated capsule.

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
pen.write(False)

# 1) Test initial painted area location
numColorPixels = computeNumColorPixels(camera, width, height)

ts_assert_boolean_equal(
    numColorPixels <= 40,
    "The number of pixels painted after the first step should be lower than 40 not %d",
    numColorPixels)

color = getPixelColor(camera, width, 19, 50)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 10,
    "Pixel (19, 50) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after first paint call",
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
    oldValue <= numColorPixels and numColorPixels <= 120,
    "The number of pixels painted after the second step should be greater than before (%d) and lower "
    "than 120 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 36, 32)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 10,
    "Pixel (36, 32) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after second paint call",
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
    oldValue <= numColorPixels and numColorPixels < 179,
    "The number of pixels painted after the third step should be greater than before (%d) and lower than "
    "179 not %d",
    oldValue, numColorPixels)

color = getPixelColor(camera, width, 45, 12)
ts_assert_color_in_delta(
    *color, 206, 171, 58, 10,
    "Pixel (45, 12) should be painted with color [r=%d, g=%d, b=%d] not [r=%d, g=%d, b=%d] after third paint call",
    206, 171, 58, *color)

ts_send_success()
