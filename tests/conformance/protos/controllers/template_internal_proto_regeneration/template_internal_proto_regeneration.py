"""Port of Webots' tests/protos/controllers/template_internal_proto_regeneration: a template PROTO holds a non-template
PROTO (derived from another PROTO, a sphere of radius 0.2) as a child; changing the template's color parameter
regenerates it, and the internal PROTO must keep its parameter values: an infra-red distance sensor reads 970 before
and after.

Run by template_internal_proto_regeneration.wbt (JavaScript template) and its _lua variant (Lua template).
"""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
EXPECTED = 970.0

robot = Supervisor()
ts_setup(robot)

object_node = robot.getFromDef("OBJECT")
color_field = object_node.getField("color")

ds = robot.getDevice("distance sensor")
ds.enable(TIME_STEP)

robot.step(TIME_STEP)

# 970 when radius is correct
value = ds.getValue()
ts_assert_double_in_delta(value, EXPECTED, 1.0, "Unexpected initial object size: measured %f, expected %f.", value,
                          EXPECTED)

new_color = [0.0, 1.0, 0.0]
color_field.setSFColor(new_color)

robot.step(TIME_STEP)

# value = 170 if parameter value is not correctly applied
value = ds.getValue()
ts_assert_double_in_delta(value, EXPECTED, 1.0, "Unexpected object size after PROTO regeneration: measured %f, "
                          "expected %f.", value, EXPECTED)

ts_send_success()
