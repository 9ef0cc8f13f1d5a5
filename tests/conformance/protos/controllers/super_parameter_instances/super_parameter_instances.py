"""Port of Webots' tests/protos/controllers/super_parameter_instances (regression test for Webots issue #6059):
importing nodes (an Accelerometer, a VelodyneVLP-16, a Servo holding a test PROTO) into a Pose given as a PROTO
parameter (the BmwX5's sensorsSlotTop) does not crash the simulator."""

from controller import Supervisor
from ts_assertion import ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)  # give the controller args

node = robot.getFromDef("SENSOR_SLOT")
children_field = node.getField("children")

# Webots should not crash when inserting subnodes,
# this means that the nodes in mSuperParametersAtInitialization list are ignored during finalization
children_field.importMFNodeFromString(0, "Accelerometer { }")
robot.step(TIME_STEP)

children_field.importMFNodeFromString(1, "VelodyneVLP-16 { }")
robot.step(TIME_STEP)

children_field.importMFNodeFromString(
    1, "Servo { translation 0 1 0 children [ DerivedColoredBoxShape { boxSize 0.5 0.5 0.5 } ] }")
robot.step(TIME_STEP)

ts_send_success()
