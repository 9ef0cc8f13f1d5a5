"""Port of Webots' tests/api/controllers/accelerometer: lookup table getters and the accelerations read by eight
accelerometers on a disc turning at 180 degrees per second (gravity plus where each one sits).

The stored upstream controller reads one device "accelerometer" that the stored world (R2023b, at a38b359a) does not
have; this port follows the version of the controller that matches that world, with the devices "center", "tX",
"tY", "tZ", "center offset", "tX offset", "tY offset", "tZ offset" and the motor "motor", as kept in
omnilink-tech/omnisim (a Webots fork, tests/api/controllers/accelerometer/accelerometer.c) and in cyberbotics/webots at
df51c2cb.
"""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
NAMES = ["center", "tX", "tY", "tZ", "center offset", "tX offset", "tY offset", "tZ offset"]
CENTER = 0
EXPECTED = [[0, 9.8, 0], [-1, 9.8, -0.1], [0, 9.8, 0], [0, 9.8, -1],
            [-1, 9.8, -0.1], [-2, 9.8, -0.2], [-1, 9.8, -0.1], [-1, 9.8, -1.1]]

robot = Robot()
ts_setup(robot)
accelerometers = [robot.getDevice(name) for name in NAMES]
for accelerometer in accelerometers:
    accelerometer.enable(TIME_STEP)

motor = robot.getDevice("motor")
motor.setPosition(float("inf"))
motor.setVelocity(3.1415927)  # 180 degrees per second

robot.step(TIME_STEP * 5)

lookup_table = accelerometers[CENTER].getLookupTable()
lookup_table_size = len(lookup_table) // 3
ts_assert_double_equal(lookup_table_size, 2, "Lookup table size returned is wrong (%d instead of 2)", lookup_table_size)
ts_assert_double_equal(lookup_table[3], 1000, "Lookup table (index 3) returned is wrong (%lf instead of 1000)",
                       lookup_table[3])
ts_assert_double_equal(lookup_table[5], 0, "Lookup table (index 5) returned is wrong (%lf instead of 0)", lookup_table[5])

values = [accelerometer.getValues() for accelerometer in accelerometers]
for measured, expected in zip(values, EXPECTED, strict=True):
    for j in range(3):
        ts_assert_double_in_delta(measured[j], expected[j], 0.1, "The Accelerometer doesn't return the right acceleration.")

ts_send_success()
