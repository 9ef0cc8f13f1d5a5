"""Port of Webots' tests/api/controllers/joints_motor_min_max_position.

A joint position written outside its motor's [minPosition, maxPosition] widens those limits on
load, for every joint type and each axis (device <-> jointParameters, device2 <-> jointParameters2...).
"""

from controller import Supervisor
from ts_assertion import ts_assert_double_equal, ts_send_success, ts_setup

# (device name, joint label, motor label, expected min, expected max, which limit is tested)
CASES = [
    ("slider_joint_lower_limit_motor", "SliderJoint", "motor", -0.2, 0.1, "lower"),
    ("slider_joint_upper_limit_motor", "SliderJoint", "motor", -0.1, 0.2, "upper"),
    ("hinge_joint_lower_limit_motor", "HingeJoint", "motor", -0.2, 0.1, "lower"),
    ("hinge_joint_upper_limit_motor", "HingeJoint", "motor", -0.1, 0.2, "upper"),
    ("hinge_2_joint_lower_limit_motor", "Hinge2Joint", "motor", -0.2, 0.1, "lower"),
    ("hinge_2_joint_lower_limit_motor2", "Hinge2Joint", "motor2", -0.3, 0.1, "lower"),
    ("hinge_2_joint_upper_limit_motor", "Hinge2Joint", "motor", -0.1, 0.2, "upper"),
    ("hinge_2_joint_upper_limit_motor2", "Hinge2Joint", "motor2", -0.1, 0.3, "upper"),
    ("ball_joint_lower_limit_motor", "BallJoint", "motor", -0.2, 0.1, "lower"),
    ("ball_joint_lower_limit_motor2", "BallJoint", "motor2", -0.3, 0.1, "lower"),
    ("ball_joint_lower_limit_motor3", "BallJoint", "motor3", -0.4, 0.1, "lower"),
    ("ball_joint_upper_limit_motor", "BallJoint", "motor", -0.1, 0.2, "upper"),
    ("ball_joint_upper_limit_motor2", "BallJoint", "motor2", -0.1, 0.3, "upper"),
    ("ball_joint_upper_limit_motor3", "BallJoint", "motor3", -0.1, 0.4, "upper"),
]

robot = Supervisor()
ts_setup(robot)
for name, joint, label, low, high, tested in CASES:
    motor = robot.getDevice(name)
    if tested == "lower":
        ts_assert_double_equal(motor.getMinPosition(), low, "'minPosition' of %s (for %s) didn't adjust correctly when "
                               "position is below lower limit.", joint, label)
        ts_assert_double_equal(motor.getMaxPosition(), high, "'maxPosition' of %s (for %s) changed but shouldn't, lower "
                               "limit being tested.", joint, label)
    else:
        ts_assert_double_equal(motor.getMinPosition(), low, "'minPosition' of %s (for %s) changed but shouldn't, upper "
                               "limit being tested.", joint, label)
        ts_assert_double_equal(motor.getMaxPosition(), high, "'maxPosition' of %s (for %s) didn't adjust correctly when "
                               "position is above upper limit.", joint, label)

ts_send_success()
