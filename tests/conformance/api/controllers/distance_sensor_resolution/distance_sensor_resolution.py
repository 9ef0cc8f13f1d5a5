"""Port of Webots' tests/api/controllers/distance_sensor_resolution: values are multiples of `resolution`."""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)
resolution = [0, 0.01, 0.1, 0.3, 15]
ds = [robot.getDevice(f"ds{c}") for c in range(5)]

for sensor in ds:
    sensor.enable(TIME_STEP)

robot.step(TIME_STEP)

value = [sensor.getValue() for sensor in ds]

# ds1 to ds4: each value is its resolution times an integer (C: (int)(value / resolution + 0.5)).
for c in range(1, 5):
    reference = int(value[c] / resolution[c] + 0.5) * resolution[c]
    ts_assert_double_equal(value[c], reference, "Distance sensor 'ds%d' doesn't respect it's resolution field", c)

ts_send_success()
