"""Port of Webots' tests/api/controllers/supervisor_save_world: worldSave writes a file that holds a field changed at
run time (a Sphere's radius) and the Viewpoint's orientation and position as they were read."""

import os

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_boolean_not_equal,
    ts_assert_double_equal,
    ts_assert_doubles_equal,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TARGET_WORLD_NAME = "test.wbt"


def atof(token: str) -> float:
    """C's atof: the longest leading number, 0 when there is none."""
    text = token.strip()
    for end in range(len(text), 0, -1):
        try:
            return float(text[:end])
        except ValueError:
            continue
    return 0.0


robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

if os.path.exists(TARGET_WORLD_NAME):
    os.remove(TARGET_WORLD_NAME)
ts_assert_boolean_not_equal(os.path.exists(TARGET_WORLD_NAME), "Impossible to remove the target world file.")

sphere = robot.getFromDef("SPHERE")
ts_assert_pointer_not_null(sphere, "Cannot find the sphere object.")
sphere_radius_field = sphere.getField("radius")
ts_assert_pointer_not_null(sphere_radius_field, "Cannot find the sphere radius field.")
sphere_radius_field.setSFFloat(0.2)

viewpoint = robot.getFromDef("VIEWPOINT")
ts_assert_pointer_not_null(viewpoint, "Cannot find the viewpoint object.")
viewpoint_orientation_field = viewpoint.getField("orientation")
expected_orientation = list(viewpoint_orientation_field.getSFRotation())
viewpoint_position_field = viewpoint.getField("position")
expected_position = list(viewpoint_position_field.getSFVec3f())

robot.step(time_step)

ts_assert_double_equal(sphere_radius_field.getSFFloat(), 0.2, "Cannot set the sphere radius field")

success = robot.worldSave(TARGET_WORLD_NAME)

ts_assert_boolean_equal(success, "Issue when saving the world.")
ts_assert_boolean_equal(os.path.exists(TARGET_WORLD_NAME), "The target world file doesn't exist.")

radius_found = False
orientation_found = False
position_found = False
with open(TARGET_WORLD_NAME, encoding="utf-8") as file:
    for line in file:
        tokens = [token for token in line.split(" ") if token]
        if not tokens:
            continue
        first = tokens[0]
        if first == "orientation":
            value = []
            for i in range(4):
                token = tokens[1 + i] if 1 + i < len(tokens) else None
                ts_assert_pointer_not_null(token, "Invalid 'orientation' value in the target file.")
                value.append(atof(token))
            ts_assert_doubles_equal(4, value, expected_orientation, "Wrong 'orientation' value in the target file.\n")
            orientation_found = True
        elif first == "position":
            value = []
            for i in range(3):
                token = tokens[1 + i] if 1 + i < len(tokens) else None
                ts_assert_pointer_not_null(token, "Wrong 'position' value in the target file.")
                value.append(atof(token))
            ts_assert_doubles_equal(3, value, expected_position, "Wrong 'position' value in the target file.\n")
            position_found = True
        elif first == "radius":
            token = tokens[1] if len(tokens) > 1 else None
            ts_assert_pointer_not_null(token, "Invalid 'radius' value in the target file.")
            value = atof(token)
            ts_assert_double_equal(value, 0.2, "Wrong 'radius' value in the target file: expected %f, found %f\n", 0.2,
                                   value)
            radius_found = True

ts_assert_boolean_equal(orientation_found, "The target file doesn't contain the viewpoint 'orientation' field definition.")
ts_assert_boolean_equal(position_found, "The target file doesn't contain the viewpoint 'position' field definition.")
ts_assert_boolean_equal(radius_found, "The target file doesn't contain the sphere radius modification.")

ts_send_success()
