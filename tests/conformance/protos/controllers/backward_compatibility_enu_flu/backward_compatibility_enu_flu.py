"""Port of Webots' tests/protos/controllers/backward_compatibility_enu_flu: a camera PROTO written for R2021b
(ENU world, FLU devices) is converted on load, so the camera and its cylinder both look towards the box.

The world is tests/protos/worlds/backward_compability_enu_flu.wbt (its name misspelt as in Webots).
"""

from controller import Supervisor
from ts_assertion import ts_assert_doubles_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

old_proto_node = robot.getFromDef("OLD_PROTO")
cylinder_node = old_proto_node.getFromProtoDef("CYLINDER_POSE")

robot.step(TIME_STEP)
camera_pose = old_proto_node.getPose()
camera_pose_expected = [1, 0, 0]
camera_pose_x_theta = [camera_pose[0], camera_pose[4], camera_pose[8]]
ts_assert_doubles_in_delta(3, camera_pose_x_theta, camera_pose_expected, 0.1,
                           "The Camera node should be looking towards the box (got %lf %lf %lf).", camera_pose_x_theta[0],
                           camera_pose_x_theta[1], camera_pose_x_theta[2])

cylinder_pose = cylinder_node.getPose()
cylinder_pose_expected = [-1, 0, 0]
cylinder_pose_z_theta = [cylinder_pose[2], cylinder_pose[6], cylinder_pose[10]]
ts_assert_doubles_in_delta(3, cylinder_pose_z_theta, cylinder_pose_expected, 0.1,
                           "The Cylinder node should be looking towards the box (got %lf %lf %lf).",
                           cylinder_pose_z_theta[0], cylinder_pose_z_theta[1], cylinder_pose_z_theta[2])

robot.step(TIME_STEP)
ts_send_success()
