"""Port of Webots' tests/physics/controllers/runtime_geom_update: bounding objects resized at run time collide."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 8
KINDS = [("Box", "box"), ("Cylinder", "cylinder"), ("Sphere", "sphere"), ("Capsule", "capsule"),
         ("IndexedFaceSet", "indexed face set")]

robot = Supervisor()
ts_setup(robot)
distance = {}
touch = {}
for kind, _ in KINDS:
    distance[kind] = robot.getDevice("ds" + kind)
    distance[kind].enable(TIME_STEP)
for kind, _ in KINDS:
    touch[kind] = robot.getDevice("ts" + kind)
    touch[kind].enable(TIME_STEP)

box_size = robot.getFromDef("BO_BOX").getField("size")
cylinder_radius = robot.getFromDef("BO_CYLINDER").getField("radius")
sphere_radius = robot.getFromDef("BO_SPHERE").getField("radius")
capsule_height = robot.getFromDef("BO_CAPSULE").getField("height")
coord_point = robot.getFromDef("BO_INDEXED_FACE_SET_COORD").getField("point")

robot.step(2 * TIME_STEP)
box_size.setSFVec3f([1.0, 0.1, 0.1])
cylinder_radius.setSFFloat(0.5)
sphere_radius.setSFFloat(0.35)
capsule_height.setSFFloat(1.5)
coord_point.setMFVec3f(2, [1.0, -0.05, 0])
robot.step(TIME_STEP)

for kind, _ in KINDS:
    value = distance[kind].getValue()
    ts_assert_double_in_delta(value, 300.0, 0.1, "%s scaling not detected from the distance sensor (received = %f)",
                              kind, value)

while robot.getTime() < 1.0:
    robot.step(TIME_STEP)
    for kind, words in KINDS:
        ts_assert_int_equal(int(touch[kind].getValue()), 0, "Object passed trough the scaled %s", words)

ts_send_success()
