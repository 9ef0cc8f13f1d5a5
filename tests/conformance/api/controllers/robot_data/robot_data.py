"""Port of Webots' tests/api/controllers/robot_data: the helper robot that reads "a + b" from its customData
field and writes back the sum (it reports no verdict; robot_data_supervisor checks the answer)."""

from controller import Robot

TIME_STEP = 32

robot = Robot()
robot.step(TIME_STEP)

while len(robot.getCustomData()) == 0:
    robot.step(TIME_STEP)

left, operator, right = robot.getCustomData().split()
robot.setCustomData("%d" % (int(left) + int(right)))

robot.step(TIME_STEP)
