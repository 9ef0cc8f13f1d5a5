"""Port of Webots' tests/api/controllers/emitter_receiver_serial_aperture: serial ignores the aperture cones.

Four cases: both ends inside each other's cone, the receiver outside the emitter's cone, the
emitter outside the receiver's cone, and both outside; a serial packet arrives every time.
"""

import sys

from controller import Robot
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32
MSG = b"Hello!\0"

robot = Robot()
ts_setup(robot, sys.argv[1])
name = robot.getName()
robot_id = -1
if name == "robot0":
    comm = robot.getDevice("emitter0")  # aperture pi/2
    comm.setChannel(2)
    robot_id = 0
elif name == "robot1":
    comm = robot.getDevice("emitter1")  # aperture -1
    comm.setChannel(1)
    robot_id = 1
elif name == "robot2":
    comm = robot.getDevice("receiver2")  # aperture 0.5
    comm.setChannel(1)
    comm.enable(TIME_STEP)
    robot_id = 2
elif name == "robot3":
    comm = robot.getDevice("receiver3")  # aperture 0.5
    comm.setChannel(2)
    comm.enable(TIME_STEP)
    robot_id = 3


def two_steps() -> None:
    robot.step(TIME_STEP)
    robot.step(TIME_STEP)


def expect_one(message: str) -> None:
    two_steps()
    q = comm.getQueueLength()
    ts_assert_int_equal(q, 1, 'Receiver "receiver%d" should receive %d not %d packets ' + message, robot_id, 1, q)
    comm.nextPacket()


# Case 1: inside both cones.
robot.step(TIME_STEP)
if robot_id == 1:
    comm.send(MSG)
if robot_id == 2:
    expect_one("when emitter and receiver are inside the respective emission/reception cones")
else:
    two_steps()

# Case 2: the emitter's aperture too small.
robot.step(TIME_STEP)
if robot_id == 0:
    comm.send(MSG)
if robot_id == 3:
    expect_one("when receiver is not located in emitter emission cone")
else:
    two_steps()

# Case 3: the receiver's aperture too small.
robot.step(TIME_STEP)
if robot_id == 1:
    comm.setChannel(2)
    comm.send(MSG)
if robot_id == 3:
    expect_one("when emitter is not located in receiver reception cone")
else:
    two_steps()

# Case 4: both apertures too small.
robot.step(TIME_STEP)
if robot_id == 0:
    comm.setChannel(1)
    comm.send(MSG)
if robot_id == 2:
    expect_one("when emitter is not located in receiver reception cone")
else:
    two_steps()

# Webots' test steps robot_id more steps here (0 for robot0) so that the results do not mix on stdout.
if robot_id > 0:
    robot.step(robot_id * TIME_STEP)
ts_send_success()
