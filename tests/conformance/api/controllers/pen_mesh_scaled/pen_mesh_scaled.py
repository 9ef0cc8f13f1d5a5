"""Port of Webots' tests/api/controllers/pen_mesh_scaled: painting with a Pen on a scaled Mesh.

The pen writes on every step (it is never switched off); after the first step a given pixel must still be grey,
and after the pen has moved 4 cm along its slider that pixel must be inked. It runs in the world pen_mesh.
"""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup
from ts_pen import computeNumColorPixels, getPixelColor, isGray

TIME_STEP = 32
width = 64
height = 64
size = 4096


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

# 1) Test initial painted area location
numColorPixels = computeNumColorPixels(camera, width, height)
ts_assert_boolean_equal(numColorPixels <= 20,
                        "The number of pixels painted after the first step should be lower than 20 not %d",
                        numColorPixels)

color = getPixelColor(camera, width, 46, 26)
ts_assert_boolean_equal(isGray(color), "The pixel (46,26) should be gray at first step")

robot.step(TIME_STEP)

# move pen
motor.setPosition(position_sensor.getValue() + 0.04)
robot.step(5 * TIME_STEP)

# 2) Test third painted area location
color = getPixelColor(camera, width, 46, 26)
ts_assert_boolean_equal(not isGray(color), "The pixel (46,26) should not be gray at last step")

ts_send_success()
