"""Port of Webots' tests/api/controllers/touch_sensor_force: an empty lookup table, then a force TouchSensor reads 0 N
in free fall and the weight it carries (981 N) on the floor."""

from controller import Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_equal,
    ts_assert_double_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 16

robot = Robot()
ts_setup(robot)

ts = robot.getDevice("touch sensor")
ts.enable(TIME_STEP)

lookup_table = ts.getLookupTable()
lookup_table_size = len(lookup_table) // 3
ts_assert_double_equal(lookup_table_size, 0, "Lookup table size returned is wrong (%d instead of 0)", lookup_table_size)
# C's NULL table is an empty list in Python.
ts_assert_boolean_equal(len(lookup_table) == 0, "Lookup table returned is wrong (%s instead of NULL)", lookup_table)

for _ in range(5):
    robot.step(TIME_STEP)

value = ts.getValue()
ts_assert_double_in_delta(value, 0.0, 0.001, "The \"force\" TouchSensor should return 0.0 N in free fall.")

for _ in range(100):
    robot.step(TIME_STEP)

value = ts.getValue()
ts_assert_double_in_delta(value, 981.0, 1.0, "The \"force\" TouchSensor doesn't return the right value when on the floor.")

ts_send_success()
