"""Port of Webots' tests/physics/controllers/passive_hinge_joint: helper of hinge_joint_damping; sends the time at
which the robot's touch sensor first detects its falling bar."""

from controller import Robot

robot = Robot()

time_step = int(robot.getBasicTimeStep())

emitter = robot.getDevice("emitter")
touch_sensor = robot.getDevice("touch sensor")
touch_sensor.enable(time_step)

while robot.step(time_step) != -1:
    if touch_sensor.getValue() == 1:
        print("collision")
        message = "%s : collision at %f" % (robot.getName(), robot.getTime())
        emitter.send(message.encode() + b"\0")
        robot.step(time_step)
        break
