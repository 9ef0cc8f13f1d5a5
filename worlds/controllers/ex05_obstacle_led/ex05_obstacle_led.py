"""Example 5: a robot that flashes its LED red and white three times before turning right when it
detects an obstacle. Lesson threshold: `< 70` on ps0/ps7."""
from controller import Robot, Motor, DistanceSensor, LED

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

led = robot.getDevice('led0')


def flashLED():
    for _ in range(3):
        led.set(1)
        robot.step(TIME_STEP)
        led.set(0)
        robot.step(TIME_STEP)


while robot.step(TIME_STEP) != -1:
    sensorValues = [sensor.getValue() for sensor in sensorObjects]
    # The lesson's line: `if sensorValues[0] < 70 or sensorValues[1] < 70:`. An e-puck's proximity
    # value grows as an obstacle comes closer (about 67 with nothing in range, 4095 at contact), so
    # "< 70" is true when nothing is near: the robot would flash and turn all the time and drive
    # into the box. wbtc ships "> 80" (about 6.5 cm from a white surface), as example 4:
    if sensorValues[0] > 80 or sensorValues[1] > 80:
        flashLED()
        leftMotor.setVelocity(FORWARD_SPEED)
        rightMotor.setVelocity(-FORWARD_SPEED)
    else:
        leftMotor.setVelocity(FORWARD_SPEED)
        rightMotor.setVelocity(FORWARD_SPEED)
