"""Port of Webots' tests/protos/controllers/template_node_id: a template robot PROTO receives its node id as
context.id and passes it as controllerArgs to its controller (copy_args_in_custom_data), which writes it into
customData. The id must match wb_supervisor_node_get_id and stay the same when the PROTO is regenerated; references
to the PROTO's internal nodes and fields become invalid on regeneration and can be looked up again, while fields of
nodes given as parameters (the slot's Shape and ImageTexture) stay valid and settable.

Run by template_node_id.wbt (JavaScript template) and its _lua variant (Lua template). The test name comes from
controllerArgs, as the C original's ts_setup(argv[1]); its spaces become underscores because the runner's result
lines are space-separated ("template_node_id (lua)" -> "template_node_id_(lua)").
"""

import re
import sys

from controller import Field, Supervisor
from ts_assertion import (
    ts_assert_boolean_not_equal,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_assert_pointer_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
WB_NO_FIELD = 0  # C: WB_NO_FIELD (the field type of an invalid field reference)


def sscanf_int(text, previous):
    """C: sscanf(text, "%d", &value): the leading integer, or the variable unchanged when there is none."""
    match = re.match(r"\s*[-+]?\d+", text or "")
    return int(match.group()) if match else previous


supervisor = Supervisor()
ts_setup(supervisor, sys.argv[1])  # give the controller args

# let the time for the robot controller to copy the args in customData field
supervisor.step(5 * TIME_STEP)

robot = supervisor.getFromDef("ROBOT")
custom_data_field = robot.getField("customData")
procedural_field = robot.getField("proceduralField")

texture = supervisor.getFromDef("TEXTURE")
ts_assert_pointer_not_null(texture, "Can't find TEXTURE node.")
repeats_field = texture.getField("repeatS")
ts_assert_pointer_not_null(repeats_field, "Can't find 'repeatS' field of TEXTURE node.")

shape = supervisor.getFromDef("SHAPE")
ts_assert_pointer_not_null(shape, "Can't find SHAPE node.")

internal_node = robot.getFromProtoDef("INTERNAL")
ts_assert_pointer_not_null(internal_node, "Can't find INTERNAL node.")

internal_children_field = internal_node.getField("children")
ts_assert_pointer_not_null(internal_children_field, "Can't find 'children' field of INTERNAL node.")

field_content = custom_data_field.getSFString()
id = sscanf_int(field_content, None)

ts_assert_int_equal(
    id, robot.getId(),
    "The 'id' returned by 'wb_supervisor_node_get_id' does not match the one received by the PROTO as 'context.id'.")

custom_data_field.setSFString("")
procedural_field.setSFString("")
supervisor.step(5 * TIME_STEP)

new_field_content = custom_data_field.getSFString()
new_id = sscanf_int(new_field_content, None)

ts_assert_int_equal(id, new_id, "The 'id' received by the PROTO as 'context.id' has changed when the PROTO was regenerated.")

ts_assert_int_equal(
    new_id, robot.getId(),
    "The 'id' returned by 'wb_supervisor_node_get_id' does not match the one received by the PROTO as 'context.id'.")

root_node = supervisor.getRoot()
ts_assert_int_equal(0, root_node.getId(), "The 'id' of the root node should be '0'.")

# test that fields can be retrieved (for the first time) even after PROTO regeneration
field_type = internal_children_field.getType()
ts_assert_int_equal(field_type, WB_NO_FIELD,
                    "'children' field reference of INTERNAL node should be invalid after PROTO regeneration.")
internal_translation_field = internal_node.getField("translation")
ts_assert_pointer_null(internal_translation_field, "INTERNAL node reference should be invalid after PROTO regeneration.")
internal_node = robot.getFromProtoDef("INTERNAL")
ts_assert_pointer_not_null(internal_node, "Can't find INTERNAL node after PROTO regeneration.")
internal_translation_field = internal_node.getField("translation")
ts_assert_pointer_not_null(internal_translation_field, "Can't find 'translation' field of INTERNAL node.")
field_type = internal_translation_field.getType()
ts_assert_int_equal(field_type, Field.SF_VEC3F, "'translation' field of INTERNAL node is invalid.")

root_children_field = root_node.getField("children")
ts_assert_pointer_not_null(root_children_field, "Can't find 'children' field of root node.")

controller_field = robot.getField("controller")
ts_assert_pointer_not_null(controller_field, "Can't find 'controller' field of ROBOT node.")

appearance_field = shape.getField("appearance")
ts_assert_pointer_not_null(appearance_field, "Can't find 'appearance' field of SHAPE node.")

repeatt_field = texture.getField("repeatT")
ts_assert_pointer_not_null(repeatt_field, "Can't find 'repeatS' field of TEXTURE node.")

# test that fields can still be modified after PROTO regeneration

repeats_field.setSFBool(False)
repeatt_field.setSFBool(False)

supervisor.step(TIME_STEP)

ts_assert_boolean_not_equal(repeats_field.getSFBool(), "'repeatS' field has not been set.")
ts_assert_boolean_not_equal(repeatt_field.getSFBool(), "'repeatT' field has not been set.")

ts_send_success()
