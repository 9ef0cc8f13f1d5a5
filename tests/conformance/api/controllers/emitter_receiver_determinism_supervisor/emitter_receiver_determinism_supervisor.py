"""Port of Webots' tests/api/controllers/emitter_receiver_determinism_supervisor.

Packets of two emitters arrive in the same order every step (A then B), however the two
controllers' processes are scheduled.
"""

from controller import Robot
from ts_assertion import ts_assert_int_not_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)
receiver = robot.getDevice("receiver")
receiver.enable(TIME_STEP)
previous = "B"
for _ in range(100):
    while receiver.getQueueLength() > 0:
        data = bytes(receiver.getBytes())[:1].decode()
        ts_assert_int_not_equal(ord(data), ord(previous), "Received same message twice: '%s'.", previous)
        previous = data
        receiver.nextPacket()
    robot.step(TIME_STEP)
ts_send_success()
