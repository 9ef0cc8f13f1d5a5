"""Port of Webots' tests/protos/controllers/slots: a GPS Solid with physics given in the slot field of a robot PROTO
falls with the robot onto the floor (physics works through the PROTO's slot): after 2 s its y is 0.05 (+- 0.01)."""

import math

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

# get and enable the gps
gps = robot.getDevice("mygps")
gps.enable(TIME_STEP)

# wait 2 second
for _i in range(2000 // TIME_STEP):
    robot.step(TIME_STEP)

values = gps.getValues()
y_value = values[1]

# check the gps value is correct
# if physics doesn't work, either the GPS will be blocked above, or will go through the plane
ts_assert_boolean_equal(not math.isnan(y_value), "GPS value is NaN")
print("y-value = %f" % y_value)
tolerance = 0.01
ts_assert_boolean_equal(y_value < 0.05 + tolerance, "GPS is above the threshold. Physics issue detected")
ts_assert_boolean_equal(y_value > 0.05 - tolerance, "GPS is below the threshold. Physics issue detected")

ts_send_success()
