"""Port of Webots' tests/protos/controllers/proto_default_def_node (its version at 895b2580, the one with a single
"box sensor" as the world has): a DEF node in a PROTO field's default value (DEF BOX) is found by a USE in the value
the world gives another field, so the second Solid has a box and the distance sensor sees it."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)  # give the controller args

box_sensor = robot.getDevice("box sensor")

box_sensor.enable(TIME_STEP)

robot.step(TIME_STEP)

# test default DEF BOX parameter is found at load
value = box_sensor.getValue()
ts_assert_double_in_delta(value, 300.0, 0.1, "Default DEF node not found at load.")

ts_send_success()
