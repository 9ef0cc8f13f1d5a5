"""Port of Webots' tests/physics/controllers/hinge_2_joint_damping_axis: two Hinge2Joints with braked second-axis
motors, one with its first axis turned by 90 degrees, must spin up and coast down at the same angular speed."""

import math

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32


def angular_speed_of(node):
    v = node.getVelocity()
    return math.sqrt(v[3] * v[3] + v[4] * v[4] + v[5] * v[5])


class HingeJoint2Data:
    def __init__(self, drive_motor_name, shaft_def):
        self.drive_motor = robot.getDevice(drive_motor_name)
        self.drive_motor.setPosition(math.inf)
        self.drive_motor.setVelocity(0.0)
        self.drive_motor.getBrake().setDampingConstant(28.0)
        self.shaft_node = robot.getFromDef(shaft_def)


def assert_same_speed_for_secs(j1, j2, duration_secs):
    tolerance = 0.001
    t = 0.0
    while robot.step(TIME_STEP) != -1 and t < duration_secs:
        t += TIME_STEP / 1000.0
        exp_speed = angular_speed_of(j1.shaft_node)
        act_speed = angular_speed_of(j2.shaft_node)
        ts_assert_double_in_delta(act_speed, exp_speed, tolerance, "Unexpected angle rate (expected = %lf, measured = %lf)",
                                  exp_speed, act_speed)
        print("angle_rate: %f expected: %f" % (act_speed, exp_speed))


robot = Supervisor()
ts_setup(robot)

joint1 = HingeJoint2Data("joint1motor", "HINGE2JOINT1_SHAFT")
joint2 = HingeJoint2Data("joint2motor", "HINGE2JOINT2_SHAFT")

robot.getDevice("joint2turnmotor").setPosition(1.57)
t = 0.0
while robot.step(TIME_STEP) != -1 and t < 1.0:
    t += TIME_STEP / 1000.0

joint1.drive_motor.setVelocity(6.28)
joint2.drive_motor.setVelocity(6.28)
assert_same_speed_for_secs(joint1, joint2, 1.0)

joint1.drive_motor.setVelocity(0.0)
joint1.drive_motor.setAvailableTorque(0.0)
joint2.drive_motor.setVelocity(0.0)
joint2.drive_motor.setAvailableTorque(0.0)
assert_same_speed_for_secs(joint1, joint2, 1.0)

ts_send_success()
