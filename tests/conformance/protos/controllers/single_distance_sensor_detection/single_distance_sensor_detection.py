"""Port of Webots' tests/protos/controllers/single_distance_sensor_detection: the distance sensor sees the box held by
a Slot given as the endPoint parameter of a PROTO's Slot (the world simple_slot_parameter).

The C original registers the test by the controller's name (ts_setup(argv[0])); the world's controllerArgs
("simple_slot_parameter") are not used.
"""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 16

robot = Robot()
ts_setup(robot)

ds = robot.getDevice("distance sensor")
ds.enable(TIME_STEP)

robot.step(TIME_STEP)

value = ds.getValue()
ts_assert_double_in_delta(value, 500.0, 10.0, "Slot node in parameter is not loaded correctly.")

ts_send_success()
