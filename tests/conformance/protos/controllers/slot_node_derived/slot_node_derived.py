"""Port of Webots' tests/protos/controllers/slot_node_derived: a Slot's type set in a base PROTO holds in PROTOs
derived from it: the device behind a matching pair of Slots belongs to the robot, the one behind a mismatched pair
does not.

The C test compares device tags with 0 (no device); Python's getDevice returns None for no device, so the checks
compare with None (ts_assert_pointer_not_null for a tag that must not be 0, ts_assert_pointer_null for 0).
"""

from controller import Robot
from ts_assertion import ts_assert_pointer_not_null, ts_assert_pointer_null, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

# get and enable the acc
acc1 = robot.getDevice("acc1")
acc2 = robot.getDevice("acc2")

robot.step(TIME_STEP)

# first accelerometer is in valid derived slot => the device should be accessible => the tag should not be 0
ts_assert_pointer_not_null(acc1,
                           "Accelerometer 'acc1' is in a valid pair of slot and is therefore supposed to be added to the "
                           "robot, there is a problem due to the fact that the slot type is not defined in the derived "
                           "proto but only in the base proto.")

# the second accelerometer is not in valid slot => the device should not be accessible => the tag should be 0
ts_assert_pointer_null(acc2,
                       "Accelerometer 'acc2' is not in a valid pair of slot and is therefore not supposed to be added to "
                       "the robot, the default slot type has been applied to the derived proto instead of the one "
                       "defined in the base proto.")

robot.step(TIME_STEP)

ts_send_success()
