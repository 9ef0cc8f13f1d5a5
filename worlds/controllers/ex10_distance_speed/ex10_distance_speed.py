"""Example 10: distance-based speed control with linear regression, speed = a * distance + b.
Lesson: the robot moves faster when the object is far away and slower as it gets closer.
(The lesson gives only the loop; the device set-up is the one used by every other example.)"""
from controller import Robot, DistanceSensor, Motor

robot = Robot()
timestep = int(robot.getBasicTimeStep())

distance_sensor = robot.getDevice('ps0')
distance_sensor.enable(timestep)
left_motor = robot.getDevice('left wheel motor')
right_motor = robot.getDevice('right wheel motor')
left_motor.setPosition(float('inf'))
right_motor.setPosition(float('inf'))

# The lesson's line: `a = -0.1`. An e-puck's proximity value is not a distance: it is about 67 with
# nothing in range and grows to 4095 at contact. With a = -0.1 the speed is already 5 - 6.7 = -1.7 rad/s
# when nothing is near, so the robot backs away from everything. wbtc ships a = -0.02: 3.7 rad/s far
# from obstacles, slower and slower as the value grows, and 0 at a value of 250 (about 3 cm from a
# white wall), where the robot stops:
a = -0.02
b = 5

while robot.step(timestep) != -1:
    distance = distance_sensor.getValue()
    speed = a * distance + b
    speed = max(-10, min(10, speed))
    left_motor.setVelocity(speed)
    right_motor.setVelocity(speed)
    print(f"Distance: {distance}, Speed: {speed}")
