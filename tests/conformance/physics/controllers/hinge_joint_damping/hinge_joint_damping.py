"""Port of Webots' tests/physics/controllers/hinge_joint_damping: four passive hinge-joint robots with different
damping constants report the exact time their bar hits their touch sensor (r1 0.48 s, r2 0.672 s, r3 and r4
1.024 s)."""

from controller import Robot
from ts_assertion import ts_assert_boolean_equal, ts_assert_int_equal, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

receiver = robot.getDevice("receiver")
receiver.enable(time_step)

expected = {"r1": 0.48, "r2": 0.672, "r3": 1.024, "r4": 1.024}
n_success = 0

while robot.step(time_step) != -1:
    if robot.getTime() > 2.0:
        ts_assert_boolean_equal(0, "Time-out reached before collisions are detected")

    if receiver.getQueueLength() > 0:
        text = receiver.getBytes().split(b"\0", 1)[0].decode()
        parts = text.split(" : collision at ")
        ts_assert_int_equal(len(parts), 2, "fscanf failed")
        name = parts[0].split()[0] if parts[0].split() else ""
        time = float(parts[1])

        if name in expected and time == expected[name]:
            n_success += 1
        else:
            ts_assert_boolean_equal(0, 'Received unexpected data (name = "%s", time = %lf)', name, time)

        if n_success == 4:
            break

        receiver.nextPacket()

ts_send_success()
