"""Port of Webots' tests/api/controllers/radar_frustum: a radar sees only the solids inside its frustum, counted at
its sampling period as they are removed one by one."""

from controller import Supervisor
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32
SOLID_NUMBER = 6

SOLID_NAMES = ("VISIBLE_SPHERE", "NOT_VISIBLE_SPHERE", "VISIBLE_BOX",
               "NOT_VISIBLE_BOX", "VISIBLE_CAPSULE", "NOT_VISIBLE_CAPSULE")

robot = Supervisor()
ts_setup(robot)

radar = robot.getDevice("radar")
radar.enable(3 * TIME_STEP)

robot.step(TIME_STEP)

target_number = radar.getNumberOfTargets()
ts_assert_int_equal(target_number, 0, "The radar should see 0 targets and not %d after 1 step from enable call.",
                    target_number)

robot.step(TIME_STEP)

target_number = radar.getNumberOfTargets()
ts_assert_int_equal(target_number, 0, "The radar should see 0 targets and not %d after 2 steps from enable call.",
                    target_number)

robot.step(TIME_STEP)

for i in range(SOLID_NUMBER):
    target_number = radar.getNumberOfTargets()
    ts_assert_int_equal(target_number, (SOLID_NUMBER - i) // 2,
                        "The radar should see %d targets and not %d before removing '%s'.", (SOLID_NUMBER - i) // 2,
                        target_number, SOLID_NAMES[i])
    node = robot.getFromDef(SOLID_NAMES[i])
    node.remove()
    robot.step(2 * TIME_STEP)
    target_number = radar.getNumberOfTargets()
    ts_assert_int_equal(
        target_number, (SOLID_NUMBER - i) // 2,
        "The radar should see %d targets and not %d after removing '%s' and before the sampling period elapsed.",
        (SOLID_NUMBER - i) // 2, target_number, SOLID_NAMES[i])
    robot.step(TIME_STEP)
    target_number = radar.getNumberOfTargets()
    ts_assert_int_equal(target_number, (SOLID_NUMBER - i - 1) // 2,
                        "The radar should see %d targets and not %d after removing '%s'.", (SOLID_NUMBER - i - 1) // 2,
                        target_number, SOLID_NAMES[i])

ts_send_success()
