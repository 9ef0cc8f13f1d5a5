"""Port of Webots' tests/physics/controllers/joint_controller: drives a three-axis joint to three targets, one axis
after the other (a helper of ball_joint_vs_hinge_joints; it makes no assertion)."""

from controller import Robot

TIME_STEP = 32
POS_1 = 1.01
POS_2 = 0.6
POS_3 = -2.45

robot = Robot()

mot1 = robot.getDevice("rotational motor")
mot2 = robot.getDevice("rotational motor 2")
mot3 = robot.getDevice("rotational motor 3")

ps1 = robot.getDevice("position sensor")
ps2 = robot.getDevice("position sensor 2")
ps3 = robot.getDevice("position sensor 3")

ps1.enable(TIME_STEP)
ps2.enable(TIME_STEP)
ps3.enable(TIME_STEP)

robot.step(TIME_STEP)

mot1.setPosition(POS_1)
while robot.step(TIME_STEP) != -1 and abs(ps1.getValue() - POS_1) > 0.01:
    pass
print("Target 1 reached")

mot2.setPosition(POS_2)
while robot.step(TIME_STEP) != -1 and abs(ps2.getValue() - POS_2) > 0.01:
    pass
print("Target 2 reached")

mot3.setPosition(POS_3)
while robot.step(TIME_STEP) != -1 and abs(ps3.getValue() - POS_3) > 0.01:
    pass
print("Target 3 reached")
