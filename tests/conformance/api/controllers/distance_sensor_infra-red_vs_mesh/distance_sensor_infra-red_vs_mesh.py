"""Port of Webots' tests/api/controllers/distance_sensor_infra-red_vs_mesh: twenty infra-red sensors against two
Mesh shapes (plain and textured), each checked against its detection flag."""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

TIME_STEP = 32
N_DISTANCE_SENSORS = 20

NO_OBSTACLE = 1000.0

# As in the C original, the assertion below passes when the detection differs from this flag.
EXPECTED_DETECTION = (True, False, False, False, True, True, True, True, True, True,
                      False, False, False, False, True, False, False, False, False, True)

robot = Robot()
ts_setup(robot)

ds = []
for i in range(N_DISTANCE_SENSORS):
    sensor = robot.getDevice(chr(ord("A") + i))
    sensor.enable(TIME_STEP)
    ds.append(sensor)

robot.step(TIME_STEP)

for i in range(N_DISTANCE_SENSORS):
    detection = ds[i].getValue() < NO_OBSTACLE
    ts_assert_boolean_equal(detection != EXPECTED_DETECTION[i],
                            "Distance sensor '%c' doesn't return the right distance when hitting an object",
                            chr(ord("A") + i))

robot.step(TIME_STEP)

ts_send_success()
