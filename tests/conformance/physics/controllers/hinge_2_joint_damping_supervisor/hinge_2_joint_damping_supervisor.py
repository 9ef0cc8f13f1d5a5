"""Port of Webots' tests/physics/controllers/hinge_2_joint_damping_supervisor: helper of hinge_2_joint_damping;
sets the wheels' second-axis dampingConstant to 0, then 20 after 10 steps, then 50 after 10 more."""

from controller import Supervisor

TIME_STEP = 64

damping = [0.0, 20.0, 50.0]  # C's `const double damping[3]`: setSFFloat takes only a float, as in Webots' Python

robot = Supervisor()
wheel_parameters_nodes = [robot.getFromDef("WHEEL1PARAMETERS"), robot.getFromDef("WHEEL2PARAMETERS")]
damping_fields = [node.getField("dampingConstant") for node in wheel_parameters_nodes]

damping_fields[0].setSFFloat(damping[0])
damping_fields[1].setSFFloat(damping[0])

for _ in range(10):
    robot.step(TIME_STEP)

damping_fields[0].setSFFloat(damping[1])
damping_fields[1].setSFFloat(damping[1])

for _ in range(10):
    robot.step(TIME_STEP)

damping_fields[0].setSFFloat(damping[2])
damping_fields[1].setSFFloat(damping[2])
