"""Port of Webots' tests/protos/controllers/hinge_joint_with_backlash_supervisor: the pendulum of a
HingeJointWithBacklash (Webots' library PROTO) does not move while its motor turns within the backlash range, and
after a physics reset swings +-0.0421 m, symmetrically, when the motor turns beyond it.
"""

import math

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 16
TEST_DURATION = 10.0

robot = Supervisor()
ts_setup(robot)

pendulum_bob = robot.getFromDef("PENDULUM_BOB")

# TEST #1: by switching direction BEFORE the backlash limit is reached, the endPoint shouldn't move
expected = [0.0, -0.4, 0.0]

while robot.step(TIME_STEP) != -1 and robot.getTime() < TEST_DURATION:
    values = pendulum_bob.getPosition()
    ts_assert_vec3_in_delta(values[0], values[1], values[2], expected[0], expected[1], expected[2], 0.0000001,
                            "The pendulum moves despite being inside the backlash range."
                            " (expected = {%f, %f, %f}, measured = {%f, %f, %f})",
                            expected[0], expected[1], expected[2], values[0], values[1], values[2])

robot.simulationResetPhysics()

# TEST #2: by switching direction AFTER the backlash limit is reached, the endPoint should move
x_max = -math.inf
x_min = math.inf

while robot.step(TIME_STEP) != -1 and robot.getTime() < 2 * TEST_DURATION:
    values = pendulum_bob.getPosition()
    if values[0] < x_min:
        x_min = values[0]
    if values[0] > x_max:
        x_max = values[0]

# Test that it moved
ts_assert_double_in_delta(x_max, 0.0421, 0.0001, "Positive swing overshoot or undershoot. (expected = 0.0421, measured = %f)",
                          x_max)

ts_assert_double_in_delta(x_min, -0.0421, 0.0001,
                          "Negative swing overshoot or undershoot. (expected = -0.0421, measured = %f)", x_min)

# Test that the swings are sufficiently symmetric
ts_assert_double_in_delta(math.fabs(x_max) - math.fabs(x_min), 0.0, 0.00005,
                          "The swings differ by too much. (x_min = %f, x_max = %f)", x_min, x_max)

ts_send_success()
