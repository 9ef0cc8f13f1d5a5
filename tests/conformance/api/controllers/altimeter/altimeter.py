"""Port of Webots' tests/api/controllers/altimeter: NaN before the first sample, then the altitude."""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_send_success, ts_setup

TIME_STEP = 32
NAN = float("nan")

robot = Robot()
ts_setup(robot)
altimeter = robot.getDevice("altimeter")
e = 0.05

h = altimeter.getValue()
ts_assert_double_equal(h, NAN, "The altitude measured by the Altimeter should be NAN and not %g before the device is enabled", h)
altimeter.enable(TIME_STEP)
h = altimeter.getValue()
ts_assert_double_equal(h, NAN,
                       "The altitude measured by the Altimeter should be NAN and not %g before a wb_robot_step is performed", h)
for j in range(1, 11):
    robot.step(TIME_STEP)
    h = altimeter.getValue()
    ts_assert_double_equal(h, e, "The altitude measured by the Altimeter should be %g and not %g after %d wb_robot_step(s)",
                           e, h, j)

ts_send_success()
