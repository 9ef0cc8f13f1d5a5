"""Port of Webots' tests/api/controllers/robot_multiple_step_supervisor: moves ROBOT after three basic steps."""

from controller import Supervisor

robot = Supervisor()
time_step = int(robot.getBasicTimeStep())
robot.step(3 * time_step)

# update world
node = robot.getFromDef("ROBOT")
rotation_field = node.getField("rotation")
translation_field = node.getField("translation")
rotation_field.setSFRotation([0.0, 1.0, 0.0, 1.5708])
translation_field.setSFVec3f([-0.05, 0.0295, 0.1])
