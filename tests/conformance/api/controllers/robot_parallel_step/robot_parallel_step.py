"""Port of Webots' tests/api/controllers/robot_parallel_step: with stepBegin/stepEnd, sensor values read between
them are those of the previous stepEnd and stay unchanged however long the controller works, and a pose written by a
supervisor between them is seen by the robot's compass, distance sensor and GPS after the next stepEnd."""

import time

from controller import Supervisor
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_doubles_in_delta,
    ts_assert_int_equal,
    ts_send_success,
    ts_setup,
)

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())
compass = robot.getDevice("compass")
gps = robot.getDevice("gps")
ds = robot.getDevice("distance sensor")

compass.enable(time_step)
gps.enable(time_step)
ds.enable(time_step)

robot_node = robot.getFromDef("ROBOT")
translation_field = robot_node.getField("translation")
rotation_field = robot_node.getField("rotation")
rotation_field.enableSFTracking(time_step)

robot.stepBegin(time_step)

rotation_field.setSFRotation([0.0, 1.0, 0.0, 1.5708])
translation_field.setSFVec3f([-0.05, 0.0295, 0.1])

robot.stepEnd()

robot.stepBegin(time_step)

values = compass.getValues()
ts_assert_doubles_in_delta(3, values, [1.0, 0.0, 0.0], 0.0001, "Initial compass measurement is wrong.")

distance = ds.getValue()
ts_assert_double_in_delta(distance, 1000, 0.001, "Initial distance sensor measurement is wrong.")

values = gps.getValues()
ts_assert_doubles_in_delta(3, values, [0.1, 0.0295, 0.1], 0.00001, "Initial GPS measurement is wrong.")

rotation_field.setSFRotation([0.0, 0.0, 1.0, 0.0])
translation_field.setSFVec3f([0.1, 0.0295, 0.1])

robot.stepEnd()

robot.stepBegin(time_step)

new_compass_values1 = [0.0, 0.0, 1.0]
new_gps_values1 = [-0.05, 0.0295, 0.1]

values = compass.getValues()
ts_assert_doubles_in_delta(3, values, new_compass_values1, 0.0001, "Compass measurement after first pose update is wrong.")

distance = ds.getValue()
ts_assert_double_in_delta(distance, 650.0, 0.001, "Distance sensor measurement after first pose update is wrong.")

values = gps.getValues()
ts_assert_doubles_in_delta(3, values, new_gps_values1, 0.00001, "GPS measurement after first pose update is wrong.")

time.sleep((time_step * 1000 + 100000) / 1e6)

result = 0xffff
for i in range(0xffff):
    result &= ~i
ts_assert_int_equal(result, 0, "Computation produced unexpected result.")

values = compass.getValues()
ts_assert_doubles_in_delta(3, values, new_compass_values1, 0.0001,
                           "Delayed compass measurement after first pose update is wrong.")

distance = ds.getValue()
ts_assert_double_in_delta(distance, 650.0, 0.001, "Delayed distance sensor measurement after first pose update is wrong.")

values = gps.getValues()
ts_assert_doubles_in_delta(3, values, new_gps_values1, 0.00001, "Delayed GPS measurement after first pose update is wrong.")

robot.stepEnd()

values = compass.getValues()
ts_assert_doubles_in_delta(3, values, [1.0, 0.0, 0.0], 0.0001, "Compass measurement after second pose update is wrong.")

distance = ds.getValue()
ts_assert_double_in_delta(distance, 1000, 0.001, "Distance sensor measurement after second pose update is wrong.")

values = gps.getValues()
ts_assert_doubles_in_delta(3, values, [0.1, 0.0295, 0.1], 0.00001, "GPS measurement after second pose update is wrong.")

ts_send_success()
