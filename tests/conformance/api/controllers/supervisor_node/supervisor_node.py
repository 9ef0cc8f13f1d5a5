"""Port of Webots' tests/api/controllers/supervisor_node: the Node API of a supervisor (root, self, getFromDef,
getFromId, getFromDevice, types and type names, parents, fields, positions and orientations, saveState and
loadState, exportString), and a non-supervisor robot's NULL answers.

The C test's calls with a NULL node or a NULL name (wb_supervisor_node_get_field(NULL, ...),
wb_supervisor_node_get_from_def(NULL), wb_supervisor_node_get_field(material, NULL)) are C-only and not ported.
"""

import math

from controller import Node, Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_doubles_equal,
    ts_assert_doubles_in_delta,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_assert_pointer_null,
    ts_assert_string_contains,
    ts_assert_string_equal,
    ts_assert_vec3_equal,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

sick_lidar = robot.getDevice("Sick LMS 291")
compass = robot.getDevice("compass")

time = robot.getTime()
ts_assert_boolean_equal(time == 0.0, "Starting time is wrong. Expected=0.0. Received=%f\n", time)

if robot.getName() != "supervisor":
    root = robot.getRoot()
    ts_assert_pointer_null(root, "A non supervisor node should return NULL when requesting the root node")
    node = robot.getFromDef("BOX")
    ts_assert_pointer_null(node, 'A non supervisor node should return NULL when requesting the "BOX" node')
    node = robot.getFromId(1)
    ts_assert_pointer_null(node, "A non supervisor node should return NULL when requesting the node having the '1' "
                           "unique id")
    ts_send_success()

root = robot.getRoot()
ts_assert_pointer_not_null(root, "Root node is not found")

i = root.getType()
ts_assert_int_equal(i, Node.GROUP, "Root node should have type %d not %d", Node.GROUP, i)

char_array = root.getTypeName()
ts_assert_string_equal(char_array, "Group", 'Root node should have type name "%s" not "%s"', "Group", char_array)

children = root.getField("children")
ts_assert_boolean_equal(children.getType() == children.MF_NODE, "Children has not the WB_MF_NODE type")

i = children.getCount()
# Webots' 12 root children include the TestSuiteSupervisor node, which the port removes from the world.
ROOT_CHILDREN = 12 - 1
ts_assert_int_equal(i, ROOT_CHILDREN, "Root node should have %d children not %d", ROOT_CHILDREN, i)

node = robot.getFromId(-1)
ts_assert_pointer_null(node, "Invalid test of wb_supervisor_node_get_from_id() failed")

node = robot.getFromId(0)
i = node.getType()
ts_assert_int_equal(i, Node.GROUP, "Root node should have type %d not %d", Node.GROUP, i)
i = node.getId()
ts_assert_int_equal(i, 0, "wb_supervisor_node_get_id(Node(0)): id doesn't match.")

node = robot.getFromId(1)
i = node.getType()
ts_assert_int_equal(i, Node.WORLD_INFO, "Root node should have type %d not %d", Node.WORLD_INFO, i)
i = node.getId()
ts_assert_int_equal(i, 1, "wb_supervisor_node_get_id(Node(1)): id doesn't match.")

node = robot.getFromId(2)
i = node.getType()
ts_assert_int_equal(i, Node.VIEWPOINT, "Root node should have type %d not %d", Node.VIEWPOINT, i)
i = node.getId()
ts_assert_int_equal(i, 2, "wb_supervisor_node_get_id(Node(2)): id doesn't match.")

robot_node = robot.getFromDef("ROBOT")
ts_assert_pointer_not_null(robot_node, '"ROBOT" node is not found')

i = robot_node.getType()
ts_assert_int_equal(i, Node.ROBOT, '"ROBOT" node should have type %d not %d', Node.ROBOT, i)

char_array = robot_node.getTypeName()
ts_assert_string_equal(char_array, "Robot", '"ROBOT" node should have type "%s" not "%s"', "Robot", char_array)

node = robot_node.getParentNode()
ts_assert_boolean_equal(node.getId() == root.getId(), "Parent node of robot should be the root node (found id = %d).",
                        node.getId())

solid = robot.getFromDef("BOX")
ts_assert_pointer_not_null(solid, '"BOX" node is not found')

i = solid.getType()
ts_assert_int_equal(i, Node.SOLID, '"BOX" node should have type %d not %d', Node.SOLID, i)

