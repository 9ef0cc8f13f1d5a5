"""Port of Webots' tests/physics/controllers/ball_joint_vs_hinge_joints: a BallJoint driven axis by axis moves its
endPoint as three chained HingeJoints do, with and without Physics, and ends at Webots' recorded position."""

from controller import Supervisor
from ts_assertion import ts_assert_vec3_in_delta, ts_send_success, ts_setup

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

ball_joint_robot = robot.getFromDef("BALL_JOINT_ROBOT")
ball_joint_robot_kinematic = robot.getFromDef("BALL_JOINT_ROBOT_KINEMATIC")
hinge_joint_robot = robot.getFromDef("HINGE_JOINT_ROBOT")
hinge_joint_robot_kinematic = robot.getFromDef("HINGE_JOINT_ROBOT_KINEMATIC")
ball_joint_marker = robot.getFromDef("BALL_JOINT_MARKER")
ball_joint_marker_kinematic = robot.getFromDef("BALL_JOINT_MARKER_KINEMATIC")
hinge_joint_marker = robot.getFromDef("HINGE_JOINT_MARKER")
hinge_joint_marker_kinematic = robot.getFromDef("HINGE_JOINT_MARKER_KINEMATIC")


def offset(marker, body):
    m, b = marker.getPosition(), body.getPosition()
    return [m[0] - b[0], m[1] - b[1], m[2] - b[2]]


while robot.step(time_step) != -1 and robot.getTime() < 6.0:
    hinge = offset(hinge_joint_marker, hinge_joint_robot)
    ball = offset(ball_joint_marker, ball_joint_robot)
    hinge_kinematic = offset(hinge_joint_marker_kinematic, hinge_joint_robot_kinematic)
    ball_kinematic = offset(ball_joint_marker_kinematic, ball_joint_robot_kinematic)
    # 0.02: small difference due to the dummy intermediate solids in the hinges case
    ts_assert_vec3_in_delta(hinge[0], hinge[1], hinge[2], ball[0], ball[1], ball[2], 0.02,
                            "Positions of the hinges and ball joints targets differ.")
    ts_assert_vec3_in_delta(hinge[0], hinge[1], hinge[2], hinge_kinematic[0], hinge_kinematic[1], hinge_kinematic[2],
                            0.02, "Positions of the kinematic and dynamic hinge joints targets differ.")
    ts_assert_vec3_in_delta(ball[0], ball[1], ball[2], ball_kinematic[0], ball_kinematic[1], ball_kinematic[2], 0.02,
                            "Positions of the kinematic and dynamic ball joints targets differ.")

ball_joint_marker_pos = ball_joint_marker.getPosition()
ts_assert_vec3_in_delta(ball_joint_marker_pos[0], ball_joint_marker_pos[1], ball_joint_marker_pos[2], 0.129531,
                        0.155783, 0.223086, 0.001, "Final position of the targets not at the expected position.")

ts_send_success()
