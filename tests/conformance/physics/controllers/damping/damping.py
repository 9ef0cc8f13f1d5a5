"""Port of Webots' tests/physics/controllers/damping: more linear damping, later landing (WorldInfo default too)."""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)
time_step = int(robot.getBasicTimeStep())


def step() -> None:
    if robot.step(time_step) == -1:
        ts_assert_boolean_equal(False, "Controller stopped before having being able to conclude.")


ts = [robot.getDevice(name) for name in ("tsA", "tsB", "tsC", "tsD")]
for sensor in ts:
    sensor.enable(time_step)
step()
for sensor, name in zip(ts, "ABCD", strict=True):
    ts_assert_boolean_equal(sensor.getValue() == 0, "Collision detected on ts%s too soon." % name)


def touching(i: int) -> bool:
    return ts[i].getValue() != 0


counter = 0
# Ball B (no damping) lands first.
while True:
    step()
    ts_assert_boolean_equal(counter < 1000, "Ball B is not touching the ground.")
    counter += 1
    ts_assert_boolean_equal(not touching(0) and not touching(2) and not touching(3),
                            "A collision has occured before or at the same time than BALL B.")
    if touching(1):
        break
# Balls A (the world's default damping 0.4) and C (0.4) land together.
while True:
    step()
    ts_assert_boolean_equal(counter < 1000, "Ball A or C are not touching the ground.")
    counter += 1
    ts_assert_boolean_equal(not touching(3), "A collision has occured before or at the same time than BALL A and C.")
    if touching(0) or touching(2):
        ts_assert_boolean_equal(touching(0) and touching(2), "Balls A and C should arrive at the same time.")
        break
# Ball D (0.8) lands last.
while True:
    step()
    ts_assert_boolean_equal(counter < 1000, "Ball D is not touching the ground.")
    counter += 1
    if touching(3):
        break

ts_send_success()