char_array = solid.getTypeName()
ts_assert_string_equal(char_array, "Solid", '"BOX" node should have type "%s" not "%s"', "Solid", char_array)

node = solid.getParentNode()
ts_assert_boolean_equal(node.getId() == robot_node.getId(), "Parent node of solid should be the robot node (found id = "
                        "%d).", node.getId())

material = robot.getFromDef("CAPSULE_MATERIAL")
ts_assert_pointer_not_null(material, '"CAPSULE_MATERIAL" node is not found')

i = material.getType()
ts_assert_int_equal(i, Node.MATERIAL, '"CAPSULE_MATERIAL" node should have type %d not %d', Node.MATERIAL, i)

char_array = material.getTypeName()
ts_assert_string_equal(char_array, "Material", '"CAPSULE_MATERIAL" node should have type "%s" not "%s"', "Material",
                       char_array)

proto = robot.getFromDef("CAN")
ts_assert_pointer_not_null(proto, '"CAN" proto node is not found')

i = proto.getType()
ts_assert_int_equal(i, Node.SOLID, '"CAN" proto node should have type %d not %d', Node.SOLID, i)

char_array = proto.getTypeName()
ts_assert_string_equal(char_array, "Can", '"CAN" proto node has type "%s" not "%s"', "Can", char_array)

char_array = proto.getBaseTypeName()
ts_assert_string_equal(char_array, "Solid", '"CAN" proto node has base type "%s" not "%s"', "Solid", char_array)

node = robot.getFromDef("DISTANCE_SENSOR")
ts_assert_pointer_not_null(node, '"DISTANCE_SENSOR" node is not found')

i = node.getType()
ts_assert_int_equal(i, Node.DISTANCE_SENSOR, '"DISTANCE_SENSOR" node should have type %d not %d', Node.DISTANCE_SENSOR,
                    i)

char_array = node.getTypeName()
ts_assert_string_equal(char_array, "DistanceSensor", '"DISTANCE_SENSOR" node should have type "%s" not "%s"',
                       "DistanceSensor", char_array)

node = robot.getFromDef("CAPSULE_GEOMETRY")
ts_assert_pointer_not_null(node, '"CAPSULE_GEOMETRY" node is not found')

i = node.getType()
ts_assert_int_equal(i, Node.CAPSULE, '"CAPSULE_GEOMETRY" node should have type %d not %d', Node.CAPSULE, i)

char_array = node.getTypeName()
ts_assert_string_equal(char_array, "Capsule", '"CAPSULE_GEOMETRY" node should have type "%s" not "%s"', "Capsule",
                       char_array)

node = robot.getFromDef("CONE_GEOMETRY")
ts_assert_pointer_not_null(node, '"CAPSULE_GEOMETRY" node is not found')

i = node.getType()
ts_assert_int_equal(i, Node.CONE, '"CONE_GEOMETRY" node should have type %d not %d', Node.CONE, i)

char_array = node.getTypeName()
ts_assert_string_equal(char_array, "Cone", '"CONE_GEOMETRY" node should have type "%s" not "%s"', "Cone", char_array)

node = robot.getFromDef("SPHERE_PHYSICS")
ts_assert_pointer_not_null(node, '"SPHERE_PHYSICS" node is not found')

i = node.getType()
ts_assert_int_equal(i, Node.PHYSICS, '"SPHERE_PHYSICS" node should have type %d not %d', Node.PHYSICS, i)

char_array = node.getTypeName()
ts_assert_string_equal(char_array, "Physics", '"SPHERE_PHYSICS" node should have type "%s" not "%s"', "Physics",
                       char_array)

node = robot.getFromDef("notExistingNode")
ts_assert_pointer_null(node, "Requesting a node with an invalid name sould return NULL")

field = proto.getField("notExistingFieldName")
ts_assert_pointer_null(field, "If a field with an invalid name is requested for a proto node, the result should be NULL")
field = solid.getField("")
ts_assert_pointer_null(field, "If a field with an empty name is requested for a solid node, the result should be NULL")

double_array = solid.getPosition()
ts_assert_vec3_in_delta(double_array[0], double_array[1], double_array[2], -0.2, 0.2, -0.2, 0.0001,
                        "Position of solid node should be [%f, %f, %f] not [%f, %f, %f]", -0.2, 0.2, -0.2,
                        double_array[0], double_array[1], double_array[2])

