"""Port of Webots' tests/api/controllers/distance_sensor_enable_disable: NaN before the first sample, sampling
periods, and a disabled sensor keeping its last value."""

import math

from controller import Supervisor
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
NAN = math.nan

robot = Supervisor()
ts_setup(robot)
new_position = [-0.03, 0.0, 0.0]

robot_node = robot.getSelf()
translation_field = robot_node.getField("translation")

ds_generic = robot.getDevice("ds generic")
ds_sonar = robot.getDevice("ds sonar")
ds_infra_red = robot.getDevice("ds infra-red")
ds_laser = robot.getDevice("ds laser")

# test: get the value of a sensor which has not been enabled yet
value = ds_generic.getValue()
ts_assert_double_equal(value, NAN,
                       "The distance sensor in generic mode doesn't return NAN when it has not been enabled yet. %lf != %lf",
                       NAN, value)
value = ds_sonar.getValue()
ts_assert_double_equal(value, NAN, "The distance sensor in sonar mode doesn't return NAN when it has not been enabled yet.")
value = ds_infra_red.getValue()
ts_assert_double_equal(value, NAN,
                       "The distance sensor in infra-red mode doesn't return NAN when it has not been enabled yet.")
value = ds_laser.getValue()
ts_assert_double_equal(value, NAN, "The distance sensor in laser mode doesn't return NAN when it has not been enabled yet.")

ds_generic.enable(3 * TIME_STEP)
ds_sonar.enable(TIME_STEP)
ds_infra_red.enable(TIME_STEP)
ds_laser.enable(TIME_STEP)

robot.step(TIME_STEP)

value = ds_sonar.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in sonar mode doesn't return the right distance in the regular case. "
                          "(%f but %f was expected)", value, 500.0)
value = ds_infra_red.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in infra-red mode doesn't return the right distance in the regular case. "
                          "(%f but %f was expected)", value, 500.0)
value = ds_laser.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in laser mode doesn't return the right distance in the regular case. "
                          "(%f but %f was expected)", value, 500.0)

# test sensor value not available before first sampling period elapsed
value = ds_generic.getValue()
ts_assert_double_equal(value, NAN, "The distance sensor in generic mode should not yet be active during the first step.")

robot.step(TIME_STEP)

value = ds_generic.getValue()
ts_assert_double_equal(value, NAN, "The distance sensor in generic mode should not yet be active during the second step.")

robot.step(TIME_STEP)

value = ds_generic.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in generic mode doesn't return the right distance in the regular case. "
                          "(%f but %f was expected)", value, 500.0)

translation_field.setSFVec3f(new_position)

# test: laser and sonar disabled -> last value returned
#       infra-red enabled        -> return value changes next step
#       generic enabled          -> return value changes in two steps
ds_sonar.disable()
ds_laser.disable()

robot.step(TIME_STEP)

# test: get the value of an disabled sonar
value = ds_sonar.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in sonar mode doesn't return the last measured distance when being disabled.")
value = ds_laser.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in laser mode doesn't return the last measured distance when being disabled.")

# test value updated
value = ds_infra_red.getValue()
ts_assert_double_in_delta(value, 800.0, 0.001,
                          "The distance sensor in infra-red mode doesn't return the updated measured distance after "
                          "translation.")

# test value not updated yet
value = ds_generic.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in generic mode shouldn't update the measured distance the next step after "
                          "translation.")

robot.step(TIME_STEP)

value = ds_generic.getValue()
ts_assert_double_in_delta(value, 500.0, 0.001,
                          "The distance sensor in generic mode shouldn't update the measured distance two steps after "
                          "translation.")

robot.step(TIME_STEP)

value = ds_generic.getValue()
ts_assert_double_in_delta(value, 800.0, 0.001,
                          "The distance sensor in generic mode doesn't return the updates measured distance three steps "
                          "after translation.")

ts_send_success()
