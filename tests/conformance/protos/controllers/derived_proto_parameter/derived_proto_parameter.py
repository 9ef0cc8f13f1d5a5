"""Port of Webots' tests/protos/controllers/derived_proto_parameter: the default value of a PROTO's MFNode parameter
is a derived PROTO (DerivedSlotContainer) that replaces its base's default slot content (a BoxShape) with a
cylinder; two infra-red distance sensors check that no box and a cylinder were built.
"""

from controller import Robot
from ts_assertion import ts_assert_double_is_bigger, ts_send_success, ts_setup

TIME_STEP = 32

value = 0.0
robot = Robot()
ts_setup(robot)

ds1 = robot.getDevice("ds1")
ds2 = robot.getDevice("ds2")
ds1.enable(TIME_STEP)
ds2.enable(TIME_STEP)

robot.step(TIME_STEP)

value = ds1.getValue()
ts_assert_double_is_bigger(value, 500, "Unexpected shape: default base PROTO Box shape shouldn't be created.")

value = ds2.getValue()
ts_assert_double_is_bigger(1000, value, "Unexpected shape: derived PROTO Cylinder shape should be created.")

ts_send_success()
