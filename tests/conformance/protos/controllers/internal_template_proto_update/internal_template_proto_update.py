"""Port of Webots' tests/protos/controllers/internal_template_proto_update: a PROTO parameter ("width") passed by IS
to a template parameter of an internal template PROTO (TemplateBoxShape's xSize) regenerates it when the supervisor
changes it; two infra-red distance sensors see the box grow.

Run by tests/protos/worlds/internal_template_proto.wbt.
"""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_assert_double_is_bigger, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

boxNode = robot.getFromDef("BOX")
widthField = boxNode.getField("width")

ds1 = robot.getDevice("ds1")
ds2 = robot.getDevice("ds2")
ds1.enable(TIME_STEP)
ds2.enable(TIME_STEP)

robot.step(TIME_STEP)

value = ds1.getValue()
ts_assert_double_in_delta(value, 1000, 10, "Unexpected box initial width for distance sensor 'ds1'.")
value = ds2.getValue()
ts_assert_double_in_delta(value, 1000, 10, "Unexpected box initial width for distance sensor 'ds2'.")

widthField.setSFFloat(0.25)

robot.step(TIME_STEP)

value = ds1.getValue()
ts_assert_double_is_bigger(500.0, value, "Unexpected box width after first update for distance sensor 'ds1'.")
value = ds2.getValue()
ts_assert_double_in_delta(value, 1000, 10, "Unexpected box width after first update for distance sensor 'ds2'.")

widthField.setSFFloat(0.5)

robot.step(TIME_STEP)

value = ds1.getValue()
ts_assert_double_is_bigger(500.0, value, "Unexpected box width after second update for distance sensor 'ds1'.")
value = ds2.getValue()
ts_assert_double_is_bigger(500.0, value, "Unexpected box width after second update for distance sensor 'ds2'.")

ts_send_success()
