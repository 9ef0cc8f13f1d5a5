"""Port of Webots' tests/api/controllers/supervisor_restart_controller: Node.restartController restarts the
controller of a plain Robot and of a PROTO Robot, which then drive forwards (towards -z) again."""

from controller import Supervisor
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

TIME_STEP = 64

robot = Supervisor()
ts_setup(robot)

normal_robot = robot.getFromDef("MY_BOT")
proto_robot = robot.getFromDef("RESETTER")

robot.step(TIME_STEP)

normal_robot_position = normal_robot.getPosition()
proto_robot_position = proto_robot.getPosition()
ts_assert_boolean_equal(normal_robot_position[2] < 0.0,
                        "The base node controller is not started correctly and the base node robot did not move forwards.")
ts_assert_boolean_equal(proto_robot_position[2] < 0.0,
                        "The PROTO controller is not started correctly and the base node robot did not move forwards.")

robot.step(10 * TIME_STEP)

normal_robot_prev_z_position = normal_robot.getPosition()[2]
proto_robot_prev_z_position = proto_robot.getPosition()[2]

normal_robot.restartController()
proto_robot.restartController()

robot.step(2 * TIME_STEP)

normal_robot_position = normal_robot.getPosition()
print("Base Node Robot Position %f %f" % (normal_robot_prev_z_position, normal_robot_position[2]))
ts_assert_boolean_equal(normal_robot_prev_z_position > normal_robot_position[2],
                        "The base node robot's controller is not restarted correctly and the base node robot did not move "
                        "forwards.")

proto_robot_position = proto_robot.getPosition()
print("PROTO Robot Position %f %f" % (proto_robot_prev_z_position, proto_robot_position[2]))
ts_assert_boolean_equal(proto_robot_prev_z_position > proto_robot_position[2],
                        "The PROTO robot's controller is not restarted correctly and the base node robot did not move "
                        "forwards.")

ts_send_success()
