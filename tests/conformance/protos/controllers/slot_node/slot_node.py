"""Port of Webots' tests/protos/controllers/slot_node: devices behind pairs of Slot nodes (plain, in PROTOs, with
gendered types "slot+"/"slot-", empty types and types with spaces) belong to the robot only when the two Slots'
types match (same type, opposite genders or no gender); otherwise the robot has no such device.

The C test compares device tags with 0 (no device); Python's getDevice returns None for no device, so the checks
compare with None (ts_assert_pointer_not_null for a tag that must not be 0, ts_assert_pointer_null for 0).
"""

from controller import Robot
from ts_assertion import ts_assert_pointer_not_null, ts_assert_pointer_null, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

# get and enable the accelerometer
acc1 = robot.getDevice("acc1")
acc2 = robot.getDevice("acc2")
acc3 = robot.getDevice("acc3")
acc4 = robot.getDevice("acc4")
acc5 = robot.getDevice("acc5")
acc6 = robot.getDevice("acc6")
acc7 = robot.getDevice("acc7")
acc8 = robot.getDevice("acc8")

robot.step(TIME_STEP)

# first six accelerometers are in valid slot => the device should be accessible => the tag should not be 0
ts_assert_pointer_not_null(acc1,
                           "Accelerometer 'acc1' is in a valid pair of slot and is therefore supposed to be added to the "
                           "robot")
ts_assert_pointer_not_null(acc2,
                           "Accelerometer 'acc2' is in a valid pair of slot including some gender test and is therefore "
                           "supposed to be added to the robot")
ts_assert_pointer_not_null(acc3,
                           "Accelerometer 'acc3' is in a valid pair of slot and is therefore supposed to be added to the "
                           "robot")
ts_assert_pointer_not_null(
    acc4, "Accelerometer 'acc4' is in the 'children' field of 'acc3' and is therefore supposed to be added to the robot")
ts_assert_pointer_not_null(
    acc5,
    "Accelerometer 'acc5' is in a valid pair of slot nodes with empty type and is therefore supposed to be added to the "
    "robot")
ts_assert_pointer_not_null(acc6,
                           "Accelerometer 'acc6' is in a valid pair of slot nodes whose type contains spaces and is "
                           "therefore supposed to be added to the robot")

# the last two accelerometers are not in valid slot => the device should not be accessible => the tag should be 0
ts_assert_pointer_null(acc7,
                       "Accelerometer 'acc7' is in a valid pair of slot but the gender are the same and is therefore not "
                       "supposed to be added to the robot")
ts_assert_pointer_null(
    acc8, "Accelerometer 'acc8' is not in a valid pair of slot and is therefore not supposed to be added to the robot")

robot.step(TIME_STEP)

ts_send_success()
