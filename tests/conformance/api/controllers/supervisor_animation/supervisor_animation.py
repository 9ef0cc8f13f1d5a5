"""Port of Webots' tests/api/controllers/supervisor_animation: animationStartRecording and animationStopRecording
succeed and leave animation.html, .json, .x3d and .css beside the controller."""

import os

from controller import Supervisor
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

for name in ("animation.html", "animation.json", "animation.x3d", "animation.css"):
    if os.path.exists(name):
        os.remove(name)

success = robot.animationStartRecording("animation.html")
ts_assert_boolean_equal(success, "Animation start recording has failed.")

for _ in range(20):
    robot.step(TIME_STEP)

success = robot.animationStopRecording()
ts_assert_boolean_equal(success, "Animation stop recording has failed.")

ts_assert_boolean_equal(os.path.exists("animation.html"), "animation.html not created.")
ts_assert_boolean_equal(os.path.exists("animation.json"), "animation.json not created.")
ts_assert_boolean_equal(os.path.exists("animation.x3d"), "animation.x3d not created.")
ts_assert_boolean_equal(os.path.exists("animation.css"), "animation.css not created.")

ts_send_success()
