"""Port of Webots' tests/protos/controllers/nested_parameter_transform_node: the position of a node given as a nested
PROTO parameter, and of a node DEF'd inside a PROTO definition nested twice, before and after the top PROTO moves."""

from controller import Supervisor
from ts_assertion import ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 64

robot = Supervisor()
ts_setup(robot)  # give the controller args

parent_node = robot.getFromDef("PARENT")
translation = parent_node.getField("translation")

# Test position update of node defined in nested PROTO parameter
parameter_node = robot.getFromDef("PARAMETER")
parameter_position = parameter_node.getPosition()
ts_assert_vec3_in_delta(parameter_position[0], parameter_position[1], parameter_position[2], 0.45, 0.5, 0.03, 0.0001,
                        "Position of visible nested PROTO parameter is wrong.")

# Test position update of node defined in a PROTO definition
test_node = parent_node.getFromProtoDef("TEST_PROTO")
robot.step(TIME_STEP)
position_before = test_node.getPosition()
ts_assert_vec3_in_delta(position_before[0], position_before[1], position_before[2], 3.0, 0.0, 1.0, 0.0001,
                        "Initial position of deeply nested PROTO parameter is wrong.")

new_position = [0.0, 1.0, 0.0]
translation.setSFVec3f(new_position)

robot.step(TIME_STEP)

position_after = test_node.getPosition()
ts_assert_vec3_in_delta(position_after[0], position_after[1], position_after[2], 2.0, 1.0, 1.0, 0.0001,
                        "Position of deeply nested PROTO parameter is wrong after top node position change.")

ts_send_success()
