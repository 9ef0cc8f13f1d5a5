"""Port of Webots' tests/api/controllers/motor_spinner: the helper controller that spins motor "wheel1" (and
"wheel2" when given an argument) at 50 rad/s for 50 steps of 32 ms, then stops them (it reports no verdict)."""

import sys

from controller import Robot

TIME_STEP = 32

robot = Robot()

wheel1 = robot.getDevice("wheel1")
wheel2 = None

wheel1.setPosition(float("inf"))
wheel1.setVelocity(50)
if len(sys.argv) > 1:
    wheel2 = robot.getDevice("wheel2")
    wheel2.setPosition(float("inf"))
    wheel2.setVelocity(50)

robot.step(TIME_STEP * 50)

wheel1.setVelocity(0)
if wheel2 is not None:
    wheel2.setVelocity(0)
