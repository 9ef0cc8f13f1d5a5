"""Port of Webots' tests/protos/controllers/bounding_object_regeneration: a template PROTO used as a boundingObject
(of a Robot, and through a PROTO's SFNode parameter) regenerates when its size changes, and the new bounding object
collides (4 contact points) where the old one did not, and no longer where the old one did.
"""

from controller import Supervisor
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

probe_proto_node = robot.getFromDef("PROBE_PROTO")
probe_robot_node = robot.getFromDef("PROBE_ROBOT")

probe_proto_translation_field = probe_proto_node.getField("translation")
probe_robot_translation_field = probe_robot_node.getField("translation")

robot.step(TIME_STEP)

proto_number_contact_points = len(probe_proto_node.getContactPoints(True))
robot_number_contact_points = len(probe_robot_node.getContactPoints(True))

robot.step(TIME_STEP)

ts_assert_int_equal(proto_number_contact_points, 0,
                    "At the initial position of the proto probe the number of contact points should be 0 but isn't.")
ts_assert_int_equal(robot_number_contact_points, 0,
                    "At the initial position of the robot probe the number of contact points should be 0 but isn't.")

# set probe position in the first zone of conflict, collision should occur
probe_proto_first_contact_position = [0.5, 0, 0]
probe_robot_first_contact_position = [0.5, 0, 2]

probe_proto_translation_field.setSFVec3f(probe_proto_first_contact_position)
probe_robot_translation_field.setSFVec3f(probe_robot_first_contact_position)

robot.step(TIME_STEP)

proto_number_contact_points = len(probe_proto_node.getContactPoints(True))
robot_number_contact_points = len(probe_robot_node.getContactPoints(True))

ts_assert_int_equal(proto_number_contact_points, 4,
                    "The first contact position for the proto probe should have 4 contact points but doesn't.")
ts_assert_int_equal(robot_number_contact_points, 4,
                    "The first contact position for the robot probe should have 4 contact points but doesn't.")

robot.step(10 * TIME_STEP)

# force a regeneration of the boundingObject, making it smaller
regenerable_proto_box_node = robot.getFromDef("REGENERABLE_BOX_IN_PROTO")
regenerable_robot_box_node = robot.getFromDef("REGENERABLE_BOX_IN_ROBOT")

proto_size_field = regenerable_proto_box_node.getField("size")
robot_size_field = regenerable_robot_box_node.getField("size")

proto_size_field.setSFFloat(0.5)
robot_size_field.setSFFloat(0.5)

# test previous contact position, should no longer collide
probe_proto_translation_field.setSFVec3f(probe_proto_first_contact_position)
probe_robot_translation_field.setSFVec3f(probe_robot_first_contact_position)

robot.step(10 * TIME_STEP)

proto_number_contact_points = len(probe_proto_node.getContactPoints(True))
robot_number_contact_points = len(probe_robot_node.getContactPoints(True))

ts_assert_int_equal(
    proto_number_contact_points, 0,
    "After regeneration, for the proto probe the first contact position should have no contact points, but does.")
ts_assert_int_equal(
    robot_number_contact_points, 0,
    "After regeneration, for the robot probe the first contact position should have no contact points, but does.")

# set probe position in the second zone of conflict, collision should occur
proto_second_contact_position = [0.25, 0, 0]
robot_second_contact_position = [0.25, 0, 2]

probe_proto_translation_field.setSFVec3f(proto_second_contact_position)
probe_robot_translation_field.setSFVec3f(robot_second_contact_position)

robot.step(TIME_STEP)

proto_number_contact_points = len(probe_proto_node.getContactPoints(True))
robot_number_contact_points = len(probe_robot_node.getContactPoints(True))

ts_assert_int_equal(proto_number_contact_points, 4,
                    "The second contact position for the proto probe should have 4 contact points but doesn't.")
ts_assert_int_equal(robot_number_contact_points, 4,
                    "The second contact position for the robot probe should have 4 contact points but doesn't.")

robot.step(TIME_STEP)

ts_send_success()
