"""Port of Webots' tests/api/controllers/radar_target_merging: radars merge targets closer than their cellDistance
and cellSpeed, and merged targets lie at the mean azimuth."""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32


def check_all_target_angle_is_correct(radar, expected_angle: float) -> bool:
    targets = radar.getTargets()
    for i in range(radar.getNumberOfTargets()):
        # The C original compares with abs(), the integer absolute value: the difference is truncated to an int first.
        if abs(int(targets[i].azimuth - expected_angle)) > 0.0000001:
            return False
    return True


robot = Robot()
ts_setup(robot)

radar1 = robot.getDevice("radar1")
radar2 = robot.getDevice("radar2")
radar3 = robot.getDevice("radar3")
radar4 = robot.getDevice("radar4")

radar1.enable(TIME_STEP)
radar2.enable(TIME_STEP)
radar3.enable(TIME_STEP)
radar4.enable(TIME_STEP)

robot.step(TIME_STEP)
robot.step(TIME_STEP)

ts_assert_int_equal(radar1.getNumberOfTargets(), 3,
                    "The radar 1 should see 3 targets because 3 targets are merged into one twice.")
ts_assert_int_equal(radar2.getNumberOfTargets(), 4,
                    "The radar 2 should see 4 targets because 3 targets are merged into one and 2 other into one.")
ts_assert_int_equal(radar3.getNumberOfTargets(), 7,
                    "The radar 3 should see all the 7 targets because no targets should be merged.")
ts_assert_int_equal(
    radar4.getNumberOfTargets(), 5,
    "The radar 4 should see 5 targets, only 2 tagets are merged into one twice because of the very small cell speed.")

ts_assert_boolean_equal(check_all_target_angle_is_correct(radar1, 0.0),
                        "After merging all the targets of radar 1 should be aligned in the center (i.e. angle should be 0)")
ts_assert_boolean_equal(check_all_target_angle_is_correct(radar2, 0.0),
                        "After merging all the targets of radar 2 should be aligned in the center (i.e. angle should be 0)")

ts_send_success()
