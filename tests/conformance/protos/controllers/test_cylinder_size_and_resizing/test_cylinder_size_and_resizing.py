"""Port of Webots' tests/protos/controllers/test_cylinder_size_and_resizing: a PROTO instance given as the default
value of an MFNode parameter (passed on through a derived PROTO, or a template PROTO) or written in a template PROTO's
MFNode parameter is placed under its parent Solid (a distance sensor reads 400) and resizing it from the supervisor
(template field "height" of the node DEF PARAMETER) takes the cylinder out of the sensor's range (1000); with the
argument "template_regeneration", the node DEF T is then moved through its `translation` after the template PROTO
holding it has been regenerated (400 again).

Run by derived_proto_with_default_parameter.wbt, derived_proto_with_template_default_parameter.wbt, the
template_proto_with_template_parameter_* and template_proto_with_nested_template_parameter_* worlds (JavaScript
templates) and their _lua variants (Lua templates). The test name comes from controllerArgs, as the C original's
ts_setup(argv[1]); its spaces become underscores because the runner's result lines are space-separated
("template_proto_with_template_parameter_1 (lua)" -> "template_proto_with_template_parameter_1_(lua)").
Only template_proto_with_nested_template_parameter_1 (and _lua) has a node DEF TEMPLATE_BOX: elsewhere the C test's
wb_supervisor_node_get_field(NULL, "xSize") and wb_supervisor_field_set_sf_float(NULL, 0.2) print Webots' error and
do nothing, so the port skips them when the node or field is missing.
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args

ds = robot.getDevice("distance sensor")
ds.enable(TIME_STEP)

parameterNode = robot.getFromDef("PARAMETER")
heightField = parameterNode.getField("height")

templateBoxNode = robot.getFromDef("TEMPLATE_BOX")
# C: wb_supervisor_node_get_field(NULL, ...) returns NULL when the node is missing.
xSizeField = templateBoxNode.getField("xSize") if templateBoxNode is not None else None

robot.step(TIME_STEP)

value = ds.getValue()
ts_assert_double_in_delta(value, 400, 5,
                          "Unexpected cylinder position due to incorrect parenting of derived parameter node instances.")

# resize cylinder
heightField.setSFFloat(0.15)

# resize box
if xSizeField is not None:  # C: wb_supervisor_field_set_sf_float(NULL, ...) is ignored.
    xSizeField.setSFFloat(0.2)

robot.step(TIME_STEP)

value = ds.getValue()
ts_assert_double_in_delta(value, 1000, 5,
                          "Unexpected cylinder size due to incorrect redirection of derived default parameter.")

if len(sys.argv) > 2 and sys.argv[2] == "template_regeneration":
    # check translation field redirection after node regeneration
    translationNode = robot.getFromDef("T")
    translationField = translationNode.getField("translation")

    # move cylinder
    newTranslation = [0.0, 0.15, 0.0]
    translationField.setSFVec3f(newTranslation)

    robot.step(TIME_STEP)

    value = ds.getValue()
    ts_assert_double_in_delta(
        value, 400, 5, "Unexpected cylinder position due to incorrect redirection of normal fields after template regeneration.")

ts_send_success()
