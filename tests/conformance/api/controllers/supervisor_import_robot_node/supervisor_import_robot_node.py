"""Port of Webots' tests/api/controllers/supervisor_import_robot_node: a Robot imported from a string (MyBot.txt,
Webots' test data) lands at its translation and its controller starts and drives it forwards; a Camera imported into
the supervisor's own children is then a device it can enable and read.

MyBot.txt is Webots' file tests/api/controllers/supervisor_import_robot_node/MyBot.txt (Copyright 1996-2024
Cyberbotics Ltd., Apache License 2.0), kept byte for byte: the test checks its size.
"""

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_boolean_not_equal,
    ts_assert_doubles_in_delta,
    ts_assert_int_equal,
    ts_assert_pointer_not_null,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 64

robot = Supervisor()
ts_setup(robot)

initial_position = [0.0, 0.0, -0.104]

root = robot.getRoot()
root_children = root.getField("children")

robot.step(2 * TIME_STEP)

with open("MyBot.txt", "rb") as fd:
    contents = fd.read(4096)
n = len(contents)
ts_assert_int_equal(n, 3262, "The MyBot.txt file could be fully read: %d/3262 bytes read", n)
root_children.importMFNodeFromString(-1, contents.decode())

my_bot = robot.getFromDef("MY_BOT")
ts_assert_boolean_equal(my_bot is not None, "The robot node has not been imported correctly")

position = my_bot.getPosition()
ts_assert_doubles_in_delta(3, position, initial_position, 0.0001, "The robot has not been imported at the correct position")

robot.step(4 * TIME_STEP)

previous_z = position[2]
position = my_bot.getPosition()
ts_assert_boolean_equal(position[2] < (previous_z - 0.02), "The controller of the imported robot has not started correctly")

self_node = robot.getSelf()
self_children = self_node.getField("children")
self_children.importMFNodeFromString(0, 'Camera { name "imported camera"}')

camera = robot.getDevice("imported camera")
ts_assert_pointer_not_null(camera, "Camera imported during controller execution not found.")
camera.enable(TIME_STEP)

robot.step(TIME_STEP)

image = camera.getImage()
ts_assert_boolean_not_equal(image is None, "Camera image is NULL.")

ts_send_success()
