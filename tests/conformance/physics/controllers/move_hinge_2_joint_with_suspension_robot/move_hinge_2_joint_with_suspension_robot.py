"""Port of Webots' tests/physics/controllers/move_hinge_2_joint_with_suspension_robot (a helper, not a test): sets the
wheel motor of the Hinge2Joint's second axis turning at 3 rad/s, steps once and exits (the command stays)."""

from controller import Robot

robot = Robot()

time_step = int(robot.getBasicTimeStep())
motor = robot.getDevice("rotational motor 2")
motor.setVelocity(3.0)
motor.setPosition(1000000)

robot.step(time_step)
