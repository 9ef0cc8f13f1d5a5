"""Port of Webots' tests/api/controllers/supervisor_force_torque: forces and torques added by the supervisor (global
or relative, with or without an offset, on a Solid merged into its parent) turn nine hinged balances as expected."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_assert_double_is_bigger, ts_send_success, ts_setup

TIME_STEP = 32
SOLID_NUMBER = 9

robot = Supervisor()
ts_setup(robot)

node = []
ps = []
for i in range(SOLID_NUMBER):
    node.append(robot.getFromDef("BALANCE_%d" % i))
    ps.append(robot.getDevice("ps%d" % i))
    ps[i].enable(TIME_STEP)

for _ in range(20):
    robot.step(TIME_STEP)

for i in range(SOLID_NUMBER):
    ts_assert_double_in_delta(ps[i].getValue(), 0.0, 0.01,
                              "All position angle should be ~0.0 before applying any force/torque")

force0 = [0.0, 0.1, 0.0]
force1 = [0.1, 0.0, 0.0]
torque0 = [0.1, 0.0, 0.0]
torque1 = [0.0, 0.1, 0.0]
offset0 = [0.0, 0.0, 0.15]
offset1 = [0.0, 0.0, -0.15]
offset2 = [0.0, 0.0, 0.0]

for _ in range(200):
    robot.step(TIME_STEP)
    node[0].addForceWithOffset(force0, offset0, False)
    node[1].addForceWithOffset(force0, offset1, False)
    node[2].addForceWithOffset(force0, offset2, False)
    node[3].addTorque(torque0, False)
    node[4].addForce(force0, False)
    node[5].addForceWithOffset(force0, offset0, False)
    node[6].addTorque(torque0, True)
    node[7].addTorque(torque1, True)
    node[8].addForce(force1, True)

positions = [ps[i].getValue() for i in range(SOLID_NUMBER)]

ts_assert_double_in_delta(positions[0], -positions[1], 0.01, "Angle 0 should be equal to -angle 1.")
ts_assert_double_in_delta(positions[4], positions[5], 0.01, "Angle 4 should be equal to angle 5.")
ts_assert_double_in_delta(positions[6], positions[3], 0.01, "Angle 3 should be equal to angle 6.")
ts_assert_double_in_delta(positions[2], 0.0, 0.01, "Angle 2 should be zero")
ts_assert_double_is_bigger(-0.2, positions[0], "Angle 0 should be smaller than -0.2")
ts_assert_double_is_bigger(positions[1], 0.2, "Angle 1 should be bigger than 0.2")
ts_assert_double_is_bigger(positions[3], 0.2, "Angle 3 should be bigger than 0.2")
ts_assert_double_is_bigger(-0.2, positions[4], "Angle 4 should be smaller than -0.2")
ts_assert_double_is_bigger(-0.2, positions[5], "Angle 5 should be smaller than -0.2")
ts_assert_double_in_delta(positions[7], 0.0, 0.01, "Angle 7 should be zero")
ts_assert_double_in_delta(positions[8], 0.0, 0.01, "Angle 8 should be zero")

# let the solid go to sleep
for _ in range(200):
    robot.step(TIME_STEP)

force = [0.0, -0.1, 0.0]
torque = [-0.1, 0.0, 0.0]
for _ in range(200):
    robot.step(TIME_STEP)
    node[0].addForceWithOffset(force, offset0, False)
    node[3].addTorque(torque, False)
    node[4].addForce(force, False)

positions = [ps[i].getValue() for i in range(SOLID_NUMBER)]

ts_assert_double_is_bigger(positions[0], 0.2, "Angle 0 should be bigger than 0.2")
ts_assert_double_is_bigger(-0.2, positions[3], "Angle 3 should be smaller than -0.2")
ts_assert_double_is_bigger(positions[4], 0.2, "Angle 4 should be bigger than 0.2")

ts_send_success()
