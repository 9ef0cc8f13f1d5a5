"""A student's Example 4 (avoid obstacles): no sensors."""
from controller import Robot

robot = Robot()
TIME_STEP = 64
left = robot.getDevice('left wheel motor')
right = robot.getDevice('right wheel motor')
left.setPosition(float('inf'))
right.setPosition(float('inf'))
left.setVelocity(0.0)
right.setVelocity(0.0)
SPEED = 5.0
THRESHOLD = 80
sensors = []
for name in []:
    sensor = robot.getDevice(name)
    sensor.enable(TIME_STEP)
    sensors.append(sensor)

while robot.step(TIME_STEP) != -1:
    left.setVelocity(SPEED)
    right.setVelocity(SPEED)
