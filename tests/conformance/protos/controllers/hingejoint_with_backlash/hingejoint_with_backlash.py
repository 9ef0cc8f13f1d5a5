"""Port of Webots' tests/protos/controllers/hingejoint_with_backlash at ff91c94b: the pendulum of the R2021b world
hingejoint_with_backlash.wbt (not a test controller: hingejoint_with_backlash_supervisor, of the same commit,
checks). Its motor turns back and forth, first within the backlash range (+-0.10 rad) until 10 s, then, after three
steps at rest, beyond it (+-0.105 rad) until 20 s.
"""

from controller import Robot

TIME_STEP = 16
TEST_DURATION = 10.0
SPEED = 0.2

robot = Robot()

motorInput = robot.getDevice("hingeInputMotor")
positionInput = robot.getDevice("hingeInputSensor")
positionInput.enable(TIME_STEP)

motorInput.setPosition(float("inf"))
motorInput.setVelocity(SPEED)

# TEST #1: by switching direction BEFORE the backlash limit is reached, the endPoint shouldn't move
print("ROBOT Test #1: Start.")
while robot.step(TIME_STEP) != -1 and robot.getTime() < TEST_DURATION:
    pos = positionInput.getValue()

    if pos >= 0.10:
        motorInput.setVelocity(-SPEED)
    if pos <= -0.10:
        motorInput.setVelocity(SPEED)
print("ROBOT Test #1: Done.")

motorInput.setVelocity(0)
robot.step(TIME_STEP)
robot.step(TIME_STEP)
robot.step(TIME_STEP)
motorInput.setVelocity(SPEED)

# TEST #2: by switching direction AFTER the backlash limit is reached, the endPoint shouldn't move
print("ROBOT Test #2: Start.")

while robot.step(TIME_STEP) != -1 and robot.getTime() < 2 * TEST_DURATION:
    # command
    pos = positionInput.getValue()

    if pos >= 0.105:
        motorInput.setVelocity(-SPEED)
    if pos <= -0.105:
        motorInput.setVelocity(SPEED)

print("ROBOT Test #2: Done.")
