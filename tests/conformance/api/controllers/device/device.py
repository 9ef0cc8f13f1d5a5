"""Port of Webots' tests/api/controllers/device: a device found by index has its node type, name and model."""

from controller import GPS, Node, Robot
from ts_assertion import (
                        ts_assert_boolean_equal,
                        ts_assert_doubles_in_delta,
                        ts_assert_int_equal,
                        ts_assert_string_equal,
                        ts_send_success,
                        ts_setup,
)

TIME_STEP = 64
EXPECTED_POSITION = [0.2, 0.0, 0.2]

robot = Robot()
ts_setup(robot)

forth_device = robot.getDeviceByIndex(3)
device_type = forth_device.getNodeType()
ts_assert_int_equal(device_type, Node.GPS, "Device type of forth device should be '%d' not '%d'.", Node.GPS, device_type)
name = forth_device.getName()
ts_assert_string_equal(name, "test_gps", "Device name of forth device should be '%s' not '%s'.", "test_gps", name)
model = forth_device.getModel()
ts_assert_string_equal(model, "gps model", "Device model of forth device should be '%s' not '%s'.", "gps model", model)

# C passes the index's tag to wb_gps_* directly; in Python the device found by index is a GPS object.
ts_assert_boolean_equal(isinstance(forth_device, GPS), "wb_robot_get_device_by_index should give the GPS its class.")
forth_device.enable(TIME_STEP)
robot.step(TIME_STEP)
values = forth_device.getValues()
ts_assert_doubles_in_delta(3, values, EXPECTED_POSITION, 0.0001, "Device 'test_gps' didn't return the expected value.")

gps = robot.getDevice("test_gps")
# Webots' Python Robot keeps one object per device: the same tag is the same object.
ts_assert_boolean_equal(forth_device is gps,
                        "wb_robot_get_device_by_index doesn't return the same WbDeviceTag as wb_robot_get_device.")

ts_send_success()
