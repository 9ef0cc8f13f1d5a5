"""Port of Webots' tests/api/controllers/emitter_receiver_infra-red: infra-red emitters and receivers.

Disabled and enabled receivers, channels and broadcast, several emitters and receivers, sending
and receiving on one robot, buffer sizes and emitter range, a wall between emitter and receiver, in
nine cases run in lockstep by the four robots of the world.
"""

import struct
import sys

from controller import Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_assert_doubles_in_delta,
    ts_assert_int_equal,
    ts_assert_string_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
CHANNEL1, CHANNEL2, CHANNEL3, CHANNEL_ALL = 1, 7, 24, -1
MSG1 = "Hello!"
MSG2 = "Do you received the message?"
MSG3 = ("A very long message that should be larger than the buffer size and cause a buffer overflow if not "
        "handled properly.")
DOUBLES4 = [9.67, 8.75, 0.00, 1.61]
INTS5 = [2, 33]


def c_string(text: str) -> bytes:
    """A C string as the test sends it: its characters and the terminating NUL."""
    return text.encode() + b"\0"


def data(receiver) -> str:
    """The head packet read as a C string (up to its first NUL)."""
    return bytes(receiver.getBytes()).split(b"\0")[0].decode()


def steps(robot: Robot, n: int) -> None:
    for _ in range(n):
        robot.step(TIME_STEP)


robot = Robot()
ts_setup(robot, sys.argv[1])
name = robot.getName()
receiver0 = None
robot_id = -1
if name == "robot0":
    comm = robot.getDevice("emitter0")
    receiver0 = robot.getDevice("receiver0")
    comm.setChannel(CHANNEL1)
    robot_id = 0
elif name == "robot1":
    comm = robot.getDevice("emitter1")
    comm.setChannel(CHANNEL2)
    robot_id = 1
elif name == "robot2":
    comm = robot.getDevice("receiver2")
    comm.setChannel(CHANNEL1)
    robot_id = 2
elif name == "robot3":
    comm = robot.getDevice("receiver3")
    comm.setChannel(CHANNEL3)
    robot_id = 3

robot.step(TIME_STEP)
# Case 1: receivers not enabled.
if robot_id in (0, 1):
    comm.send(c_string(MSG1))
    steps(robot, 2)
elif robot_id in (2, 3):
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 1 - Receiver "receiver%d" should not receive %d packets not %d packets when disabled',
                        robot_id, 0, q)
    comm.enable(TIME_STEP)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 1 - Receiver "receiver%d" should not receive %d packets not %d packets before the step '
                        'after it is enabled', robot_id, 0, q)

robot.step(TIME_STEP)
# Case 2: receivers enabled; e0 -> r2.
if robot_id == 0:
    comm.send(c_string(MSG1))
    steps(robot, 2)
elif robot_id == 1:
    comm.send(c_string(MSG2))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 2 - Receiver "receiver%d" should receive 1 packet not %d packets', robot_id - 2, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG1, 'Case 2 - Receiver "receiver%d" should receive packet contaning "%s" not "%s"',
                           robot_id, MSG1, buffer)
    comm.nextPacket()
elif robot_id == 3:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 2 - Receiver "receiver%d" should receive 0 packet not %d packets', robot_id - 2, q)
    comm.setChannel(CHANNEL2)

robot.step(TIME_STEP)
# Case 3: several messages from one emitter, data sizes.
if robot_id == 0:
    comm.send(c_string(MSG1))
    comm.send(struct.pack("2i", *INTS5))
    steps(robot, 2)
