"""Port of Webots' tests/protos/controllers/save_joint_proto_parameter: a HingeJoint given as a PROTO parameter (the
slot of SlotifiedRobot) with a non-zero position is saved and reloaded without moving its endPoint Solid: the first
run saves the world and loads the saved file, the controller of the reloaded world checks the Solid's pose."""

from controller import Supervisor
from ts_assertion import ts_assert_doubles_in_delta, ts_send_success, ts_setup

# The saved world sits beside the test world (so that its controller is found); the runner ignores *_temp.wbt.
temp_world_file_path = "../../worlds/save_joint_proto_parameter_temp.wbt"


def check_solid_position():
    expected_position = [0, 0.270151, 0.420735]
    expected_orientation = [1, 0, 0, 0, 0.540302, -0.841471, 0, 0.841471, 0.540302]
    solid = robot.getFromDef("TARGET")
    position = solid.getPosition()
    orientation = solid.getOrientation()
    ts_assert_doubles_in_delta(3, position, expected_position, 1e-6, "After saving the PROTO parameter Solid position "
                               "changed.")
    ts_assert_doubles_in_delta(9, orientation, expected_orientation, 1e-6,
                               "After saving the PROTO parameter Solid orientation changed.")


robot = Supervisor()

custom_data = robot.getCustomData()

if custom_data == "init":
    robot.setCustomData("save")
    robot.worldSave(temp_world_file_path)
    robot.worldLoad(temp_world_file_path)

else:
    ts_setup(robot, "save_joint_proto_parameter")

    check_solid_position()

    ts_send_success()
