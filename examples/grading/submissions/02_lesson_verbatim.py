"""A student's Example 4 (avoid obstacles): lesson verbatim."""
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
THRESHOLD = 70
sensors = []
for name in ['ps0', 'ps7', 'ps1', 'ps6']:
    sensor = robot.getDevice(name)
    sensor.enable(TIME_STEP)
    sensors.append(sensor)

while robot.step(TIME_STEP) != -1:
    front_right, front_left, right_side, left_side = [s.getValue() for s in sensors]
    if front_right < THRESHOLD or front_left < THRESHOLD:
        left.setVelocity(0)
        right.setVelocity(0)
    elif right_side < THRESHOLD:
        left.setVelocity(-SPEED)
        right.setVelocity(SPEED)
    elif left_side < THRESHOLD:
        left.setVelocity(SPEED)
        right.setVelocity(-SPEED)
    else:
        left.setVelocity(SPEED)
        right.setVelocity(SPEED)