elif robot_id == 1:
    comm.send(c_string(MSG3))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 2, 'Case 3 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 2, q)
    buffer, size = data(comm), comm.getDataSize()
    ts_assert_boolean_equal(size == len(MSG1) + 1, 'Case 3 - Receiver "receiver%d" should receive a first packet with size '
                            '%d not %d', robot_id, len(MSG1) + 1, size)
    ts_assert_string_equal(buffer, MSG1, 'Case 3 - Receiver "receiver%d" should receive a first packet contaning "%s" not '
                           '"%s"', robot_id, MSG1, buffer)
    comm.nextPacket()
    size = comm.getDataSize()
    ints = struct.unpack("2i", bytes(comm.getBytes())[:8])
    ts_assert_boolean_equal(size == 8, 'Case 3 - Receiver "receiver%d" should receive a second packet with size %d not %d',
                            robot_id, 8, size)
    ts_assert_boolean_equal(list(ints) == INTS5, 'Case 3 - Receiver "receiver%d" should receive a second packet contaning '
                            '[%d, %d] not [%d, %d]', robot_id, *INTS5, *ints)
    comm.nextPacket()
elif robot_id == 3:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 3 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 1, q)
    buffer, size = data(comm), comm.getDataSize()
    ts_assert_boolean_equal(size == len(MSG3) + 1, 'Case 3 - Receiver "receiver%d" should receive packet with size %d not %d',
                            robot_id, len(MSG3) + 1, size)
    ts_assert_string_equal(buffer, MSG3, 'Case 3 - Receiver "receiver%d" should receive packet contaning "%s" not "%s"',
                           robot_id, MSG3, buffer)
    comm.nextPacket()
    comm.setChannel(CHANNEL1)

robot.step(TIME_STEP)
# Case 4: several messages to several receivers; get/set channel.
if robot_id == 0:
    comm.send(c_string(MSG1))
    comm.send(struct.pack("4d", *DOUBLES4))
    channel = comm.getChannel()
    ts_assert_boolean_equal(channel == CHANNEL1, 'Case 4 - Emitter "emiter%d" should be set to channel %d not %d', robot_id,
                            CHANNEL1, channel)
    comm.setChannel(CHANNEL3)
    channel = comm.getChannel()
    ts_assert_boolean_equal(channel == CHANNEL3, 'Case 4 - Emitter "emitter%d" should be set to channel %d not %d', robot_id,
                            CHANNEL3, channel)
    steps(robot, 2)
elif robot_id == 1:
    comm.send(c_string(MSG2))
    comm.setChannel(CHANNEL3)
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 2, 'Case 4 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 2, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG1, 'Case 4 - Receiver "receiver%d" should receive a first packet contaning "%s" not '
                           '"%s"', robot_id, MSG1, buffer)
    comm.nextPacket()
    doubles = list(struct.unpack("4d", bytes(comm.getBytes())[:32]))
    ts_assert_doubles_in_delta(4, doubles, DOUBLES4, 0.001, 'Case 4 - Receiver "receiver%d" should receive a second packet '
                               'contaning [%f, %f, %f, %f] not [%f, %f, %f, %f]', robot_id, *DOUBLES4, *doubles)
    comm.nextPacket()
    channel = comm.getChannel()
    ts_assert_boolean_equal(channel == CHANNEL1, 'Case 4 - Receiver "receiver%d" should be set to channel %d not %d',
                            robot_id, CHANNEL1, channel)
elif robot_id == 3:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 4 - Receiver "receiver%d" should receive %d packets not %d packets when a wall is placed '
                        'between the emitter and the receiver', robot_id, 0, q)
    channel = comm.getChannel()
    ts_assert_boolean_equal(channel == CHANNEL1, 'Case 4 - Receiver "receiver%d" should be set to channel %d not %d before '
                            'changing it', robot_id, CHANNEL1, channel)
    comm.setChannel(CHANNEL3)
    channel = comm.getChannel()
    ts_assert_boolean_equal(channel == CHANNEL3, 'Case 4 - Receiver "receiver%d" should be set to channel %d not %d after '
                            'changing it', robot_id, CHANNEL3, channel)

robot.step(TIME_STEP)
# Case 5: several emitters to one receiver; the third packet overflows receiver3's 120-byte buffer.
if robot_id == 0:
    comm.send(c_string(MSG1))
    steps(robot, 3)
elif robot_id == 1:
    robot.step(TIME_STEP)
    comm.send(c_string(MSG2))
    comm.send(c_string(MSG3))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 3)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 5 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 0, q)
