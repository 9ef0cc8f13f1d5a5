"""Port of Webots' tests/protos/controllers/hingejoint_with_backlash_supervisor (a55acb30), run by the R2021b world
hingejoint_with_backlash.wbt: the pendulum of a HingeJointWithBacklash (Webots' library PROTO) does not move while
its motor turns within the backlash range, and after a physics reset swings +-0.0421 m, symmetrically.

The C test also gets the devices "hingeInputMotor" and "hingeInputSensor", which belong to the pendulum robot, not to
this supervisor: Webots returns tag 0 and its wb_motor_*/wb_position_sensor_* calls print an error and do nothing
(the sensor reads NaN, so no comparison holds). Python returns None; the port skips those calls likewise.
"""

import math

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 16
TEST_DURATION = 2.5
SPEED = 0.2

robot = Supervisor()
ts_setup(robot)

motorInput = robot.getDevice("hingeInputMotor")
positionInput = robot.getDevice("hingeInputSensor")


def set_velocity(velocity):
    if motorInput is not None:  # C: wb_motor_set_velocity(0, ...) is ignored.
        motorInput.setVelocity(velocity)


def position_value():
    return positionInput.getValue() if positionInput is not None else math.nan  # C: NaN for tag 0.


if positionInput is not None:
    positionInput.enable(TIME_STEP)

if motorInput is not None:
    motorInput.setPosition(math.inf)
set_velocity(SPEED)

pendulum_bob = robot.getFromDef("PENDULUM_BOB")

# TEST #1: by switching direction BEFORE the backlash limit is reached, the endPoint shouldn't move
print("Test #1: Start.")
expected = [0.0, -0.4, 0.0]
while robot.step(TIME_STEP) != -1 and robot.getTime() < TEST_DURATION:
    # command
    pos = position_value()

    if pos >= 0.10:
        set_velocity(-SPEED)
    if pos <= -0.10:
        set_velocity(SPEED)

    # control
    values = pendulum_bob.getPosition()
    ts_assert_vec3_in_delta(values[0], values[1], values[2], expected[0], expected[1], expected[2], 0.0000001,
                            "The pendulum moves despite being inside the backlash range."
                            " (expected = {%f, %f, %f}, received = {%f, %f, %f})",
                            expected[0], expected[1], expected[2], values[0], values[1], values[2])
print("Test #1: Done.")

set_velocity(0.0)
robot.simulationResetPhysics()
set_velocity(SPEED)

# TEST #2: by switching direction AFTER the backlash limit is reached, the endPoint shouldn't move
print("Test #2: Start.")

xmax = -math.inf
xmin = math.inf
while robot.step(TIME_STEP) != -1 and robot.getTime() < 2 * TEST_DURATION:
    # command
    pos = position_value()

    if pos >= 0.105:
        set_velocity(-SPEED)
    if pos <= -0.105:
        set_velocity(SPEED)

    # control
    values = pendulum_bob.getPosition()
    if values[0] < xmin:
        xmin = values[0]
    if values[0] > xmax:
        xmax = values[0]

print("Test #2: Done.")
print("%.5f %.5f" % (xmin, xmax))
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
