"""Port of Webots' tests/api/controllers/my_bot_controller: the helper controller of a MyBot that drives straight
at 5 rad/s and turns left while a sonar reads below 100 (it reports no verdict)."""

from controller import Robot

TIME_STEP = 8

robot = Robot()

us0 = robot.getDevice("us0")
us1 = robot.getDevice("us1")
left_motor = robot.getDevice("left wheel motor")
right_motor = robot.getDevice("right wheel motor")
left_motor.setPosition(float("inf"))
right_motor.setPosition(float("inf"))
left_motor.setVelocity(0)
right_motor.setVelocity(0)

us0.enable(TIME_STEP)
us1.enable(TIME_STEP)

while robot.step(TIME_STEP) != -1:
    d0 = us0.getValue()
    d1 = us1.getValue()
    if d0 < 100 or d1 < 100:
        left_motor.setVelocity(-5)
        right_motor.setVelocity(5)
    else:
        left_motor.setVelocity(5)
        right_motor.setVelocity(5)
