"""Port of Webots' tests/physics/controllers/radar_rays: radars with and without occlusion count a fixed and a falling
target correctly step after step, whether the radars stand still ("static" robot) or are driven by wheels during the
physics step ("dynamic" robot)."""

import sys

from controller import Robot
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot, sys.argv[1])

count = 0
expected_count = 0
time_step = int(robot.getBasicTimeStep())
dynamic = robot.getName() != "static"

rs = robot.getDevice("radar static")
rd = robot.getDevice("radar dynamic")
ros = robot.getDevice("radar occlusion static")
rod = robot.getDevice("radar occlusion dynamic")
rs.enable(time_step)
rd.enable(time_step)
ros.enable(time_step)
rod.enable(time_step)

robot.step(3 * time_step)

if dynamic:
    left_motor = robot.getDevice("left motor")
    right_motor = robot.getDevice("right motor")
    left_motor.setPosition(float("inf"))
    right_motor.setPosition(float("inf"))
    left_motor.setVelocity(100)
    right_motor.setVelocity(100)

# without occlusion
count = rs.getNumberOfTargets()
ts_assert_int_equal(count, 1, "Radar without occlusion detects the wrong number of static objects at check 1: "
                    "expected %d, detected %d", 1, count)
count = rd.getNumberOfTargets()
ts_assert_int_equal(count, 1, "Radar without occlusion detects the wrong number of dynamic objects at check 1: "
                    "expected %d, detected %d", 1, count)

# with occlusion
count = ros.getNumberOfTargets()
ts_assert_int_equal(count, 1, "Radar with occlusion detects the wrong number of static objects at check 1: "
                    "expected %d, detected %d", 1, count)
count = rod.getNumberOfTargets()
ts_assert_int_equal(count, 1, "Radar with occlusion detects the wrong number of dynamic objects at check 1: "
                    "expected %d, detected %d", 1, count)

robot.step(time_step)

expected_count = 0 if dynamic else 1

# without occlusion
count = rs.getNumberOfTargets()
ts_assert_int_equal(count, expected_count, "Radar without occlusion detects the wrong number of static objects at "
                    "check 2: expected %d, detected %d", expected_count, count)
count = rd.getNumberOfTargets()
ts_assert_int_equal(count, expected_count, "Radar without occlusion detects the wrong number of dynamic objects at "
                    "check 2: expected %d, detected %d", expected_count, count)

# with occlusion
count = ros.getNumberOfTargets()
ts_assert_int_equal(count, expected_count, "Radar with occlusion detects the wrong number of static objects at "
                    "check 2: expected %d, detected %d", expected_count, count)
count = rod.getNumberOfTargets()
ts_assert_int_equal(count, expected_count, "Radar with occlusion detects the wrong number of dynamic objects at "
                    "check 2: expected %d, detected %d", expected_count, count)

robot.step(time_step)

ts_send_success()
