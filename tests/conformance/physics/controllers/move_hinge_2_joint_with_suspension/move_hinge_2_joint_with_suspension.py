"""Port of Webots' tests/physics/controllers/move_hinge_2_joint_with_suspension: after a supervisor moves a robot whose
wheel hangs on a Hinge2Joint with suspension, the spinning wheel stays between two distance sensors (it does not
deviate left or right) for 50 steps."""

from controller import Supervisor
from ts_assertion import ts_assert_double_is_bigger, ts_assert_int_equal, ts_send_success, ts_setup

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

robot.step(10 * time_step)

robot_node = robot.getFromDef("ROBOT")
translation_field = robot_node.getField("translation")
position = [0.0, 1.01, 0.0]
translation_field.setSFVec3f(position)

robot.step(5 * time_step)

left_sensor = robot.getDevice("left distance sensor")
right_sensor = robot.getDevice("right distance sensor")
left_sensor.enable(time_step)
right_sensor.enable(time_step)

steps = 50
while steps > 0 and robot.step(time_step) != -1:
    ts_assert_double_is_bigger(left_sensor.getValue(), 999.0, "Cylinder deviated to the left.")
    ts_assert_double_is_bigger(right_sensor.getValue(), 999.0, "Cylinder deviated to the right.")
    steps -= 1

ts_assert_int_equal(steps, 0, "Simulation terminated before completing all the tests.")

ts_send_success()
