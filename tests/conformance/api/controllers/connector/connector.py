"""Port of Webots' tests/api/controllers/connector: presence and locking of a Yamor module's connectors
as the other module is released and falls."""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

rear_connector = robot.getDevice("rear_connector")
front_connector = robot.getDevice("front_connector")
rear_connector.enablePresence(TIME_STEP)
front_connector.enablePresence(TIME_STEP)

t = 0  # ms since the start
while robot.step(TIME_STEP) != -1:
    if t == 34 * TIME_STEP:
        ts_assert_int_equal(rear_connector.getPresence(), 1, "connector presence should be 1")
        ts_assert_boolean_equal(rear_connector.isLocked(), "connector should be locked")
        front_connector.unlock()
        rear_connector.unlock()
    elif t >= 38 * TIME_STEP:
        ts_assert_int_equal(rear_connector.getPresence(), 0,
                            "connector presence should be 0, as the other module should have fallen.")
        ts_assert_boolean_equal(not rear_connector.isLocked(), "connector should not be locked")
        break
    t += TIME_STEP

ts_send_success()
