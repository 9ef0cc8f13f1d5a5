"""Port of Webots' tests/api/controllers/brake: a brake's damping slows its joint (0: none, 10000: held)."""

from controller import Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_assert_double_is_bigger,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Robot()
ts_setup(robot)
brakes = [robot.getDevice("brake %d" % i) for i in (1, 2, 3)]
brakes[0].setDampingConstant(0.0)
brakes[1].setDampingConstant(1.0)
brakes[2].setDampingConstant(10000.0)

sensors = [None] * 4
sensors[1] = brakes[0].getPositionSensor()
# C compares device tags; a device name is unique in a robot, so the names stand for the tags.
ts_assert_boolean_equal(sensors[1] is not None and sensors[1].getName() == "position sensor 2",
                        "wb_brake_get_position_sensor didn't work correctly.")
sensors[0] = robot.getDevice("position sensor 1")
sensors[2] = robot.getDevice("position sensor 3")
sensors[3] = robot.getDevice("position sensor 4")
for sensor in sensors:
    sensor.enable(TIME_STEP)
for _ in range(8):
    robot.step(TIME_STEP)

ps3 = brakes[1].getPositionSensor()
ts_assert_boolean_equal(ps3 is not None and ps3.getName() == sensors[2].getName(),
                        "wb_brake_get_position_sensor after simulation start didn't work correctly.")
angles = [sensor.getValue() for sensor in sensors]
ts_assert_double_in_delta(angles[0], angles[1], 0.01, "Joint 0 and 1 should have the same dynamic, because one has no "
                          "brake and the other has a brake set to 0.0.")
ts_assert_double_is_bigger(angles[1], angles[2], "Joint 2 should have a smaller angle than joint 1 because its brake is "
                           "set to a non-null value.")
ts_assert_double_in_delta(angles[3], 0, 0.001, "Joint 3 should have an angle close to 0.0, because its brake is set to a "
                          "very high value.")

ts_send_success()
