"""Port of Webots' tests/api/controllers/robot_wait_for_user_input_event: waitForUserInputEvent answers
EVENT_NO_EVENT at once while the keyboard is disabled, and after its 2 s timeout (wall clock) once it is enabled."""

import time

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIMEOUT = 2000
TIME_STEP = 32

robot = Robot()
ts_setup(robot)

start = time.time()
event_type = robot.waitForUserInputEvent(Robot.EVENT_KEYBOARD, TIMEOUT)
ts_assert_int_equal(event_type, Robot.EVENT_NO_EVENT, "wb_robot_wait_for_user_input_event should return "
                    "WB_EVENT_NO_EVENT.")
elapsed_time = time.time() - start

ts_assert_double_in_delta(elapsed_time, 0.0, 0.01, "wb_robot_wait_for_user_input_event should return immediatly when "
                          "the keyboard is not enabled (and not after %lfsec).", elapsed_time)

robot.getKeyboard().enable(TIME_STEP)

start = time.time()
event_type = robot.waitForUserInputEvent(Robot.EVENT_KEYBOARD, TIMEOUT)
ts_assert_int_equal(event_type, Robot.EVENT_NO_EVENT, "wb_robot_wait_for_user_input_event should return "
                    "WB_EVENT_NO_EVENT.")
elapsed_time = time.time() - start

ts_assert_double_in_delta(elapsed_time, 0.001 * TIMEOUT + 0.1, 0.3, "wb_robot_wait_for_user_input_event should return "
                          "after 2sec when the keyboard is enabled (and not after %lfsec).", elapsed_time)

ts_send_success()
