"""Port of Webots' tests/api/controllers/emitter_receiver_enable_disable.

Emitters and receivers of mixed types: only devices of the same type talk, receivers hear nothing
while disabled, and channels filter.
"""

import sys

from controller import Robot
from ts_assertion import ts_assert_int_equal, ts_assert_string_equal, ts_send_success, ts_setup

TIME_STEP = 32
MSG0, MSG1, MSG2, MSG3 = "Hello", "Radio", "Serial", "Infra-Red"


def c_string(text: str) -> bytes:
    return text.encode() + b"\0"


def data(receiver) -> str:
    return bytes(receiver.getBytes()).split(b"\0")[0].decode()


robot = Robot()
ts_setup(robot, sys.argv[1])
name = robot.getName()
emitter = receiver = None
robot_id = -1
if name == "robot0":
    emitter, receiver, robot_id = robot.getDevice("emitter0"), robot.getDevice("receiver0"), 0  # serial 2, radio -1
elif name == "robot1":
    emitter, robot_id = robot.getDevice("emitter1"), 1  # infra-red, channel -1
elif name == "robot2":
    emitter, robot_id = robot.getDevice("emitter2"), 2  # radio, channel -1
elif name == "robot3":
    receiver, robot_id = robot.getDevice("receiver3"), 3  # serial, channel 2
elif name == "robot4":
    receiver, robot_id = robot.getDevice("receiver4"), 4  # infra-red, channel 2

# Test 1: receivers disabled.
robot.step(TIME_STEP)
if robot_id in (0, 1, 2):
    emitter.send(c_string(MSG0))
    robot.step(TIME_STEP)
    if robot_id == 0:
        q = receiver.getQueueLength()
        ts_assert_int_equal(q, 0, "Radio receiver should receive %d not %d packets when disabled", 0, q)
elif robot_id in (3, 4):
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    kind = "Serial" if robot_id == 3 else "Infra-red"
    ts_assert_int_equal(q, 0, kind + " receiver should receive %d not %d packets when disabled", 0, q)

# Test 2: receivers enabled.
robot.step(TIME_STEP)
if robot_id == 0:
    receiver.enable(TIME_STEP)
    emitter.send(c_string(MSG2))
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 1, "Radio receiver should receive %d not %d packets when enabled", 1, q)
    buffer = data(receiver)
    ts_assert_string_equal(buffer, MSG1, 'Radio receiver should receive a packet containing "%s" not "%s"', MSG1, buffer)
    receiver.nextPacket()
    robot.step(TIME_STEP)
elif robot_id == 1:
    emitter.send(c_string(MSG3))
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
elif robot_id == 2:
    emitter.send(c_string(MSG1))
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
elif robot_id == 3:
    receiver.enable(2 * TIME_STEP)
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 0, "Serial receiver should receive %d not %d packets one step after being enabled", 0, q)
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 1, "Serial receiver should receive %d not %d packets two steps after being enabled", 1, q)
    buffer = data(receiver)
    ts_assert_string_equal(buffer, MSG2, 'Serial receiver should receive a packet containing "%s" not "%s"', MSG2, buffer)
    receiver.nextPacket()
elif robot_id == 4:
    receiver.enable(TIME_STEP)
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 1, "Infra-red receiver should receive %d not %d packets when enabled", 1, q)
    buffer = data(receiver)
    ts_assert_string_equal(buffer, MSG3, 'Infra-red receiver should receive a packet containing "%s" not "%s"', MSG3,
                           buffer)
    receiver.nextPacket()
    robot.step(TIME_STEP)

# Test 3: radio receiver on channel 0, serial receiver on 10, infra-red receiver disabled.
robot.step(TIME_STEP)
if robot_id == 0:
    receiver.setChannel(0)
    emitter.send(c_string(MSG2))
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 1, "Radio receiver should receive %d not %d packets when channel set to 0", 1, q)
    buffer = data(receiver)
    ts_assert_string_equal(buffer, MSG1, 'Radio receiver should receive a packet containing "%s" not "%s" when channel '
                           'set to 0', MSG1, buffer)
    receiver.nextPacket()
    robot.step(TIME_STEP)
elif robot_id == 1:
    emitter.send(c_string(MSG3))
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
elif robot_id == 2:
    emitter.send(c_string(MSG1))
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
elif robot_id == 3:
    receiver.setChannel(10)
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 0, "Serial receiver should receive %d not %d packets when channel set to 10", 0, q)
    receiver.setChannel(2)
elif robot_id == 4:
    receiver.disable()
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 0, "Infra-red receiver should receive %d not %d packets when re-disabled", 0, q)
    robot.step(TIME_STEP)

# Test 4: radio receiver on channel 0, serial receiver on 2.
robot.step(TIME_STEP)
if robot_id == 0:
    emitter.send(c_string(MSG2))
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 1, "Radio receiver should receive %d not %d packets when channel set to 0", 1, q)
    buffer = data(receiver)
    ts_assert_string_equal(buffer, MSG1, 'Radio receiver should receive a packet containing "%s" not "%s" when channel '
                           'set to 0', MSG1, buffer)
    receiver.nextPacket()
    robot.step(TIME_STEP)
elif robot_id in (1, 4):
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
elif robot_id == 2:
    emitter.setChannel(0)
    emitter.send(c_string(MSG1))
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)
elif robot_id == 3:
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 0, "Serial receiver should receive %d not %d packets during same step when the message is sent",
                        0, q)
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 0, "Serial receiver should receive %d not %d packets one step after the message is sent", 0, q)
    robot.step(TIME_STEP)
    q = receiver.getQueueLength()
    ts_assert_int_equal(q, 1, "Serial receiver should receive %d not %d packets two steps after the message is sent", 1, q)
    receiver.nextPacket()

# Webots' test steps robot_id more steps here (0 for robot0) so that the results do not mix on stdout.
if robot_id > 0:
    robot.step(robot_id * TIME_STEP)
ts_send_success()
