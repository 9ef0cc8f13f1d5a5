"""Port of Webots' tests/api/controllers/touch_sensor_force3d: a force-3d TouchSensor reads a zero vector in free fall
and (0, 0, -9.81) N in its own frame on the floor."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 16

robot = Robot()
ts_setup(robot)

ts = robot.getDevice("touch sensor")
ts.enable(TIME_STEP)

for _ in range(5):
    robot.step(TIME_STEP)

values = ts.getValues()
for i in range(3):
    ts_assert_double_in_delta(values[i], 0.0, 0.0001,
                              "The \"force3d\" TouchSensor should return [0.0 0.0 0.0] N in free fall.")

for _ in range(100):
    robot.step(TIME_STEP)

values = ts.getValues()
expected = (0.0, 0.0, -9.81)
for i in range(3):
    ts_assert_double_in_delta(values[i], expected[i], 0.1,
                              "The \"force3d\" TouchSensor doesn't return the right values when on the floor.")

ts_send_success()
