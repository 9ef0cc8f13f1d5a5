"""Port of Webots' tests/api/controllers/supervisor_reset_simulation_fields: after simulationReset, a field read by
another supervisor shows the value written after the reset, not a stale one.

Webots' repository holds two versions of the C controller; this ports the later one (the resetter waits one step
after the reset before writing, "or else the reset will overwrite the new value").
"""

import sys

from controller import Supervisor
from ts_assertion import ts_assert_vec3_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot, sys.argv[1])

initial_translation = [0, 0, 1]
new_translation = [1, 0, 0]
translation_field = robot.getFromDef("SOLID").getField("translation")
if sys.argv[1] == "supervisor_reset_simulation_fields_resetter":
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)

    # <Other controller verifies SOLID's inital position>

    robot.step(TIME_STEP)
    robot.simulationReset()
    robot.step(TIME_STEP)  # We have to wait another step or else the reset will overwrite the new value
    translation_field.setSFVec3f(new_translation)
else:
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    first_translation = translation_field.getSFVec3f()
    ts_assert_vec3_equal(first_translation[0], first_translation[1], first_translation[2], initial_translation[0],
                         initial_translation[1], initial_translation[2],
                         "SOLID's initial position should be [%f, %f, %f] not [%f, %f, %f]", initial_translation[0],
                         initial_translation[1], initial_translation[2], first_translation[0], first_translation[1],
                         first_translation[2])
    robot.step(TIME_STEP)

    # <Other controller resets the simulation>

    robot.step(TIME_STEP)

    # <Other controller updates SOLID's position>

    robot.step(TIME_STEP)
    second_translation = translation_field.getSFVec3f()
    ts_assert_vec3_equal(second_translation[0], second_translation[1], second_translation[2], new_translation[0],
                         new_translation[1], new_translation[2],
                         "SOLID's position should be [%f, %f, %f] not [%f, %f, %f] after reset", new_translation[0],
                         new_translation[1], new_translation[2], second_translation[0], second_translation[1],
                         second_translation[2])

ts_send_success()
