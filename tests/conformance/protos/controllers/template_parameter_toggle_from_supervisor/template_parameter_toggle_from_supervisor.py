"""Port of Webots' tests/protos/controllers/template_parameter_toggle_from_supervisor: a supervisor sets a template
PROTO's SFBool `physicsToggle` that adds a Physics node to its Solid, which then falls on a touch sensor; the
regenerated node's fields stay reachable (its translation is reset and read back).

Run by template_parameter_toggle_from_supervisor.wbt (JavaScript template) and its _lua variant (Lua template). The
test name comes from controllerArgs, as the C original's ts_setup(argv[1]); its spaces become underscores because
the runner's result lines are space-separated.
"""

import sys

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_pointer_not_null,
    ts_assert_vec3_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])

template = robot.getFromDef("TEMPLATE")
ts_assert_pointer_not_null(template, "Unable to retrieve template node")

toggle = template.getField("physicsToggle")
ts_assert_pointer_not_null(toggle, "Unable to retrieve physicsToggle field")

toggle.setSFBool(True)
ts_assert_boolean_equal(toggle.getSFBool(), "Problem when setting physicsToggle")

ts = robot.getDevice("touch sensor")
ts.enable(TIME_STEP)
robot.step(TIME_STEP)

success = False
for _i in range(3000 // TIME_STEP):
    robot.step(TIME_STEP)
    if ts.getValue() != 0:
        success = True
        break

ts_assert_boolean_equal(success, "No collision detected")

# check the node id is still accessible
# by reseting the node at its initial state
toggle.setSFBool(False)
translation_field = template.getField("translation")
ts_assert_pointer_not_null(translation_field, "Unable to retrieve the translation field after the node regeneration.")
initial_translation = [0.0, 1.0, 0.0]
translation_field.setSFVec3f(initial_translation)

robot.step(TIME_STEP)

current_translation = translation_field.getSFVec3f()
ts_assert_vec3_equal(current_translation[0], current_translation[1], current_translation[2], initial_translation[0],
                     initial_translation[1], initial_translation[2],
                     "Impossible to reset the procedural node to its initial set after a successful regeneration.")

ts_send_success()
