"""Port of Webots' tests/api/controllers/supervisor_node_set_joint_position: Node.setJointPosition moves a slider, a
hinge, a hinge-2 (second axis) and a ball joint (third axis), seen by four distance sensors; invalid indices are
ignored and position 0 puts the slider back."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

slider_sensor = robot.getDevice("slider sensor")
hinge_sensor = robot.getDevice("hinge sensor")
hinge2_sensor = robot.getDevice("hinge2 sensor")
ball_joint_sensor = robot.getDevice("ball joint sensor")
slider_sensor.enable(TIME_STEP)
hinge_sensor.enable(TIME_STEP)
hinge2_sensor.enable(TIME_STEP)
ball_joint_sensor.enable(TIME_STEP)

# Run some simulation steps to stabilize the simulation
robot.step(15 * TIME_STEP)

ball_joint_node = robot.getFromDef("BALL_JOINT")
ball_joint_node.setJointPosition(0.6, 3)

slider_joint_node = robot.getFromDef("SLIDER_JOINT")
slider_joint_node.setJointPosition(0.6, 1)

hinge_joint_node = robot.getFromDef("HINGE_JOINT")
hinge_joint_node.setJointPosition(0.6, 1)

hinge2_joint_node = robot.getFromDef("HINGE2_JOINT")
hinge2_joint_node.setJointPosition(0.6, 2)

robot.step(TIME_STEP)

# Check joints position is applied correctly
slider_value = slider_sensor.getValue()
ts_assert_double_in_delta(slider_value, 305.0, 2.0, "Slider joint position is not set correctly.")
hinge_value = hinge_sensor.getValue()
ts_assert_double_in_delta(hinge_value, 421.0, 2.0, "Hinge joint position is not set correctly.")
hinge2_value = hinge2_sensor.getValue()
ts_assert_double_in_delta(hinge2_value, 150.0, 2.0, "Hinge2 joint position is not set correctly.")
ball_value = ball_joint_sensor.getValue()
ts_assert_double_in_delta(ball_value, 205.0, 2.0, "Ball joint position is not set correctly.")

# Test invalid indices
slider_joint_node.setJointPosition(0, 2)
robot.step(TIME_STEP)
slider_value = slider_sensor.getValue()
ts_assert_double_in_delta(slider_value, 305.0, 50.0, "Slider joint position should not change using invalid index 2.")

slider_joint_node.setJointPosition(0, 0)
robot.step(TIME_STEP)
slider_value = slider_sensor.getValue()
ts_assert_double_in_delta(slider_value, 305.0, 50.0, "Slider joint position should not change using invalid index 0.")

slider_joint_node.setJointPosition(0, -1)
robot.step(TIME_STEP)
slider_value = slider_sensor.getValue()
ts_assert_double_in_delta(slider_value, 305.0, 50.0, "Slider joint position should not change using invalid index -1.")

# Reset position of slider joint
slider_joint_node.setJointPosition(0, 1)
robot.step(TIME_STEP)
slider_value = slider_sensor.getValue()
ts_assert_double_in_delta(slider_value, 1000.0, 1.0, "Slider joint position is correctly reset.")

ts_send_success()
