"""Port of Webots' tests/protos/controllers/slots_node_proto_parameter: a Slot PROTO (SlotNode) given as the default
value of a derived robot PROTO's field pairs with the base PROTO's Slot, so its accelerometer belongs to the robot.

The C test compares the device tag with 0 (no device); Python's getDevice returns None for no device, so the check
compares with None.
"""

from controller import Robot
from ts_assertion import ts_assert_pointer_not_null, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

# get acclerometer
acc1 = robot.getDevice("acc1")

robot.step(TIME_STEP)

# The accelerometer is in valid slot => the device should be accessible => the tag should not be 0
ts_assert_pointer_not_null(acc1,
                           "Accelerometer 'acc1' is in a valid pair of slot and is therefore supposed to be added to the "
                           "robot")

robot.step(TIME_STEP)

ts_send_success()
