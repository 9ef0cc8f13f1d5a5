"""Port of Webots' tests/protos/controllers/hinge_2_joint_with_backlash: the robot of hinge_2_joint_with_backlash.wbt
(not a test controller: hinge_2_joint_with_backlash_supervisor checks). It waits for the two motor velocities the
supervisor sends (two C floats), then drives the motors of its four Hinge2JointWithBacklash and of the reference
Hinge2Joint back and forth between +-ANGLE_LIMIT of the reference joint.
"""

import math
import struct

from controller import Robot

TIME_STEP = 16
ANGLE_LIMIT = 0.523599

robot = Robot()

receiver = robot.getDevice("receiver")
receiver.enable(TIME_STEP)
# wait for command
velocity_motor = 0.0
velocity_motor2 = 0.0
while robot.step(TIME_STEP) != -1:
    if receiver.getQueueLength() > 0:
        velocity_motor, velocity_motor2 = struct.unpack("ff", receiver.getBytes()[:8])
        break

names_motor = ["backlash_on_both_motor", "backlash_on_axis_motor", "backlash_on_axis2_motor",
               "backlash_on_neither_motor", "reference_hinge2joint_motor"]
names_motor2 = ["backlash_on_both_motor2", "backlash_on_axis_motor2", "backlash_on_axis2_motor2",
                "backlash_on_neither_motor2", "reference_hinge2joint_motor2"]
motor = []
motor2 = []
for i in range(5):
    motor.append(robot.getDevice(names_motor[i]))
    motor2.append(robot.getDevice(names_motor2[i]))
    motor[i].setPosition(math.inf)
    motor2[i].setPosition(math.inf)
    motor[i].setVelocity(velocity_motor)
    motor2[i].setVelocity(velocity_motor2)

reference_hinge2joint_sensor = robot.getDevice("reference_hinge2joint_sensor")
reference_hinge2joint_sensor2 = robot.getDevice("reference_hinge2joint_sensor2")
reference_hinge2joint_sensor.enable(TIME_STEP)
reference_hinge2joint_sensor2.enable(TIME_STEP)

while robot.step(TIME_STEP) != -1:
    if velocity_motor == 0.0 and velocity_motor2 != 0.0:  # actuating only axis2
        reference_hinge2joint_position = reference_hinge2joint_sensor2.getValue()
    else:
        reference_hinge2joint_position = reference_hinge2joint_sensor.getValue()

    if reference_hinge2joint_position > ANGLE_LIMIT:
        for i in range(5):
            if velocity_motor == 0.0 and velocity_motor2 != 0.0:
                motor2[i].setVelocity(-velocity_motor2)  # first test, only axis2 actuated
            else:
                motor[i].setVelocity(-velocity_motor)  # second test, only axis actuated
    if reference_hinge2joint_position < -ANGLE_LIMIT:
        for i in range(5):
            if velocity_motor == 0.0 and velocity_motor2 != 0.0:
                motor2[i].setVelocity(velocity_motor2)  # first test, only axis2 actuated
            else:
                motor[i].setVelocity(velocity_motor)  # second test, only axis actuated
