"""Port of Webots' tests/api/controllers/gyro: lookup table getters and the angular velocity of a turning hinge.

The stored upstream controller expects lookupTable[3] = 100 where the stored world (R2021c) writes 1000; this port
follows the version of the controller that matches that world, as kept in omnilink-tech/omnisim (a Webots fork,
tests/api/controllers/gyro/gyro.c): 1000.
"""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)
motor = robot.getDevice("rotational motor")
gyro = robot.getDevice("gyro")
motor.setPosition(float("inf"))
motor.setVelocity(10.0)
gyro.enable(TIME_STEP)
for _ in range(40):
    robot.step(TIME_STEP)

lookup_table = gyro.getLookupTable()
size = len(lookup_table) // 3
ts_assert_double_equal(size, 2, "Lookup table size returned is wrong (%d instead of 2)", size)
ts_assert_double_equal(lookup_table[3], 1000, "Lookup table (index 3) returned is wrong (%lf instead of 1000)",
                       lookup_table[3])
ts_assert_double_equal(lookup_table[5], 0, "Lookup table (index 5) returned is wrong (%lf instead of 0)", lookup_table[5])

values = gyro.getValues()
expected = [0.0, 10.0, 0.0]
print("expected = {%f, %f, %f}" % tuple(expected))
print("values = {%f, %f, %f}" % tuple(values))
ts_assert_vec3_in_delta(values[0], values[1], values[2], expected[0], expected[1], expected[2], 0.0001,
                        "The Gyro doesn't return the right angular velocity. (expected = {%f, %f, %f}, "
                        "received = {%f, %f, %f})", *expected, *values)

ts_send_success()
