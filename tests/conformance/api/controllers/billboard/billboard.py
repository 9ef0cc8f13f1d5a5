"""Port of Webots' tests/api/controllers/billboard: a Billboard's children look the same from any viewpoint."""

import math
import os
import time

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_boolean_not_equal,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

NAMES = ["image0.png", "image1.png", "image2.png"]

robot = Supervisor()
ts_setup(robot)

node = robot.getFromDef("VIEWPOINT")
ts_assert_pointer_not_null(node, 'wb_supervisor_node_get_from_def("VIEWPOINT") failed')
position = node.getField("position")
ts_assert_pointer_not_null(node, 'wb_supervisor_node_get_field("position") failed')
orientation = node.getField("orientation")
ts_assert_pointer_not_null(node, 'wb_supervisor_node_get_field("orientation") failed')

time_step = int(robot.getBasicTimeStep())
for name in NAMES:
    if os.path.exists(name):
        os.remove(name)
for name in NAMES:
    ts_assert_boolean_not_equal(os.path.exists(name), "Impossible to remove a PNG file")

robot.step(time_step)
robot.exportImage("image0.png", 100)
position.setSFVec3f([5, -3, 0.4])
robot.step(time_step)  # so that the node's absolute position is updated
robot.exportImage("image1.png", 100)
orientation.setSFRotation([0.5, 0.5, 1.0, math.pi / 3.0])
robot.step(time_step)
robot.exportImage("image2.png", 100)
robot.step(time_step)

start = time.time()
while time.time() - start < 5:
    if all(os.path.exists(name) for name in NAMES):
        break
    time.sleep(0.1)
    robot.step(time_step)

for name in NAMES:
    ts_assert_boolean_equal(os.path.exists(name), "wb_supervisor_export_image() failed to create the %s file." % name)

size = os.path.getsize("image0.png")
ts_assert_int_equal(os.path.getsize("image1.png") - size, 0, "File sizes differ between image0 and image1")
ts_assert_int_equal(os.path.getsize("image2.png") - size, 0, "File sizes differ between image0 and image2")

buffers = []
for i, name in enumerate(NAMES):
    with open(name, "rb") as file:
        data = file.read(size)
    ts_assert_int_equal(len(data), size, "Cannot read image%d file.", i)
    buffers.append(data)

difference = 0
for i in range(size):
    if buffers[0][i] != buffers[1][i] or buffers[0][i] != buffers[2][i]:
        difference = i
        break
ts_assert_int_equal(difference, 0, "Files differ at index %d", difference)

for name in NAMES:
    os.unlink(name)

ts_send_success()