elif robot_id == 3:
    steps(robot, 3)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 5 - Receiver "receiver%d" should receive %d packets not %d packets when a wall is placed '
                        'between the emitter and the receiver', robot_id, 1, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG2, 'Case 5 - Receiver "receiver%d" should receive a second packet contaning "%s" not '
                           '"%s"', robot_id, MSG2, buffer)
    comm.nextPacket()

robot.step(TIME_STEP)
# Case 6: broadcast, signal strength and emitter direction.
if robot_id == 0:
    comm.setChannel(CHANNEL_ALL)
    comm.send(c_string(MSG1))
    steps(robot, 3)
elif robot_id == 1:
    robot.step(TIME_STEP)
    comm.send(c_string(MSG2))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 3)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 6 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 1, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG1, 'Case 6 - Receiver "receiver%d" should receive packet contaning "%s" not "%s"',
                           robot_id, MSG1, buffer)
    direction = list(comm.getEmitterDirection())
    expected = [-0.7071, -0.7071, 0.0]
    ts_assert_doubles_in_delta(3, direction, expected, 0.0001, 'Case 6 - Receiver "receiver%d" should receive packet from '
                               'the emitter in direction [%f, %f, %f] not [%f, %f, %f]', robot_id, *expected, *direction)
    strength = comm.getSignalStrength()
    ts_assert_double_in_delta(strength, 1.3889, 0.0001, 'Case 6 - Receiver "receiver%d" should receive packet with signal '
                              'strength %f not %f', robot_id, 1.3889, strength)
    comm.nextPacket()
    comm.setChannel(CHANNEL_ALL)
elif robot_id == 3:
    steps(robot, 3)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 6 - Receiver "receiver%d" should receive %d packets not %d packets  when a wall is placed '
                        'between the emitter and the receiver', robot_id, 1, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG2, 'Case 6 - Receiver "receiver%d" should receive a second packet contaning "%s" not '
                           '"%s"', robot_id, MSG2, buffer)
    direction = list(comm.getEmitterDirection())
    expected = [0.7071, -0.7071, 0.0]
    ts_assert_doubles_in_delta(3, direction, expected, 0.0001, 'Case 6 - Receiver "receiver%d" should receive a second packet '
                               'from the emitter in direction [%f, %f, %f] not [%f, %f, %f]', robot_id, *expected, *direction)
    strength = comm.getSignalStrength()
    ts_assert_double_in_delta(strength, 1.3889, 0.0001, 'Case 6 - Receiver "receiver%d" should receive packet with signal '
                              'strength %f not %f', robot_id, 1.3889, strength)
    comm.nextPacket()
    comm.disable()

robot.step(TIME_STEP)
# Case 7: a disabled receiver; no delivery between devices of one robot.
if robot_id == 0:
    receiver0.enable(TIME_STEP)
    comm.send(c_string(MSG1))
    steps(robot, 3)
    q = receiver0.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 7 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 1, q)
    buffer = data(receiver0)
    ts_assert_string_equal(buffer, MSG2, 'Case 7 - Receiver "receiver%d" should receive packet contaning "%s" not "%s"',
                           robot_id, MSG2, buffer)
    receiver0.nextPacket()
    period = receiver0.getSamplingPeriod()
    ts_assert_int_equal(period, TIME_STEP, 'Case 7 - Receiver "receiver%d" should have a sampling period %d not %d when '
                        'enabled', robot_id, TIME_STEP, period)
    receiver0.disable()
elif robot_id == 1:
    robot.step(TIME_STEP)
    comm.send(c_string(MSG2))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 3)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 2, 'Case 7 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 2, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG1, 'Case 7 - Receiver "receiver%d" should receive a first packet contaning "%s" not '
                           '"%s"', robot_id, MSG1, buffer)
    comm.nextPacket()
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG2, 'Case 7 - Receiver "receiver%d" should receive a second packet contaning "%s" not '
                           '"%s"', robot_id, MSG2, buffer)
    comm.nextPacket()
    period = comm.getSamplingPeriod()
    ts_assert_int_equal(period, TIME_STEP, 'Case 7 - Receiver "receiver%d" should have a sampling period %d not %d when '
                        'enabled', TIME_STEP, robot_id, period)
