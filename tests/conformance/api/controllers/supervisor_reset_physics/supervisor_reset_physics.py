"""Port of Webots' tests/api/controllers/supervisor_reset_physics: Node.resetPhysics stops one ball rolling down a
ramp while the two others go on, then simulationResetPhysics stops them all."""

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

previous_position_ball1 = 0.0
previous_position_others = 0.0
previous_height = 0.0

node_ball1 = robot.getFromDef("BALL1")
node_ball2 = robot.getFromDef("BALL2")
node_ball3 = robot.getFromDef("BALL3")

ts_assert_pointer_not_null(node_ball1, "The supervisor cannot get the WbNodeRef of BALL1.")
ts_assert_pointer_not_null(node_ball2, "The supervisor cannot get the WbNodeRef of BALL2.")
ts_assert_pointer_not_null(node_ball3, "The supervisor cannot get the WbNodeRef of BALL3.")

field_translation1 = node_ball1.getField("translation")
field_translation2 = node_ball2.getField("translation")
field_translation3 = node_ball3.getField("translation")
ts_assert_pointer_not_null(field_translation1, "The supervisor cannot get the WbFieldRef of translation of BALL1.")
ts_assert_pointer_not_null(field_translation2, "The supervisor cannot get the WbFieldRef of translation of BALL2.")
ts_assert_pointer_not_null(field_translation3, "The supervisor cannot get the WbFieldRef of translation of BALL3.")

step_count = 0
while robot.step(TIME_STEP) != 1:
    step_count += 1
    current_translation = field_translation1.getSFVec3f()
    if abs(previous_height - current_translation[1]) < 1e-6:
        previous_position_ball1 = current_translation[2]
        break
    previous_height = current_translation[1]

ts_assert_boolean_equal(step_count < 55, "Balls don't roll as expected.")

node_ball1.resetPhysics()

robot.step(32 * TIME_STEP)

current_translation = field_translation1.getSFVec3f()
ts_assert_double_in_delta(current_translation[2], previous_position_ball1, 0.002,
                          "Physics of BALL1 has not been reset corectly: the ball position '%f' doesn't match the "
                          "expected one '%f'.", current_translation[2], previous_position_ball1)

current_translation = field_translation2.getSFVec3f()
ts_assert_boolean_equal(abs(current_translation[2] - previous_position_ball1) > 0.002,
                        "BALL2 stops moving: the ball position '%f' should be smaller than '%f'.", current_translation[2],
                        previous_position_ball1)

previous_position_others = current_translation[2]

current_translation = field_translation3.getSFVec3f()
ts_assert_double_in_delta(current_translation[2], previous_position_others, 1e-6,
                          "BALL3 stops moving: the position of BALL3 '%f' should match the position of BALL2 '%f'.",
                          current_translation[2], previous_position_others)

robot.simulationResetPhysics()

robot.step(2 * TIME_STEP)

current_translation = field_translation1.getSFVec3f()
ts_assert_double_in_delta(current_translation[2], previous_position_ball1, 0.002,
                          "Physics of BALL1 has not been reset corectly: the ball position '%f' doesn match the expected "
                          "one '%f'.", current_translation[2], previous_position_ball1)

current_translation = field_translation2.getSFVec3f()
ts_assert_double_in_delta(current_translation[2], previous_position_others, 0.002,
                          "Physics of BALL2 has not been reset corectly: the ball position '%f' doesn match the expected "
                          "one '%f'.", current_translation[2], previous_position_others)

current_translation = field_translation3.getSFVec3f()
ts_assert_double_in_delta(current_translation[2], previous_position_others, 0.002,
                          "Physics of BALL3 has not been reset corectly: the ball position '%f' doesn match the expected "
                          "one '%f'.", current_translation[2], previous_position_others)

ts_send_success()
