"""Port of Webots' tests/api/controllers/supervisor_get_position_orientation_pose: getFromDef with a dotted DEF path,
getPosition, getOrientation (unscaled after a scale change), getPose relative to a parent Solid, pose tracking, and
no crash when the tracked reference node is removed."""

import sys

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_doubles_in_delta,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

node = robot.getFromDef("NODE")
ts_assert_pointer_not_null(node, 'wb_supervisor_node_get_from_def("NODE") failed')

node2 = robot.getFromDef("ROBOT.JOINT.SOLID.NODE")
ts_assert_pointer_not_null(node2, 'wb_supervisor_node_get_from_def("ROBOT.JOINT.SOLID.NODE") failed')

node_parent = robot.getFromDef("ROBOT.JOINT.SOLID")
ts_assert_pointer_not_null(node_parent, 'wb_supervisor_node_get_from_def("ROBOT.JOINT.SOLID") failed')

if node != node2:
    ts_assert_boolean_equal(False, 'wb_supervisor_node_get_from_def("ROBOT.JOINT.SOLID.NODE") failed, reference to node '
                            'and node2 should be equal.')

position = node.getPosition()
POSITION = [0.1, -0.2, 0.3]
ts_assert_doubles_in_delta(3, position, POSITION, 0.000001, "wb_supervisor_node_get_position() did not return the "
                           "expected values")

orientation = node.getOrientation()
ROTATION = [1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0, -0.0]
ts_assert_doubles_in_delta(9, orientation, ROTATION, 0.0001, "wb_supervisor_node_get_orientation() did not return the "
                           "expected values.")

scale_field = node.getField("scale")
# The R2023b world's NODE is a Pose, which has no scale field: the C test passes NULL on to
# wb_supervisor_field_set_sf_vec3f, which Webots' C API reports and ignores. Python's API has no such
# call on None, so the port does what the C call does.
if scale_field is None:
    print("Error: wb_supervisor_field_set_sf_vec3f() called with NULL 'field' argument.", file=sys.stderr)
else:
    scale_field.setSFVec3f([2.0, 3.0, 4.0])

robot.step(TIME_STEP)

orientation = node.getOrientation()
ts_assert_doubles_in_delta(9, orientation, ROTATION, 0.0001, "wb_supervisor_node_get_orientation() did not return the "
                           "expected values for scaled node.")

pose = node.getPose(node_parent)
POSE = [-1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, -1.0, 0.0, 0.3, 0.0, 0.0, 0.0, 1.0]
ts_assert_doubles_in_delta(16, pose, POSE, 0.0001, "wb_supervisor_node_get_pose() did not return the expected values.")

node.enablePoseTracking(TIME_STEP, node_parent)

for _ in range(10):
    robot.step(TIME_STEP)
    tracked_pose = node.getPose(node_parent)
    ts_assert_doubles_in_delta(16, POSE, tracked_pose, 0.0001, "wb_supervisor_node_get_pose() did not return the "
                               "expected values.")

node.disablePoseTracking(node_parent)

robot.step(TIME_STEP)
node.enablePoseTracking(TIME_STEP, node_parent)
robot.step(TIME_STEP)
tracked_pose = node.getPose(node_parent)
ts_assert_doubles_in_delta(16, POSE, tracked_pose, 0.0001, "wb_supervisor_node_get_pose() did not return the expected "
                           "values.")
node_parent.remove()
robot.step(2 * TIME_STEP)
node.getPose(node_parent)
node.disablePoseTracking(node_parent)

ts_send_success()
