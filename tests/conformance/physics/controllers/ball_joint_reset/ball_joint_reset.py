"""Port of Webots' tests/physics/controllers/ball_joint_reset: a BallJoint endPoint written at non-zero joint
positions is where it was after simulationReset."""

from controller import Supervisor
from ts_assertion import ts_assert_doubles_in_delta, ts_send_success, ts_setup

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

end_point_node = robot.getFromDef("SOLID_ENDPOINT")
translation_field = end_point_node.getField("translation")
rotation_field = end_point_node.getField("rotation")

robot.step(time_step)

# save initial position to compare afterwards
expected_translation = list(translation_field.getSFVec3f())
expected_rotation = list(rotation_field.getSFRotation())

robot.step(2 * time_step)

robot.simulationReset()

robot.step(2 * time_step)

translation_after = translation_field.getSFVec3f()
rotation_after = rotation_field.getSFRotation()

ts_assert_doubles_in_delta(3, translation_after, expected_translation, 1e-10,
                           "Translation of the endpoint changed after the reset but shouldn't.")
ts_assert_doubles_in_delta(4, rotation_after, expected_rotation, 1e-10,
                           "Rotation of the endpoint changed after the reset but shouldn't.")

robot.step(2 * time_step)

ts_send_success()
