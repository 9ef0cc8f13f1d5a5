"""Port of Webots' tests/api/controllers/emitter_set_channel: setChannel applies to the very next send()."""

import sys

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_string_equal, ts_send_success, ts_setup

TIME_STEP = 64
MESSAGE1 = "Hello1"
MESSAGE2 = "Hello2"


def text(receiver) -> str:
    """The packet as C reads it: up to its first NUL."""
    return bytes(receiver.getBytes()).split(b"\0")[0].decode()


def receiver1_controller(robot: Robot) -> None:
    receiver = robot.getDevice("receiver1")
    receiver.enable(TIME_STEP)
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    # Step 2: one message.
    length = receiver.getQueueLength()
    ts_assert_double_in_delta(length, 1, 0.5, "Receiver1 received %d message(s) instead of 1 at step 2.", length)
    msg1 = text(receiver)
    ts_assert_string_equal(msg1, MESSAGE1, "Receiver1 received the wrong message at step 2: '%s' instead of '%s'.",
                           msg1, MESSAGE1)
    receiver.nextPacket()
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    # Step 4: one message.
    length = receiver.getQueueLength()
    ts_assert_double_in_delta(length, 1, 0.5, "Receiver1 received %d message(s) instead of 1 at step 4.", length)
    msg2 = text(receiver)
    ts_assert_string_equal(msg2, MESSAGE1, "Receiver1 received the wrong message at step 4: '%s' instead of '%s'.",
                           msg2, MESSAGE1)
    receiver.nextPacket()


def receiver2_controller(robot: Robot) -> None:
    receiver = robot.getDevice("receiver2")
    receiver.enable(TIME_STEP)
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    # Step 2: nothing.
    length = receiver.getQueueLength()
    ts_assert_double_in_delta(length, 0, 0.5, "Receiver2 received %d message(s) instead of 0 at step 2.", length)
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    # Step 4: one message.
    length = receiver.getQueueLength()
    ts_assert_double_in_delta(length, 1, 0.5, "Receiver2 received %d message(s) instead of 1 at step 4.", length)
    msg = text(receiver)
    ts_assert_string_equal(msg, MESSAGE2, "Receiver2 received the wrong message at step 4: '%s' instead of '%s'.",
                           msg, MESSAGE2)
    receiver.nextPacket()


def emitter_controller(robot: Robot) -> None:
    emitter = robot.getDevice("emitter")
    robot.step(TIME_STEP)
    # Step 1: on channel 1.
    emitter.setChannel(1)
    emitter.send((MESSAGE1 + "\0").encode())
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    # Step 3: on channel 2, then on channel 1, in the same step.
    emitter.setChannel(2)
    emitter.send((MESSAGE2 + "\0").encode())
    emitter.setChannel(1)
    emitter.send((MESSAGE1 + "\0").encode())
    robot.step(TIME_STEP)


robot = Robot()
ts_setup(robot, sys.argv[1])
name = robot.getName()
if name == "robot_emitter":
    emitter_controller(robot)
elif name == "robot_receiver1":
    receiver1_controller(robot)
    robot.step(TIME_STEP)
elif name == "robot_receiver2":
    receiver2_controller(robot)
    robot.step(2 * TIME_STEP)
ts_send_success()
