"""Port of Webots' tests/protos/controllers/follow_solid_in_slot: the Viewpoint follows ("solid:solid(1)") a Solid
given in a PROTO's MFNode slot parameter; after 25 steps of fall its position moved down by the Solid's fall.
"""

from controller import Supervisor
from ts_assertion import ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

node = robot.getFromDef("VIEWPOINT")
position_field = node.getField("position")
position = position_field.getSFVec3f()
initial_position = list(position[:3])
expected_position = [initial_position[0], initial_position[1] - 3.26275, initial_position[2]]

robot.step(25 * TIME_STEP)

position = position_field.getSFVec3f()
ts_assert_vec3_in_delta(position[0], position[1], position[2], expected_position[0], expected_position[1],
                        expected_position[2], 0.01, "The Viewpoint position is not the expected one")

ts_send_success()
