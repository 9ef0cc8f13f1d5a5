"""Port of Webots' tests/physics/controllers/hinge_joint_slot: a bar hinged through two Slots falls onto the robot's
own touch sensor (selfCollision) at exactly 0.48 s."""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_assert_double_equal, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

touch_sensor = robot.getDevice("touch sensor")
touch_sensor.enable(time_step)

while robot.step(time_step) != -1:
    if robot.getTime() > 2.0:
        ts_assert_boolean_equal(0, "Time-out reached before collisions are detected")
    if touch_sensor.getValue() != 0.0:
        break

ts_assert_double_equal(robot.getTime(), 0.48, "Falling time not correct, %lf instead of %lf", robot.getTime(), 0.48)

ts_send_success()
