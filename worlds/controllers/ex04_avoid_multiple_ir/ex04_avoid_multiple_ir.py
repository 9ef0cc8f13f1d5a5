"""Example 4: avoid obstacles using multiple infrared sensors.
Lesson: ps0/ps7 (front) -> stop; ps1 (front-right) -> turn left; ps6 (front-left) -> turn right;
otherwise forward at 5 rad/s. The lesson's threshold is `< 70`."""
from controller import Robot, Motor, DistanceSensor

robot = Robot()
TIME_STEP = 64

leftMotor = robot.getDevice('left wheel motor')
rightMotor = robot.getDevice('right wheel motor')
leftMotor.setPosition(float('inf'))
rightMotor.setPosition(float('inf'))
leftMotor.setVelocity(0.0)
rightMotor.setVelocity(0.0)

FORWARD_SPEED = 5.0

sensors = ['ps0', 'ps7', 'ps1', 'ps6']
sensorObjects = []
for sensorName in sensors:
    sensor = robot.getDevice(sensorName)
    sensor.enable(TIME_STEP)
    sensorObjects.append(sensor)

while robot.step(TIME_STEP) != -1:
    sensorValues = [sensor.getValue() for sensor in sensorObjects]
    # The lesson's line: `if sensorValues[0] < 70 or sensorValues[1] < 70:`. An e-puck's proximity
    # value grows as an obstacle comes closer (about 67 with nothing in range, 4095 at contact), so
    # "< 70" is true when nothing is near and the robot would never move. wbtc ships "> 80":
    if sensorValues[0] > 80 or sensorValues[1] > 80:
        leftMotor.setVelocity(0)
        rightMotor.setVelocity(0)
    elif sensorValues[2] > 80:  # the lesson's line: `elif sensorValues[2] < 70:` (see above)
        leftMotor.setVelocity(-FORWARD_SPEED)
        rightMotor.setVelocity(FORWARD_SPEED)
    elif sensorValues[3] > 80:  # the lesson's line: `elif sensorValues[3] < 70:` (see above)
        leftMotor.setVelocity(FORWARD_SPEED)
        rightMotor.setVelocity(-FORWARD_SPEED)
    else:
        leftMotor.setVelocity(FORWARD_SPEED)
        rightMotor.setVelocity(FORWARD_SPEED)
