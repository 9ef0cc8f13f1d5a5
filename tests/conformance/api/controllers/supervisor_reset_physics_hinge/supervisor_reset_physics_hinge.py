"""Port of Webots' tests/api/controllers/supervisor_reset_physics_hinge: Node.resetPhysics on a robot stops its
spinning hinge (or hinge2) end point, for a plain Robot, a PROTO robot, a nested PROTO robot and a Hinge2Joint robot
(read through the end point's rotation field or the PROTO's hingeRotation parameter)."""

from controller import Supervisor
from ts_assertion import ts_assert_double_is_bigger, ts_assert_rotation_equals, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

normal_test_bot = robot.getFromDef("TESTBOT")
proto_test_bot = robot.getFromDef("PROTOTESTBOT")
nested_test_bot = robot.getFromDef("NESTEDTESTBOT")
hinge2_test_bot = robot.getFromDef("HINGE2TESTBOT")

normal_hinge = normal_test_bot.getField("children").getMFNode(1)
hinge_end_point = normal_hinge.getField("endPoint").getSFNode()

hinge2_hinge = hinge2_test_bot.getField("children").getMFNode(1)
hinge2_end_point = hinge2_hinge.getField("endPoint").getSFNode()

fields = [
    hinge_end_point.getField("rotation"),
    proto_test_bot.getField("hingeRotation"),
    nested_test_bot.getField("hingeRotation"),
    hinge2_end_point.getField("rotation"),
]

previous = [list(field.getSFRotation()) for field in fields]

robot.step(TIME_STEP * 2)

rotations = [field.getSFRotation() for field in fields]

ts_assert_double_is_bigger(rotations[0][3], previous[0][3], "The base node's motor should rotate, but it is not rotating.")
ts_assert_double_is_bigger(rotations[1][3], previous[1][3], "The PROTO's motor should rotate, but it is not rotating.")
ts_assert_double_is_bigger(rotations[2][3], previous[2][3],
                           "The nested PROTO's motor should rotate, but it is not rotating.")
ts_assert_double_is_bigger(rotations[3][3], previous[3][3], "The hinge2 motors should rotate, but they are not rotating.")

robot.step(TIME_STEP * 70)

normal_test_bot.resetPhysics()
proto_test_bot.resetPhysics()
nested_test_bot.resetPhysics()
hinge2_test_bot.resetPhysics()

previous = [list(field.getSFRotation()) for field in fields]

robot.step(TIME_STEP)

rotations = [field.getSFRotation() for field in fields]

ts_assert_rotation_equals(rotations[0], previous[0], 0.0001,
                          "The base node's motor should have stopped, but it is still turning.")
ts_assert_rotation_equals(rotations[1], previous[1], 0.0001,
                          "The PROTO's motor should have stopped, but it is still turning.")
ts_assert_rotation_equals(rotations[2], previous[2], 0.0001,
                          "The Nested PROTO's motor should have stopped, but it is still turning.")
ts_assert_rotation_equals(rotations[3], previous[3], 0.0001,
                          "The hinge2 motors should have stopped, but they are still turning.")

ts_send_success()
