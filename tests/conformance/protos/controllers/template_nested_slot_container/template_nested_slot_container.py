"""Port of Webots' tests/protos/controllers/template_nested_slot_container: a template PROTO passes two SFNode
parameters into the Slots of a nested PROTO; the world's DEF TEST_BOX geometry in one and its USE in the other must
stay linked after the template is regenerated (its regenerate field set): two infra-red distance sensors read 1000
(nothing in range), then 500 once the supervisor lengthens TEST_BOX.

Run by template_nested_slot_container.wbt (JavaScript template) and its _lua variant (Lua template). The test name
comes from controllerArgs, as the C original's ts_setup(argv[1]); its spaces become underscores because the runner's
result lines are space-separated ("template_nested_slot_container (lua)" -> "template_nested_slot_container_(lua)").
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

robot = Supervisor()
ts_setup(robot, sys.argv[1])  # give the controller args

time_step = int(robot.getBasicTimeStep())

ds_def = robot.getDevice("ds def")
ds_use = robot.getDevice("ds use")
ds_def.enable(time_step)
ds_use.enable(time_step)

# Regenerate procedural PROTO by modifying template field
template_node = robot.getFromDef("TEST_PROTO")
template_field = template_node.getField("regenerate")
template_field.setSFBool(True)

robot.step(time_step)

# Check initial size of boxes
ts_assert_double_in_delta(ds_def.getValue(), 1000.0, 0.1, "Wrong initial size of DEF TEST_BOX.")
ts_assert_double_in_delta(ds_use.getValue(), 1000.0, 0.1, "Wrong initial size of USE TEST_BOX.")

# Increase boxes size
box_node = robot.getFromDef("TEST_BOX")

size_field = box_node.getField("size")
new_size = [0.1, 0.1, 0.5]
size_field.setSFVec3f(new_size)

robot.step(time_step)

# Check new boxes size
ts_assert_double_in_delta(ds_def.getValue(), 500.0, 0.1, "Size of DEF TEST_BOX not updated after template regeneration.")
ts_assert_double_in_delta(ds_use.getValue(), 500.0, 0.1, "Size of USE TEST_BOX not updated after template regeneration.")

ts_send_success()
