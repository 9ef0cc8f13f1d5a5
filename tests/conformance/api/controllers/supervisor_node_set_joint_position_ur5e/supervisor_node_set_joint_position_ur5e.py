"""Port of Webots' tests/api/controllers/supervisor_node_set_joint_position_ur5e: Node.setJointPosition on a joint
inside the UR5e PROTO (found from its motor with getFromDevice and getParentNode) moves the tool's GPS."""

from controller import Supervisor
from ts_assertion import ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

gps = robot.getDevice("gps")
gps.enable(TIME_STEP)

robot.step(TIME_STEP)

initial_gps_value = gps.getValues()
print("initial_gps_value %f %f %f" % (initial_gps_value[0], initial_gps_value[1], initial_gps_value[2]))
ts_assert_vec3_in_delta(initial_gps_value[0], initial_gps_value[1], initial_gps_value[2], 0.8170, 0.0628, -0.2340, 0.0001,
                        "Wrong initial position of UR5e tool.")

shoulder_lift_motor = robot.getDevice("shoulder_lift_joint")
shoulder_lift_motor_node = robot.getFromDevice(shoulder_lift_motor)
shoulder_lift_joint_node = shoulder_lift_motor_node.getParentNode()
shoulder_lift_joint_node.setJointPosition(-1.55, 1)

robot.step(TIME_STEP)

new_gps_value = gps.getValues()
print("new_gps_value %f %f %f" % (new_gps_value[0], new_gps_value[1], new_gps_value[2]))
ts_assert_vec3_in_delta(new_gps_value[0], new_gps_value[1], new_gps_value[2], 0.1170, 0.9776, -0.2340, 0.0001,
                        "Wrong initial position of UR5e tool.")

ts_send_success()
