"""wbtc's version of Webots' python_device_refresh test: devices imported at run time are found by the API."""

from controller import Supervisor
from ts_assertion import (
                    ts_assert_boolean_equal,
                    ts_assert_int_equal,
                    ts_assert_pointer_not_null,
                    ts_send_success,
                    ts_setup,
)

TIME_STEP = 64

robot = Supervisor()
ts_setup(robot)

devices_at_start = robot.getNumberOfDevices()
children = robot.getSelf().getField("children")

# getDevice finds a device imported after start-up, before anything else refreshed the devices.
children.importMFNodeFromString(-1, 'DistanceSensor { name "late_sensor" }')
robot.step(TIME_STEP)
count = robot.getNumberOfDevices()
ts_assert_int_equal(count, devices_at_start + 1, "The number of devices should be %d after the first import, not %d.",
                    devices_at_start + 1, count)
sensor = robot.getDevice("late_sensor")
ts_assert_pointer_not_null(sensor, 'Robot.getDevice did not find the imported device "late_sensor".')
kind = type(sensor).__name__
ts_assert_boolean_equal(kind == "DistanceSensor", 'Robot.getDevice returned a %s for "late_sensor", expected a DistanceSensor.',
                        kind)

# Likewise getDeviceByIndex, before any getDevice call refreshed the devices.
children.importMFNodeFromString(-1, 'Camera { name "late_camera" width 4 height 4 }')
robot.step(TIME_STEP)
count = robot.getNumberOfDevices()
ts_assert_int_equal(count, devices_at_start + 2, "The number of devices should be %d after the second import, not %d.",
                    devices_at_start + 2, count)
camera = robot.getDeviceByIndex(devices_at_start + 1)
kind = type(camera).__name__
ts_assert_boolean_equal(kind == "Camera", "Robot.getDeviceByIndex returned a %s for the imported camera, expected a Camera.",
                        kind)
ts_assert_boolean_equal(camera is robot.getDevice("late_camera"),
                        'Robot.getDeviceByIndex and Robot.getDevice returned different objects for "late_camera".')

sensor.enable(TIME_STEP)
robot.step(TIME_STEP)
sensor.getValue()

ts_send_success()
