"""Example 3: obstacle avoidance with the front infrared sensor ps0.
Lesson: move forward at 10 % of MAX_SPEED; when ps0 detects an obstacle, turn (left wheel at
MAX_SPEED, right wheel stopped). The lesson's threshold is `distance < 62`, "adjust based on your
sensor's range and sensitivity"."""
from controller import Robot, Motor, DistanceSensor

TIME_STEP = 64
MAX_SPEED = 6.28

robot = Robot()
leftMotor = robot.getDevice('left wheel motor')
rightMotor = robot.getDevice('right wheel motor')
leftMotor.setPosition(float('inf'))
rightMotor.setPosition(float('inf'))

distanceSensor = robot.getDevice('ps0')
distanceSensor.enable(TIME_STEP)

leftMotor.setVelocity(0.1 * MAX_SPEED)
rightMotor.setVelocity(0.1 * MAX_SPEED)

while robot.step(TIME_STEP) != -1:
    distance = distanceSensor.getValue()
    print(distance)
    # The lesson's line: `if distance < 62:`. An e-puck's proximity value grows as an obstacle comes
    # closer (about 67 with nothing in range, 4095 at contact), so "< 62" is never true near the wall
    # and, with the sensor noise (67 +- 3), true now and then in the open: the robot would spin at
    # random and drive into the wall. wbtc ships "> 80" (about 6.5 cm from a white wall), as example 4:
    if distance > 80:
        leftMotor.setVelocity(MAX_SPEED)
        rightMotor.setVelocity(0)
    else:
        leftMotor.setVelocity(0.1 * MAX_SPEED)
        rightMotor.setVelocity(0.1 * MAX_SPEED)
