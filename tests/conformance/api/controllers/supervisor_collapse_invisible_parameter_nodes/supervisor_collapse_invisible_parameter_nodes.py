"""Port of Webots' tests/api/controllers/supervisor_collapse_invisible_parameter_nodes.

Robots built inside PROTOs (with some or none of their nodes exposed as parameters) must move
exactly as the same robot written out in the world.
"""

from controller import Supervisor
from ts_assertion import ts_assert_boolean_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)
receiver = robot.getDevice("receiver")
receiver.enable(TIME_STEP)
robot.step(TIME_STEP)

received: dict[str, list[float]] = {}
while robot.getTime() < 10.0:
    robot.step(TIME_STEP)
    if receiver.getQueueLength() > 0:
        words = bytes(receiver.getBytes()).split(b"\0")[0].decode().split()
        position, name = [float(w) for w in words[:5]], words[5]
        if name in ("non_proto", "partially_visible", "invisible") and name not in received:
            received[name] = position
        else:
            ts_assert_boolean_equal(False, "Message unknown.")
        receiver.nextPacket()
    if len(received) == 3:
        for i in range(5):
            ts_assert_double_in_delta(received["partially_visible"][i], received["non_proto"][i], 1e-8,
                                      "Partially visible nested proto not behaving like non-proto version.")
            ts_assert_double_in_delta(received["invisible"][i], received["non_proto"][i], 1e-8,
                                      "Invisible nested proto not behaving like non-proto version.")
        received.clear()

ts_send_success()
