"""Port of Webots' tests/protos/controllers/hingejoint_with_backlash_supervisor at ff91c94b, run by the R2021b world
hingejoint_with_backlash.wbt with the pendulum robot's controller of the same commit: the pendulum of a
HingeJointWithBacklash (Webots' library PROTO) does not move for 10 s while the robot turns its motor within the
backlash range (+-0.10 rad), and after a physics reset, while the robot turns it beyond (+-0.105 rad), swings
+-0.0421 m by 20 s, symmetrically.
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
print("SUPERVISOR Test #1: Start.")
expected = [0.0, -0.4, 0.0]
while robot.step(TIME_STEP) != -1 and robot.getTime() < TEST_DURATION:
    # control
    values = pendulum_bob.getPosition()
    ts_assert_vec3_in_delta(values[0], values[1], values[2], expected[0], expected[1], expected[2], 0.0000001,
                            "The pendulum moves despite being inside the backlash range."
                            " (expected = {%f, %f, %f}, received = {%f, %f, %f})",
                            expected[0], expected[1], expected[2], values[0], values[1], values[2])
print("SUPERVISOR Test #1: Done.")

robot.simulationResetPhysics()

# TEST #2: by switching direction AFTER the backlash limit is reached, the endPoint shouldn't move
print("SUPERVISOR Test #2: Start.")

xmax = -math.inf
xmin = math.inf
while robot.step(TIME_STEP) != -1 and robot.getTime() < 2 * TEST_DURATION:
    values = pendulum_bob.getPosition()
    if values[0] < xmin:
        xmin = values[0]
    if values[0] > xmax:
        xmax = values[0]

print("SUPERVISOR Test #2: Done.")
# Test that it moved ...
exp = 0.0421
delta = math.fabs(xmax) - exp
ts_assert_double_in_delta(delta, 0.0, 0.0001, "Positive swing overshoot or undershoot. (expected = %.10f, value = %.10f", exp,
                          math.fabs(xmax))

delta = math.fabs(xmin) - exp
ts_assert_double_in_delta(delta, 0.0, 0.0001, "Negative swing overshoot or undershoot. (expected = %.10f, value = %.10f", exp,
                          math.fabs(xmin))

# Test that the swings are sufficiently symmetric
delta = math.fabs(xmax) - math.fabs(xmin)
ts_assert_double_in_delta(delta, 0.0, 0.00005, "The swings differ by too much. (values: %.10f // %.10f)", xmin, xmax)

ts_send_success()
