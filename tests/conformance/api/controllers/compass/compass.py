"""Port of Webots' tests/api/controllers/compass: the north direction, before and after a coordinateSystem change."""

from controller import Supervisor
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)
compass = robot.getDevice("compass")
compass.enable(TIME_STEP)
robot.step(TIME_STEP)

lookup_table = compass.getLookupTable()
size = len(lookup_table) // 3
ts_assert_double_equal(size, 2, "Lookup table size returned is wrong (%d instead of 2)", size)
ts_assert_double_equal(lookup_table[3], 1000, "Lookup table (index 3) returned is wrong (%lf instead of 1000)",
                       lookup_table[3])
ts_assert_double_equal(lookup_table[5], 0, "Lookup table (index 5) returned is wrong (%lf instead of 0)", lookup_table[5])

values = compass.getValues()
expected = [0.258819, 0, 0.965926]
for i in range(3):
    ts_assert_double_in_delta(values[i], expected[i], 0.0001, "The compass doesn't return the right north direction.")

coordinate_system = robot.getFromDef("WORLD_INFO").getField("coordinateSystem")
coordinate_system.setSFString("EUN")
for _ in range(3):
    robot.step(TIME_STEP)
values = compass.getValues()
message = "The compass doesn't return the right north direction after changing the coordinate system."
ts_assert_double_in_delta(values[0], -expected[2], 0.0001, message)
ts_assert_double_in_delta(values[1], expected[1], 0.0001, message)
ts_assert_double_in_delta(values[2], expected[0], 0.0001, message)

ts_send_success()
