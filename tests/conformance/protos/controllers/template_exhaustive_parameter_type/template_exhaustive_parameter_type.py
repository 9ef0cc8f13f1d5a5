"""Port of Webots' tests/protos/controllers/template_exhaustive_parameter_type: the robot's PROTO template checks the
value of a parameter of every type (SFBool ... SFNode, a PROTO SFNode and its node_name, MFInt32, default values)
and writes "success" or the first failed check into the robot's model; its customData comes from a string parameter.

Run by template_exhaustive_parameter_type.wbt (JavaScript template) and its _lua variant (Lua template).
"""

from controller import Robot
from ts_assertion import ts_assert_string_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

template_result = robot.getModel()
ts_assert_string_equal(template_result, "success", "Unexpected template result: %s", template_result)

custom_data = robot.getCustomData()
ts_assert_string_equal(custom_data, "custom data", "Unexpected custom data result: %s", custom_data)

ts_send_success()
