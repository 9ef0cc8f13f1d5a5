"""Port of Webots' tests/physics/controllers/youbot_move_arm (a helper, not a test): sends the Youbot's arm2, arm3 and
arm4 motors to 1.57, -2.635 and 1.78 rad, then exits (the targets stay)."""

from controller import Robot

robot = Robot()

arm2 = robot.getDevice("arm2")
arm3 = robot.getDevice("arm3")
arm4 = robot.getDevice("arm4")
arm2.setPosition(1.57)
arm3.setPosition(-2.635)
arm4.setPosition(1.78)
