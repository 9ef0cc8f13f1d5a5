"""Port of Webots' tests/api/controllers/motion: a Hexapod plays tests/api/motions/HexapodForwards.motion once
("regular"), reversed ("reverse") or looped for 0.002 x its duration ("loop"), and must end where Webots' ODE put
it (calibrated positions, 0.1 mm tolerance). The motions_* worlds pass the mode in controllerArgs."""

import math
import sys

from controller import Motion, Robot
from ts_assertion import ts_assert_boolean_equal, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 40


def wait_s(time: float) -> None:
    starts = robot.getTime()
    while robot.getTime() - starts < time:
        robot.step(TIME_STEP)


def distance(v1, v2) -> float:
    return math.sqrt((v1[0] - v2[0]) * (v1[0] - v2[0]) + (v1[1] - v2[1]) * (v1[1] - v2[1]) +
                     (v1[2] - v2[2]) * (v1[2] - v2[2]))


robot = Robot()
regular = sys.argv[1] == "regular"
loop = sys.argv[1] == "loop"
reverse = sys.argv[1] == "reverse"

ts_setup(robot, "motion_%s" % sys.argv[1])

ts_assert_int_equal(len(sys.argv), 2, "Wrong arguments size")

gps = robot.getDevice("gps")
gps.enable(TIME_STEP)

wait_s(1.0)  # stablize the robot before playing the motion

forwards = Motion("../../motions/HexapodForwards.motion")

if regular:
    # Note (David): calibrated on my Ubuntu 64 with ODE MT
    expected_position = [-0.278282, 0.079743, -0.002273]
elif loop:
    # Note (David): calibrated on my Ubuntu 64 with ODE MT
    expected_position = [-0.539533, 0.079410, -0.011085]
    forwards.setLoop(True)
elif reverse:
    # Note (David): calibrated on my Ubuntu 64 with ODE MT
    expected_position = [0.278282, 0.079743, -0.002273]
    forwards.setReverse(True)
else:
    expected_position = [0, 0, 0]
    ts_assert_boolean_equal(False, "Unexpected argument")

forwards.play()

if loop:
    start_time = robot.getTime()
    while True:
        robot.step(TIME_STEP)
        if not robot.getTime() < start_time + 0.002 * forwards.getDuration():
            break
    forwards.stop()
else:
    while True:
        robot.step(TIME_STEP)
        if forwards.isOver():
            break
wait_s(1.0)  # stabilize the robot before playing the motion

position = gps.getValues()
err = distance(position, expected_position)
print("pos = %f %f %f" % (position[0], position[1], position[2]))
print("expected = %f %f %f" % (expected_position[0], expected_position[1], expected_position[2]))
print("Error = %f" % err)
ts_assert_boolean_equal(err < 0.0001, "Unexpected target position (error = %g)", err)

ts_send_success()
