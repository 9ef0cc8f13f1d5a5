"""Port of Webots' tests/physics/controllers/check_joint_hard_limits_after_move: slider, hinge and hinge-2 joints
driven against their maxStop stay at it, before and after a supervisor moves the robot."""

import math

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

MAX_STOP = 0.4

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

slider_motor = robot.getDevice("slider motor")
slider_sensor = robot.getDevice("slider sensor")
slider_sensor.enable(time_step)
slider_motor.setPosition(math.inf)
slider_motor.setVelocity(2.0)

hinge_motor = robot.getDevice("hinge motor")
hinge_sensor = robot.getDevice("hinge sensor")
hinge_sensor.enable(time_step)
hinge_motor.setPosition(math.inf)
hinge_motor.setVelocity(1.0)

hinge2_motor = robot.getDevice("hinge2 motor1")
hinge2_sensor = robot.getDevice("hinge2 sensor1")
hinge2_sensor.enable(time_step)
hinge2_motor.setPosition(math.inf)
hinge2_motor.setVelocity(1.0)

robot.step(60 * time_step)

joint_position = slider_sensor.getValue()
ts_assert_double_in_delta(joint_position, MAX_STOP, 0.01,
                          "Before moving the robot the SliderJoint hard limit is not respected: position %.3f > "
                          "maxStop %.3f.", joint_position, MAX_STOP)
joint_position = hinge_sensor.getValue()
ts_assert_double_in_delta(joint_position, MAX_STOP, 0.01,
                          "Before moving the robot the HingeJoint hard limit is not respected: position %.3f > "
                          "maxStop %.3f.", joint_position, MAX_STOP)
joint_position = hinge2_sensor.getValue()
ts_assert_double_in_delta(joint_position, MAX_STOP, 0.01,
                          "Before moving the robot the Hinge2Joint hard limit is not respected: position %.3f > "
                          "maxStop %.3f.", joint_position, MAX_STOP)

# Move robot
node = robot.getSelf()
translation_field = node.getField("translation")
translation = translation_field.getSFVec3f()
translation_field.setSFVec3f([translation[0], translation[1], -0.5])

robot.step(60 * time_step)

joint_position = slider_sensor.getValue()
ts_assert_double_in_delta(joint_position, MAX_STOP, 0.01,
                          "After moving the robot the SliderJoint hard limit is not respected: position %.3f > "
                          "maxStop %.3f.", joint_position, MAX_STOP)
joint_position = hinge_sensor.getValue()
ts_assert_double_in_delta(joint_position, MAX_STOP, 0.01,
                          "After moving the robot the HingeJoint hard limit is not respected: position %.3f > "
                          "maxStop %.3f.", joint_position, MAX_STOP)
joint_position = hinge2_sensor.getValue()
ts_assert_double_in_delta(joint_position, MAX_STOP, 0.01,
                          "After moving the robot the Hinge2Joint hard limit is not respected: position %.3f > "
                          "maxStop %.3f.", joint_position, MAX_STOP)

ts_send_success()
