"""Port of Webots' tests/physics/controllers/move_car: a Car driving in a circle keeps its front wheels clear of two
distance sensors in front of them, before and after a supervisor moves the car, so the wheels' Hinge2Joint axes and
anchors followed the move."""

from controller import Robot
from ts_assertion import ts_assert_double_is_bigger, ts_assert_int_equal, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

right_sensor = robot.getDevice("right sensor")
left_sensor = robot.getDevice("left sensor")
right_sensor.enable(time_step)
left_sensor.enable(time_step)

motors = [robot.getDevice("right_front_wheel"), robot.getDevice("left_front_wheel")]
for motor in motors:
    motor.setVelocity(4.0)
    motor.setPosition(1000000)

left_steer_motor = robot.getDevice("left_steer")
right_steer_motor = robot.getDevice("right_steer")
left_steer_motor.setPosition(0.25)
right_steer_motor.setPosition(0.25)

robot.step(5 * time_step)

steps = 15
while steps > 0 and robot.step(time_step) != -1:
    ts_assert_double_is_bigger(right_sensor.getValue(), 999.0,
                               "Right front wheel joint axis or anchor is wrong after artificial move.")
    ts_assert_double_is_bigger(left_sensor.getValue(), 999.0,
                               "Left front wheel joint axis or anchor is wrong after artificial move.")
    steps -= 1

robot.step(10 * time_step)

steps = 100
while steps > 0 and robot.step(time_step) != -1:
    ts_assert_double_is_bigger(right_sensor.getValue(), 999.0,
                               "Right front wheel joint axis or anchor is wrong after artificial move.")
    ts_assert_double_is_bigger(left_sensor.getValue(), 999.0,
                               "Left front wheel joint axis or anchor is wrong after artificial move.")
    steps -= 1

ts_assert_int_equal(steps, 0, "Simulation terminated before completing all the tests after artificial move.")

ts_send_success()
