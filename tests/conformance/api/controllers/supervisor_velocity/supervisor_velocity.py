"""Port of Webots' tests/api/controllers/supervisor_velocity: Node.setVelocity moves and turns kinematic Solids
(without physics, a child carried along) and dynamic ones (falling too) for 20 steps; their positions, rotation fields
and getVelocity then match the expected values."""

from controller import Supervisor
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_doubles_in_delta,
    ts_assert_pointer_not_null,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

velocities = [[0, 0, 0, 0.5, 0, 1], [1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 1], [0, 0, 0, 1, 0, 1], [1, 0, 1, 0, 0, 1],
              [0, 1, 0, 0, 0, 1]]

expected_position = [[-0.4, 0.2, 0.8], [0.64, 0, 0.5], [0.5, 0.64, 0.5], [-0.5, -2.11, -0.5], [0.64, -2.11, 0.14],
                     [0.5, -1.47, -0.5], [0.64, 0.2, 0.5]]

expected_rotation = [[0.45, 0, 0.895, 0.716], [0, 0, 1, 0], [0, 0, 1, 0.64], [0.7, 0, 0.7, 0.9], [0, 0, 1, 0.64],
                     [0, 0, 1, 0.64], [0, 0, 1, 0]]

expected_velocities = [[0, 0, 0, 0.5, 0, 1], [1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 1], [0, -6.28, 0, 1, 0, 1],
                       [1, -6.28, 1, 0, 0, 1], [0, -5.28, 0, 0, 0, 1], [1, 0, 0, 0, 0, 0]]

node_names = ["KINEMATIC_ROTATE", "KINEMATIC_TRANSLATE", "KINEMATIC_TRANSLATE_ROTATE", "DYNAMIC_ROTATE",
              "DYNAMIC_TRANSLATE", "DYNAMIC_TRANSLATE_ROTATE", "KINEMATIC_TRANSLATE_CHILDREN"]

robot = Supervisor()
ts_setup(robot)

nodes = []
rotation_fields = []
for i in range(7):
    node = robot.getFromDef(node_names[i])
    ts_assert_pointer_not_null(node, "The supervisor cannot get the WbNodeRef of %s.", node_names[i])
    rotation_field = node.getField("rotation")
    ts_assert_pointer_not_null(rotation_field, "The supervisor cannot get the rotationField field of %s.", node_names[i])
    if i < 6:
        node.setVelocity(velocities[i])
    nodes.append(node)
    rotation_fields.append(rotation_field)

for _ in range(20):
    robot.step(TIME_STEP)

for i in range(7):
    position = nodes[i].getPosition()
    ts_assert_vec3_in_delta(position[0], position[1], position[2], expected_position[i][0], expected_position[i][1],
                            expected_position[i][2], 0.02,
                            "Solid %s is not at the expected position [%lf %lf %lf] instead of [%lf %lf %lf].",
                            node_names[i], position[0], position[1], position[2], expected_position[i][0],
                            expected_position[i][1], expected_position[i][2])

    r = rotation_fields[i].getSFRotation()
    if r[3] * expected_rotation[i][3] < 0:
        rotation = [-value for value in r[:4]]
    else:
        rotation = list(r[:4])
    ts_assert_double_in_delta(rotation[3], expected_rotation[i][3], 0.02,
                              "Solid %s has not the expected orientation angle %lf instead of %lf.", node_names[i],
                              rotation[3], expected_rotation[i][3])
    ts_assert_vec3_in_delta(rotation[0], rotation[1], rotation[2], expected_rotation[i][0], expected_rotation[i][1],
                            expected_rotation[i][2], 0.01,
                            "Solid %s has not the expected orientation axis [%lf %lf %lf] instead of [%lf %lf %lf].",
                            node_names[i], rotation[0], rotation[1], rotation[2], expected_rotation[i][0],
                            expected_rotation[i][1], expected_rotation[i][2])

    velocity = nodes[i].getVelocity()
    ts_assert_doubles_in_delta(6, velocity, expected_velocities[i], 0.02,
                               "Solid %s has not the expected velocity [%lf %lf %lf %lf %lf %lf] instead of [%lf %lf %lf "
                               "%lf %lf %lf].", node_names[i], velocity[0], velocity[1], velocity[2], velocity[3],
                               velocity[4], velocity[5], *expected_velocities[i])

ts_send_success()
