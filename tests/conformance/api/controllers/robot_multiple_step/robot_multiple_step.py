"""Port of Webots' tests/api/controllers/robot_multiple_step: one step(n) of several basic steps samples sensors at
their own period, and a supervisor's move between samples shows only at the next sample.

Follows the upstream version at a6ae7631 (as omnilink-tech/omnisim keeps it), which goes with the stored R2025a world:
the camera facing the sky reads the plain skyColor (0x66, 0xB2, 0xFF); the older 8364fc97 expected (0x84, 0xC9, 0xEF).
"""

from controller import Robot
from ts_assertion import (
    ts_assert_color_in_delta,
    ts_assert_double_in_delta,
    ts_assert_doubles_in_delta,
    ts_send_success,
    ts_setup,
)

robot = Robot()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())
camera = robot.getDevice("camera")
compass = robot.getDevice("compass")
gps = robot.getDevice("gps")
ds = robot.getDevice("distance sensor")
ts = robot.getDevice("touch sensor")

camera.enable(3 * time_step)
compass.enable(3 * time_step)
gps.enable(3 * time_step)
ds.enable(3 * time_step)
ts.enable(3 * time_step)

# step 1 - 32 ms
# step 2 - 64 ms
# step 3 - 96 ms -> refresh sensor value
# change robot position
# step 4 - 128 ms -> sensor values not updated
# step 5 - 160 ms
robot.step(5 * time_step)

# check initial sensor values

# camera
image = camera.getImage()
r = camera.imageGetRed(image, 1, 0, 0)
g = camera.imageGetGreen(image, 1, 0, 0)
b = camera.imageGetBlue(image, 1, 0, 0)
ts_assert_color_in_delta(r, g, b, 0x66, 0xB2, 0xFF, 5, "Initial camera measurement is wrong.")

# compass
values = compass.getValues()
ts_assert_doubles_in_delta(3, values, [1.0, 0.0, 0.0], 0.0001, "Initial compass measurement is wrong.")

# distance sensor
ts_assert_double_in_delta(ds.getValue(), 1000.0, 0.001, "Initial distance sensor measurement is wrong.")

# gps
values = gps.getValues()
ts_assert_doubles_in_delta(3, values, [0.100000, 0.025178, 0.100000], 0.00001, "Initial GPS measurement is wrong.")

# touch sensor
ts_assert_double_in_delta(ts.getValue(), 0.0, 0.001, "Initial touch sensor measurement is wrong.")

robot.step(time_step)

# check sensor values after robot position changed

# camera
image = camera.getImage()
r = camera.imageGetRed(image, 1, 0, 0)
g = camera.imageGetGreen(image, 1, 0, 0)
b = camera.imageGetBlue(image, 1, 0, 0)
ts_assert_color_in_delta(r, g, b, 207, 207, 207, 5, "Camera measurement after robot moved is wrong.")

# compass
values = compass.getValues()
ts_assert_doubles_in_delta(3, values, [0.003230, -0.034126, 0.999412], 0.00001,
                           "Compass measurement after robot moved is wrong (received: {%f, %f, %f}).", values[0],
                           values[1], values[2])

# distance sensor
value = ds.getValue()
ts_assert_double_in_delta(value, 666.766, 0.001, "Distance sensor measurement after robot moved is wrong (received: %f).",
                          value)

# gps
values = gps.getValues()
ts_assert_doubles_in_delta(3, values, [-0.049331, 0.025861, 0.101667], 0.00001,
                           "GPS measurement after robot moved is wrong (received: {%f, %f, %f}).", values[0], values[1],
                           values[2])

# touch sensor
value = ts.getValue()
ts_assert_double_in_delta(value, 5.442, 0.001, "Touch sensor measurement after robot moved is wrong (received: %f).",
                          value)

ts_send_success()
