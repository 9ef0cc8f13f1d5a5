"""Port of Webots' tests/api/controllers/joint_end_point_collision: rays hit a joint's end point Solid, before and
after the joint moves it. One controller for both robots: "obstacle" moves its slider, "sensors" checks its
three infra-red sensors (the test name comes from controllerArgs, as the C original's ts_setup(argv[1]))."""

import sys

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
OBSTACLE, SENSOR = 0, 1

robot = Robot()
ts_setup(robot, sys.argv[1])
motor = ir1 = ir2 = ir3 = None
tolerance = 50

name = robot.getName()
if name == "obstacle":
    robot_type = OBSTACLE
    motor = robot.getDevice("motor")
else:
    robot_type = SENSOR
    ir1 = robot.getDevice("ir1")
    ir2 = robot.getDevice("ir2")
    ir3 = robot.getDevice("ir3")
    ir1.enable(TIME_STEP)
    ir2.enable(TIME_STEP)
    ir3.enable(TIME_STEP)

robot.step(TIME_STEP)
robot.step(TIME_STEP)

if robot_type == SENSOR:
    # check initial sensor values
    value = ir1.getValue()
    ts_assert_double_in_delta(value, 350, tolerance,
                              "The value measured by the light sensor \"ir1\" should be 350 and not %g before joint moves",
                              value)

    value = ir2.getValue()
    ts_assert_double_in_delta(value, 350, tolerance,
                              "The value measured by the light sensor \"ir2\" should be 350 and not %g before joint moves",
                              value)

    value = ir3.getValue()
    ts_assert_double_in_delta(value, 1000, tolerance,
                              "The value measured by the light sensor \"ir3\" should be 1000 and not %g before joint moves",
                              value)

robot.step(TIME_STEP)

if robot_type == OBSTACLE:
    motor.setPosition(0.1)

i = 10
while i > 0 and robot.step(TIME_STEP) != -1:
    i -= 1

if robot_type == SENSOR:
    # check updated sensor values
    value = ir1.getValue()
    ts_assert_double_in_delta(value, 350, tolerance,
                              "The value measured by the light sensor \"ir1\" should be 350 and not %g after joint moved",
                              value)

    value = ir2.getValue()
    ts_assert_double_in_delta(value, 1000, tolerance,
                              "The value measured by the light sensor \"ir2\" should be 1000 and not %g after joint moved",
                              value)

    value = ir3.getValue()
    ts_assert_double_in_delta(value, 350, tolerance,
                              "The value measured by the light sensor \"ir3\" should be 350 and not %g after joint moved",
                              value)

ts_send_success()
