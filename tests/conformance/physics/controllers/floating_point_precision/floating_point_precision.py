"""Port of Webots' tests/physics/controllers/floating_point_precision: worldSave keeps doubles exactly.

The first run imports one Pose per value, writes the value into its translation, saves the world and
loads the saved file; the controller of the reloaded world checks the values and the saved text.
"""

import os
import re
import sys

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_equal,
    ts_assert_int_equal,
    ts_assert_string_equal,
    ts_send_success,
    ts_setup,
)

# The saved world sits beside the test world (so that its controller is found); the runner ignores *_temp.wbt.
TEMP_WORLD = "../../worlds/floating_point_precision_temp.wbt"
DBL_EPSILON = sys.float_info.epsilon
DBL_MIN = sys.float_info.min
FLT_MAX = 3.4028234663852886e38
VALUES = [0.0, 0.1, 0.2, 0.3, 123456.0, 0.123456, 123456789012345.0, 0.123456789012345, DBL_EPSILON, -DBL_EPSILON,
          DBL_MIN, FLT_MAX]

robot = Supervisor()
time_step = int(robot.getBasicTimeStep())
custom_data = robot.getCustomData()
root_children = robot.getRoot().getField("children")

if custom_data == "init":
    for i, value in enumerate(VALUES):
        name = f"TEST_{i}"
        root_children.importMFNodeFromString(-1, f"DEF {name} Pose {{}}")
        robot.getFromDef(name).getField("translation").setSFVec3f([value, value, value])
    robot.setCustomData("saved")  # tells the reloaded controller apart
    robot.step(time_step)
    robot.worldSave(TEMP_WORLD)
    robot.worldLoad(TEMP_WORLD)
    robot.step(time_step)
elif custom_data == "saved":
    ts_setup(robot, "floating_point_precision")
    ts_assert_boolean_equal((1.0 + DBL_EPSILON) != 1.0 and (1.0 + DBL_EPSILON / 2) == 1.0, "DBL_EPSILON is not correct.")
    for i, value in enumerate(VALUES):
        got = robot.getFromDef(f"TEST_{i}").getField("translation").getSFVec3f()
        for c in range(3):
            ts_assert_double_equal(got[c], value, "Issue when getting value[%d][%d] (get = %g, expected = %g)", i, c, got[c],
                                   value)

    # No noise digits: the first three translations of the saved file read exactly 0.1, 0.2 and 0.3.
    with open(TEMP_WORLD, encoding="utf-8") as saved:
        lines = saved.read().splitlines()
    os.remove(TEMP_WORLD)
    counter = 0
    for line in lines:
        match = re.match(r"  translation (\S+) (\S+) (\S+)", line)
        if match:
            counter += 1
            if counter > 3:
                break
            expected = f"0.{counter}"
            for k in range(3):
                ts_assert_string_equal(match.group(k + 1), expected, "Unexpected TEST_%d.translation[%d] (expected: %s, get: %s)",
                                       counter, k, expected, match.group(k + 1))
    ts_assert_int_equal(counter - 1, 3, "Cannot read 3 TEST_?.translation in %s (read: %d)", TEMP_WORLD, counter)
    ts_send_success()