double_array = material.getPosition()
ts_assert_boolean_equal(math.isnan(double_array[0]) and math.isnan(double_array[1]) and math.isnan(double_array[2]),
                        "Position of material node should be NAN")

double_array = proto.getPosition()
ts_assert_vec3_in_delta(double_array[0], double_array[1], double_array[2], -0.21, 0.031, 0.24, 0.001,
                        "Position of proto node should be [%f, %f, %f] not [%f, %f, %f]", -0.21, 0.031, 0.24,
                        double_array[0], double_array[1], double_array[2])

ORIENTATION_MESSAGE = ("Orientation of %s node should be [%f, %f, %f; %f, %f, %f; %f, %f, %f] not "
                       "[%f, %f, %f; %f, %f, %f; %f, %f, %f]")

double_array = solid.getOrientation()
expected0 = [0.921, 0.326, 0.214, -0.214, 0.881, -0.422, -0.326, 0.342, 0.881]
ts_assert_doubles_in_delta(9, double_array, expected0, 0.001, ORIENTATION_MESSAGE, "solid", *expected0, *double_array)

double_array = material.getOrientation()
ts_assert_boolean_equal(all(math.isnan(value) for value in double_array[:9]),
                        "Orientation of material node should be NAN")

double_array = proto.getOrientation()
expected1 = [0.957, 0.204, 0.207, 0.212, 0.000, -0.977, -0.199, 0.979, -0.043]
ts_assert_doubles_in_delta(9, double_array, expected1, 0.001, ORIENTATION_MESSAGE, "proto", *expected1, *double_array)

self_node = robot.getSelf()
ts_assert_pointer_not_null(self_node, "Self node is not found")

i = self_node.getType()
ts_assert_int_equal(i, Node.ROBOT, "Self node should have type %d not %d", Node.ROBOT, i)

ts_assert_boolean_equal(robot.getSupervisor(), "'wb_robot_get_supervisor' should return true.")

controller = self_node.getField("controller")
ts_assert_pointer_not_null(controller, "Self node should have a controller field.")

char_array = controller.getSFString()
ts_assert_string_equal(char_array, "supervisor_node", 'Self node should have controller field set to "%s" not "%s"',
                       "supervisor_node", char_array)

robot.step(TIME_STEP)

time = robot.getTime()
ts_assert_boolean_equal(time == 0.001 * TIME_STEP, "Ending time is wrong. Expected=%f. Received=%f\n",
                        0.001 * TIME_STEP, time)

robot.step(TIME_STEP)

reset_target = robot.getFromDef("RESET_TARGET")
reset_target.saveState("custom_state")
state_rotation = list(reset_target.getField("rotation").getSFRotation())
state_position = list(reset_target.getField("translation").getSFVec3f())

self_by_tag = robot.getFromDevice(0)
ts_assert_pointer_not_null(self_by_tag, "Null node reference to self node by device tag")
ts_assert_boolean_equal(self_by_tag == robot.getSelf(), "Invalid node reference to self node by tag")

compass_node = robot.getFromDevice(compass)
ts_assert_pointer_not_null(compass_node, "Invalid compass node reference from device tag")
ts_assert_string_equal(compass_node.getDef(), "COMPASS", "Wrong compass node reference")

sick_node = robot.getFromDevice(sick_lidar)
ts_assert_pointer_not_null(sick_node, "Invalid Sick node reference from device tag")
sick_translation_field = sick_node.getField("translation")
ts_assert_pointer_not_null(sick_translation_field, "Invalid translation field for Sick node")
sick_translation = sick_translation_field.getSFVec3f()
ts_assert_vec3_equal(sick_translation[0], sick_translation[1], sick_translation[2], 0.39, 0.1, 0.4,
                     "Invalid translation value for Sick node")

reset_target.loadState("custom_state")
double_array = reset_target.getField("translation").getSFVec3f()
ts_assert_doubles_equal(3, state_position, double_array, "Current solid's position is not equal to the solid's position "
                        "on when the wb_supervisor_node_save_state function was called")

double_array = reset_target.getField("rotation").getSFRotation()
ts_assert_doubles_equal(4, state_rotation, double_array, "Current solid's rotation is not equal to the solid's rotation "
                        "on when the wb_supervisor_node_save_state function was called")

node = robot.getFromDef("CONE")
ts_assert_string_contains(node.exportString(), "DEF CONE Solid {", "The exported string is not valid")

ts_send_success()
