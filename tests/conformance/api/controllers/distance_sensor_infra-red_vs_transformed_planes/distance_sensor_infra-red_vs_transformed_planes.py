"""Port of Webots' tests/api/controllers/distance_sensor_infra-red_vs_transformed_planes: ten infra-red sensors
against a plain, a rotated and a flipped Plane (the flipped one is not seen)."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
N_DISTANCE_SENSORS = 10

OBSTACLE = 833.3333
NO_OBSTACLE = 1000.0

EXPECTED_VALUES = (NO_OBSTACLE, OBSTACLE, OBSTACLE, OBSTACLE, NO_OBSTACLE,
                   OBSTACLE, OBSTACLE, NO_OBSTACLE, NO_OBSTACLE, NO_OBSTACLE)

robot = Robot()
ts_setup(robot)

ds = []
for i in range(N_DISTANCE_SENSORS):
    sensor = robot.getDevice(chr(ord("A") + i))
    sensor.enable(TIME_STEP)
    ds.append(sensor)

robot.step(TIME_STEP)

for i in range(N_DISTANCE_SENSORS):
    value = ds[i].getValue()
    ts_assert_double_in_delta(value, EXPECTED_VALUES[i], 0.01,
                              "Distance sensor '%c' doesn't return the right distance when hitting an object "
                              "(expected = %f, received = %f)",
                              chr(ord("A") + i), EXPECTED_VALUES[i], value)

robot.step(TIME_STEP)

ts_send_success()