elif robot_id == 3:
    steps(robot, 3)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 7 - Receiver "receiver%d" should receive %d packet not %d packets when disabled',
                        robot_id, 0, q)
    period = comm.getSamplingPeriod()
    ts_assert_int_equal(period, 0, 'Case 7 - Receiver "receiver%d" should have a sampling period %d not %d when disabled',
                        robot_id, 0, period)

robot.step(TIME_STEP)
# Case 8: emitter buffer sizes.
if robot_id == 0:
    size = comm.getBufferSize()
    ts_assert_int_equal(size, 100, 'Case 8 - Emitter "emitter%d" should have a buffer size %d not %d', robot_id, 100, size)
    steps(robot, 2)
    receiver0.enable(TIME_STEP)
elif robot_id == 1:
    size = comm.getBufferSize()
    ts_assert_int_equal(size, -1, 'Case 8 - Emitter "emitter%d" should have a buffer size %d not %d', robot_id, 4096, size)
    comm.send(c_string(MSG2))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 8 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 1, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG2, 'Case 8 - Receiver "receiver%d" should receive a first packet contaning "%s" not '
                           '"%s"', robot_id, MSG2, buffer)
    comm.nextPacket()
elif robot_id == 3:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 8 - Receiver "receiver%d" should receive %d packet not %d packets when disabled',
                        robot_id, 0, q)
    comm.enable(TIME_STEP)

robot.step(TIME_STEP)
# Case 9: emitter range (maxRange caps setRange).
if robot_id == 0:
    value = comm.getRange()
    ts_assert_double_in_delta(value, -1, 0.001, 'Case 9 - Emitter "emitter%d" should have range %d not %d', robot_id, -1,
                              value)
    steps(robot, 2)
    q = receiver0.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 9 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 1, q)
    buffer = data(receiver0)
    ts_assert_string_equal(buffer, MSG2, 'Case 9 - Receiver "receiver%d" should receive a first packet contaning "%s" not '
                           '"%s"', robot_id, MSG2, buffer)
    receiver0.nextPacket()
elif robot_id == 1:
    value = comm.getRange()
    ts_assert_double_in_delta(value, 1.3, 0.001, 'Case 9 - Emitter "emitter%d" should have range %f not %f before changing '
                              'it', robot_id, 1.3, value)
    comm.setRange(2.5)
    value = comm.getRange()
    ts_assert_double_in_delta(value, 2.0, 0.001, 'Case 9 - Emitter "emitter%d" should have range %f not %f if setting a value '
                              'greater than max range %f', robot_id, 2.0, value, 2.0)
    comm.setRange(0.7)
    value = comm.getRange()
    ts_assert_double_in_delta(value, 0.7, 0.001, 'Case 9 - Emitter "emitter%d" should have range %f not %f after changing it',
                              robot_id, 0.7, value)
    comm.send(c_string(MSG2))
    steps(robot, 2)
elif robot_id == 2:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Case 9 - Receiver "receiver%d" should receive %d packets not %d packets', robot_id, 1, q)
    buffer = data(comm)
    ts_assert_string_equal(buffer, MSG2, 'Case 9 - Receiver "receiver%d" should receive a first packet contaning "%s" not '
                           '"%s"', robot_id, MSG2, buffer)
    comm.nextPacket()
elif robot_id == 3:
    steps(robot, 2)
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 0, 'Case 9 - Receiver "receiver%d" should receive %d packet not %d packets when distance larger '
                        'that valid range', robot_id, 0, q)

# Webots' test steps robot_id more steps here (0 for robot0) so that the four results do not mix on stdout.
if robot_id > 0:
    robot.step(robot_id * TIME_STEP)
ts_send_success()
