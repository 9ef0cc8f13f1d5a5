"""Port of Webots' tests/physics/controllers/distance_sensor_rays: generic and infra-red sensors see a static and a
falling box at the right distance, step after step, whether the sensors stand still (the robot named "static") or are
driven by wheels during the physics step (the "dynamic" robot, which turns its "left motor" and "right motor" at
20 rad/s as the stored dynamic_distance_sensor_rays world and the motor version of the C controller do).
"""

import sys

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

OBJ_VALUE = 300.0
NONE_VALUE = 0.0


def check_sensor_value(sensor, expected, message):
    value = sensor.getValue()
    ts_assert_double_in_delta(value, expected, 0.005, message, expected, value)


robot = Robot()
ts_setup(robot, sys.argv[1])

time_step = int(robot.getBasicTimeStep())
dynamic = robot.getName() != "static"

ds_generic_s = robot.getDevice("ds_generic_static")
ds_infra_red_s = robot.getDevice("ds_infra_red_static")
ds_generic_d = robot.getDevice("ds_generic_dynamic")
ds_infra_red_d = robot.getDevice("ds_infra_red_dynamic")
for sensor in (ds_generic_s, ds_infra_red_s, ds_generic_d, ds_infra_red_d):
    sensor.enable(time_step)

# stabilize the system
robot.step(3 * time_step)

if dynamic:
    left_motor = robot.getDevice("left motor")
    right_motor = robot.getDevice("right motor")
    left_motor.setPosition(float("inf"))
    right_motor.setPosition(float("inf"))
    left_motor.setVelocity(20)
    right_motor.setVelocity(20)

# static object: generic (using ODE rays), infra-red (using Webots ray collision detection)
check_sensor_value(ds_generic_s, OBJ_VALUE, "The generic distance sensor doesn't return the correct initial distance of "
                   "static object: expected %f, measured %f.")
check_sensor_value(ds_infra_red_s, OBJ_VALUE, "The infra-red distance sensor doesn't return the correct initial "
                   "distance of static object: expected %f, measured %f.")
# dynamic object
check_sensor_value(ds_generic_d, OBJ_VALUE, "The generic distance sensor doesn't return the correct initial distance of "
                   "dynamic object: expected %f, measured %f.")
check_sensor_value(ds_infra_red_d, OBJ_VALUE, "The infra-red distance sensor doesn't return the correct initial "
                   "distance of dynamic object: expected %f, measured %f.")

# check ray position has been update before ray collision detection when the robot moves
robot.step(time_step)

check_sensor_value(ds_generic_s, OBJ_VALUE, "The generic distance sensor doesn't return the correct distance of static "
                   "object after 1 step: expected %f, measured %f.")
check_sensor_value(ds_infra_red_s, OBJ_VALUE, "The infra-red distance sensor doesn't return the correct distance of "
                   "static object after 1 step: expected %f, measured %f.")
check_sensor_value(ds_generic_d, OBJ_VALUE, "The generic distance sensor doesn't return the correct distance of dynamic "
                   "object after 1 step: expected %f, measured %f.")
check_sensor_value(ds_infra_red_d, OBJ_VALUE, "The infra-red distance sensor doesn't return the correct distance of "
                   "dynamic object after 1 step: expected %f, measured %f.")

robot.step(time_step)

static_expected = NONE_VALUE if dynamic else OBJ_VALUE
check_sensor_value(ds_generic_s, static_expected, "The generic distance sensor doesn't return the correct distance of "
                   "static object after 2 steps: expected %f, measured %f.")
check_sensor_value(ds_infra_red_s, static_expected, "The infra-red distance sensor doesn't return the correct distance "
                   "of static object after 2 steps: expected %f, measured %f.")
check_sensor_value(ds_generic_d, NONE_VALUE, "The generic distance sensor doesn't return the correct distance of "
                   "dynamic object after 2 steps: expected %f, measured %f.")
check_sensor_value(ds_infra_red_d, NONE_VALUE, "The infra-red distance sensor doesn't return the correct distance of "
                   "dynamic object after 2 steps: expected %f, measured %f.")

ts_send_success()
