"""Port of Webots' tests/api/controllers/supervisor_reset_simulation: simulationReset regenerates a non-deterministic
PROTO (its custom data counts the regenerations), restores the solids' positions, and node visibility and imported
nodes seen by cameras before the reset.
"""

import os
import sys

from controller import Supervisor
from ts_assertion import (
    ts_assert_color_in_delta,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_assert_vec3_in_delta,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
SOLID_BOX_NUMBER = 5

robot = Supervisor()
ts_setup(robot, sys.argv[1])

camera = [robot.getDevice("camera0"), robot.getDevice("camera1")]

root_children = robot.getRoot().getField("children")
self_node = robot.getSelf()
controller_args_field = self_node.getField("controllerArgs")
description_field = self_node.getField("description")

box_node = robot.getFromDef("BOX")
camera_node = robot.getFromDef("CAMERA0")
solid_box = [robot.getFromDef("SOLID%d" % i) for i in range(SOLID_BOX_NUMBER)]

ts_assert_pointer_not_null(box_node, "The supervisor cannot get the WbNodeRef of BOX.")
ts_assert_pointer_not_null(camera_node, "The supervisor cannot get the WbNodeRef of CAMERA0.")

camera[0].enable(TIME_STEP)
camera[1].enable(TIME_STEP)

robot.step(TIME_STEP)


def pixel(cam):
    image = cam.getImage()
    return image[2], image[1], image[0]


r, g, b = pixel(camera[0])
ts_assert_color_in_delta(r, g, b, 207, 0, 0, 0, "CAMERA0 should see the red box before changing it's visibility.")
r, g, b = pixel(camera[1])
ts_assert_color_in_delta(r, g, b, 0, 0, 255, 0, "CAMERA1 should see the background before importing the second box.")

root_children.importMFNodeFromString(-1, 'Solid { translation 1.3 0 0 children [ USE BOX_SHAPE ] name "solid(1)" }')
box_node.setVisibility(camera_node, False)

robot.step(TIME_STEP)

r, g, b = pixel(camera[0])
ts_assert_color_in_delta(r, g, b, 0, 0, 255, 0,
                         "CAMERA0 should see the background after changing the visibility of the first box.")
r, g, b = pixel(camera[1])
ts_assert_color_in_delta(r, g, b, 207, 0, 0, 0, "CAMERA1 should see the second red box before importing it.")

while robot.step(TIME_STEP) != -1 and robot.getTime() < 2.0:
    pass

words = robot.getCustomData().split()
iteration = int(words[0])
file_path = words[1] if len(words) > 1 else ""

if sys.argv[1] == "supervisor_reset_simulation_iteration_0":
    controller_args_field.setMFString(0, "supervisor_reset_simulation_iteration_1")
    ts_assert_int_equal(iteration, 0,
                        "Robot custom data should start with '0' at first iteration, not '%d'. The PROTO has been "
                        "regenerated since Webots started.", iteration)
    text = ""
    for i in range(SOLID_BOX_NUMBER):
        position = solid_box[i].getPosition()
        text += "%.8f %.8f %.8f " % (position[0], position[1], position[2])
    description_field.setSFString(text)
    robot.step(TIME_STEP)
    robot.simulationReset()
    self_node.restartController()
    test_suite_supervisor = robot.getFromDef("TEST_SUITE_SUPERVISOR")  # removed from the world in wbtc
    if test_suite_supervisor is not None:
        test_suite_supervisor.restartController()
elif sys.argv[1] == "supervisor_reset_simulation_iteration_1":
    controller_args_field.setMFString(0, "supervisor_reset_simulation_iteration_2")
    ts_assert_int_equal(iteration, 1, "Robot custom data should start with '1' at second iteration.")
    values = [float(v) for v in description_field.getSFString().split()]
    for i in range(SOLID_BOX_NUMBER):
        expected_x, expected_y, expected_z = values[3 * i:3 * i + 3]
        position = solid_box[i].getPosition()
        ts_assert_vec3_in_delta(position[0], position[1], position[2], expected_x, expected_y, expected_z, 0.000001,
                                "Position of solid box %d is not equal to the one of the first run.", i)
    if os.path.exists(file_path):
        os.remove(file_path)

ts_send_success()
