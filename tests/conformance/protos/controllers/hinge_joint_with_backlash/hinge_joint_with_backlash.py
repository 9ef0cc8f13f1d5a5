"""Port of Webots' tests/protos/controllers/hinge_joint_with_backlash: the pendulum of hinge_joint_with_backlash.wbt
(not a test controller: hinge_joint_with_backlash_supervisor checks). Its motor turns back and forth, first within
the backlash range (+-0.10 rad), then beyond it (+-0.105 rad).
"""

from controller import Robot

TIME_STEP = 16
TEST_DURATION = 10.0
SPEED = 0.2

robot = Robot()

joint_motor = robot.getDevice("joint_motor")
joint_sensor = robot.getDevice("joint_sensor")
joint_sensor.enable(TIME_STEP)

joint_motor.setPosition(float("inf"))
joint_motor.setVelocity(SPEED)

# TEST #1: by switching direction BEFORE the backlash limit is reached, the endPoint shouldn't move
while robot.step(TIME_STEP) != -1 and robot.getTime() < TEST_DURATION:
    position = joint_sensor.getValue()

    if position >= 0.10:
        joint_motor.setVelocity(-SPEED)
    if position <= -0.10:
        joint_motor.setVelocity(SPEED)

joint_motor.setVelocity(0)
robot.step(TIME_STEP)  # reset
joint_motor.setVelocity(SPEED)

# TEST #2: by switching direction AFTER the backlash limit is reached, the endPoint should move
while robot.step(TIME_STEP) != -1 and robot.getTime() < 2 * TEST_DURATION:
    position = joint_sensor.getValue()

    if position >= 0.105:
        joint_motor.setVelocity(-SPEED)
    if position <= -0.105:
        joint_motor.setVelocity(SPEED)
