"""Port of Webots' tests/api/controllers/light_sensor_point_spot_light_no_occlusion: irradiance of two lights."""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

LS0_VALUE = 279.21
LS1_VALUE = 102.4
TIME_STEP = 32
NAN = float("nan")

robot = Robot()
ts_setup(robot)

ls0 = robot.getDevice("ls0")
ls1 = robot.getDevice("ls1")

# C reads the table as a flat array of rows (input, value, noise); Python's getLookupTable gives the same flat list.
lookup_table = ls0.getLookupTable()
lookup_table_size = len(lookup_table) // 3
ts_assert_double_equal(lookup_table_size, 2, "Lookup table size returned is wrong (%d instead of 2)", lookup_table_size)
ts_assert_double_equal(lookup_table[3], 10, "Lookup table (index 3) returned is wrong (%f instead of 10)", lookup_table[3])
ts_assert_double_equal(lookup_table[5], 0, "Lookup table (index 5) returned is wrong (%f instead of 0)", lookup_table[5])

r = ls0.getValue()
ts_assert_double_equal(r, NAN, 'The value measured by the light sensor "ls0" should be NaN and not %g before the device is enabled', r)
r = ls1.getValue()
ts_assert_double_equal(r, NAN, 'The value measured by the light sensor "ls1" should be NaN and not %g before the device is enabled', r)

ls0.enable(TIME_STEP)
ls1.enable(2 * TIME_STEP)

r = ls0.getValue()
ts_assert_double_equal(r, NAN, 'The value measured by the light sensor "ls0" should be NaN and not %g before a wb_robot_step is performed', r)
r = ls1.getValue()
ts_assert_double_equal(r, NAN, 'The value measured by the light sensor "ls1" should be NaN and not %g before a wb_robot_step is performed', r)

robot.step(TIME_STEP)

r = ls0.getValue()
ts_assert_double_in_delta(r, LS0_VALUE, 0.001, 'The value measured by the light sensor "ls0" should be %g and not %g after 1 wb_robot_step(s)',
                          LS0_VALUE, r)
r = ls1.getValue()
ts_assert_double_equal(r, NAN, 'The value measured by the light sensor "ls1" should be NaN and not %g after 1 wb_robot_step is performed', r)

for i in range(2, 11):
    robot.step(TIME_STEP)
    r = ls0.getValue()
    ts_assert_double_in_delta(r, LS0_VALUE, 0.001,
                              'The value measured by the light sensor "ls0" should be %g and not %g after %d wb_robot_step(s)',
                              LS0_VALUE, r, i)
    r = ls1.getValue()
    ts_assert_double_in_delta(r, LS1_VALUE, 0.001,
                              'The value measured by the light sensor "ls0" should be %g and not %g after %d wb_robot_step(s)',
                              LS1_VALUE, r, i)

ts_send_success()
