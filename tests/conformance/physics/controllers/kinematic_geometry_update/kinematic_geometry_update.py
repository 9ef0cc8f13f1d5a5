"""Port of Webots' tests/physics/controllers/kinematic_geometry_update: a sleeping dynamic Solid resting on a static
box is woken up and pushed away when a supervisor enlarges that box's Box geometry."""

from controller import Supervisor
from ts_assertion import ts_assert_vec3_not_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

kinematic_box = robot.getFromDef("BOX_GEOMETRY")
kinematic_box_size_field = kinematic_box.getField("size")
solid = robot.getFromDef("SOLID")

# wait for SOLID to fall asleep
robot.step(2000)

position = list(solid.getPosition())
size = [0.9, 0.4, 0.9]
kinematic_box_size_field.setSFVec3f(size)

# give SOLID time to move
robot.step(512)

new_position = solid.getPosition()
ts_assert_vec3_not_in_delta(new_position[0], new_position[1], new_position[2], position[0], position[1], position[2],
                            0.01, "Solid 'SOLID' didn't moved when changing the size of the box.")

ts_send_success()
