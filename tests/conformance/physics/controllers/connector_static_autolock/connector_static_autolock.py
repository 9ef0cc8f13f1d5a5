"""Port of Webots' tests/physics/controllers/connector_static_autolock: a free Solid's connector touching the
connector of a static robot (no Physics) locks to it and is held in place, against gravity, for 100 steps."""

from controller import Supervisor
from ts_assertion import ts_assert_boolean_equal, ts_assert_vec3_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

solid = robot.getFromDef("SOLID")

connector = robot.getDevice("connector")
connector.enablePresence(TIME_STEP)

robot.step(TIME_STEP)

ts_assert_boolean_equal(connector.getPresence() == 1, "Connectors are expected to be in contact at the beginning.")

connector.lock()

robot.step(TIME_STEP)

for _ in range(100):
    robot.step(TIME_STEP)

position = solid.getPosition()
ts_assert_vec3_in_delta(position[0], position[1], position[2], 0.25, 0.2, 0.0, 0.005,
                        "Solid not at the expected position.")

ts_send_success()
