"""Port of Webots' tests/api/controllers/supervisor_set_position_orientation: after a supervisor writes a Pose's
translation and rotation, getPosition and getOrientation give its new absolute pose (under a turned robot and a
hinge's end point) one step later."""

import math

from controller import Supervisor
from ts_assertion import ts_assert_doubles_in_delta, ts_assert_pointer_not_null, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

node = robot.getFromDef("NODE")
ts_assert_pointer_not_null(node, 'wb_supervisor_node_get_from_def("NODE") failed')

NEW_POSITION = [0.2, -0.15, 0.4]
EXPECTED_POSITION = [-0.1, -0.05, 0.4]
translation = node.getField("translation")
translation.setSFVec3f(NEW_POSITION)
robot.step(TIME_STEP)
position = node.getPosition()

ts_assert_doubles_in_delta(3, position, EXPECTED_POSITION, 0.0001, "wb_supervisor_node_get_position() did not return the "
                           "expected set value ({%f, %f, %f} instead of {%f, %f, %f})", position[0], position[1],
                           position[2], EXPECTED_POSITION[0], EXPECTED_POSITION[1], EXPECTED_POSITION[2])

EXPECTED_ROTATION_MATRIX3 = [-0.5, 0.866, 0.0, -0.866, -0.5, 0.0, 0.0, 0.0, 1.0]
NEW_ROTATION_FIELD_VALUE = [0.0, 0.0, 1.0, math.pi / 3.0]

rotation = node.getField("rotation")
rotation.setSFRotation(NEW_ROTATION_FIELD_VALUE)
robot.step(TIME_STEP)
orientation = node.getOrientation()

ts_assert_doubles_in_delta(9, orientation, EXPECTED_ROTATION_MATRIX3, 0.001,
                           "wb_supervisor_node_get_orientation() did not return the expected changed values.")

ts_send_success()
