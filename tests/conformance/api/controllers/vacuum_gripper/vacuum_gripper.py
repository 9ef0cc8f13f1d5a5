"""Port of Webots' tests/api/controllers/vacuum_gripper: a VacuumGripper on a slider lifts a box only while it is on,
and releases it when turned off."""

from controller import Supervisor
from ts_assertion import (
                        ts_assert_boolean_equal,
                        ts_assert_int_equal,
                        ts_assert_vec3_in_delta,
                        ts_send_success,
                        ts_setup,
)

TIME_STEP = 32
JOINT_STEP = 0.1

robot = Supervisor()
ts_setup(robot)

motor = robot.getDevice("linear motor")

vacuum_gripper = robot.getDevice("vacuum gripper")
vacuum_gripper.enablePresence(TIME_STEP)

obj = robot.getFromDef("OBJECT")
p0 = list(obj.getPosition())

robot.step(5 * TIME_STEP)

motor.setPosition(JOINT_STEP)

robot.step(30 * TIME_STEP)

ts_assert_boolean_equal(not vacuum_gripper.isOn(), "Vacuum gripper should not be on at start.")
ts_assert_boolean_equal(not vacuum_gripper.getPresence(),
                        "Vacuum gripper should not be connected to objects when turned off.")
ts_assert_int_equal(vacuum_gripper.getPresenceSamplingPeriod(), TIME_STEP, "Vacuum gripper wrong sampling period.")

p1 = obj.getPosition()
ts_assert_vec3_in_delta(p1[0], p1[1], p1[2], p0[0], p0[1], p0[2], 0.002, "Object shouldn't move before vacumm cup is on.")

motor.setPosition(0)

robot.step(30 * TIME_STEP)

vacuum_gripper.turnOn()

robot.step(TIME_STEP)

ts_assert_boolean_equal(vacuum_gripper.isOn(), "Vacuum gripper should be turned on.")
ts_assert_boolean_equal(vacuum_gripper.getPresence(), "Vacuum gripper should be connected to object when is on.")

motor.setPosition(JOINT_STEP)
robot.step(50 * TIME_STEP)

p2 = obj.getPosition()
ts_assert_vec3_in_delta(p2[0], p2[1], p2[2], p0[0], p0[1], p0[2] + JOINT_STEP, 0.002,
                        "Object should be lifted when vacumm cup is on.")

vacuum_gripper.turnOff()

robot.step(TIME_STEP)
ts_assert_boolean_equal(not vacuum_gripper.isOn(), "Vacuum gripper should be off after turning it off.")
ts_assert_boolean_equal(not vacuum_gripper.getPresence(), "Vacuum gripper should release the object when is turned off.")

robot.step(30 * TIME_STEP)

p3 = obj.getPosition()
ts_assert_vec3_in_delta(p3[0], p3[1], p3[2], p0[0], p0[1], p0[2], 0.002,
                        "Object should be release when vacumm cup is turned off.")

ts_send_success()
