"""Port of Webots' tests/api/controllers/gps: NaN before the first sample, then the device's position."""

from controller import GPS, Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

NAN = float("nan")


def check_position(gps, x: float, y: float, z: float, end_msg: str) -> None:
    position = gps.getValues()
    for i, (value, expected) in enumerate(zip(position, (x, y, z), strict=True)):
        ts_assert_double_in_delta(value, expected, 0.000001, "The %s value measured by the GPS should be %f and not %f %s.",
                                  "XYZ"[i], expected, value, end_msg)


robot = Robot()
ts_setup(robot)
time_step = int(robot.getBasicTimeStep())
gps = robot.getDevice("gps")
check_position(gps, NAN, NAN, NAN, "before the device is enabled")
gps.enable(time_step)
check_position(gps, NAN, NAN, NAN, "before a wb_robot_step is performed")
ts_assert_int_equal(gps.getCoordinateSystem(), GPS.LOCAL, "Wrong coordinate system returned")
for i in range(1, 11):
    robot.step(time_step)
    check_position(gps, 0.19996, 0.05, -0.35, "after %d wb_robot_step(s)" % i)

ts_send_success()
