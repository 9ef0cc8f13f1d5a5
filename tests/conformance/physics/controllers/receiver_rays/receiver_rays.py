"""Port of Webots' tests/physics/controllers/receiver_rays: radio and infra-red receivers get the right number of
packets from a fixed and a falling emitter, with the right emitter directions, step after step, whether the receivers
stand still ("static" robot) or are driven by wheels during the physics step ("dynamic" robot)."""

import sys

from controller import Robot
from ts_assertion import ts_assert_int_equal, ts_assert_vec3_in_delta, ts_send_success, ts_setup


def check_queue_length(receiver, sensor_name, expected, check_number):
    count = receiver.getQueueLength()
    ts_assert_int_equal(count, expected, "Wrong number of messages received from %s emitter at check %d: "
                        "expected %d, received %d.", sensor_name, check_number, expected, count)


def check_last_emitter_direction(receiver, sensor_name, expected_x, expected_y, expected_z, check_number):
    while receiver.getQueueLength() > 1:
        receiver.nextPacket()

    if receiver.getQueueLength() == 1:
        emitter_dir = receiver.getEmitterDirection()
        ts_assert_vec3_in_delta(emitter_dir[0], emitter_dir[1], emitter_dir[2], expected_x, expected_y, expected_z,
                                0.01, "Wrong %s emitter direction for the message received at check %d.", sensor_name,
                                check_number)
        receiver.nextPacket()


robot = Robot()
ts_setup(robot, sys.argv[1])

n_check = 1
time_step = int(robot.getBasicTimeStep())
dynamic = robot.getCustomData() != "static"

# radio receivers
rrs = robot.getDevice("receiver radio static")
rrd = robot.getDevice("receiver radio dynamic")
# infra-red receivers (ray casting)
ris = robot.getDevice("receiver infra-red static")
rid = robot.getDevice("receiver infra-red dynamic")
rrs.enable(time_step)
rrd.enable(time_step)
ris.enable(time_step)
rid.enable(time_step)

robot.step(3 * time_step)

if dynamic:
    left_motor = robot.getDevice("left motor")
    right_motor = robot.getDevice("right motor")
    left_motor.setPosition(float("inf"))
    right_motor.setPosition(float("inf"))
    left_motor.setVelocity(20)
    right_motor.setVelocity(20)

# static emitter
check_queue_length(rrs, "static radio", 3, n_check)
if dynamic:
    check_last_emitter_direction(rrs, "static radio", 0.99, 0.00, 0.06, n_check)
else:
    check_last_emitter_direction(rrs, "static radio", 1.00, 0.00, 0.00, n_check)

# dynamic emitter: its packets are dropped unchecked
rrd.nextPacket()
rrd.nextPacket()

# static emitter
check_queue_length(ris, "static infra-red", 3, n_check)
if dynamic:
    check_last_emitter_direction(ris, "static infra-red", 0.99, 0.00, 0.06, n_check)
else:
    check_last_emitter_direction(ris, "static infra-red", 1.00, 0.00, 0.00, n_check)

# dynamic emitter
check_queue_length(rid, "dynamic infra-red", 0, n_check)

robot.step(time_step)
n_check += 1

# radio, static emitter
check_queue_length(rrs, "static radio", 1, n_check)
if dynamic:
    check_last_emitter_direction(rrs, "static radio", 0.98, -0.18, 0.02, n_check)
else:
    check_last_emitter_direction(rrs, "static radio", 1.00, 0.00, 0.00, n_check)

# radio, dynamic emitter
check_queue_length(rrd, "dynamic radio", 1, n_check)
if dynamic:
    check_last_emitter_direction(rrd, "dynamic radio", 0.98, 0.12, -0.09, n_check)
else:
    check_last_emitter_direction(rrd, "dynamic radio", 0.99, 0.00, -0.13, n_check)

# infra-red, static emitter
check_queue_length(ris, "static infra-red", 1, n_check)
if dynamic:
    check_last_emitter_direction(ris, "static infra-red", 0.98, -0.18, 0.02, n_check)
else:
    check_last_emitter_direction(ris, "static infra-red", 1.00, 0.00, 0.00, n_check)

# infra-red, dynamic emitter
check_queue_length(rid, "dynamic infra-red", 1, n_check)
if dynamic:
    check_last_emitter_direction(rid, "dynamic infra-red", 0.98, 0.12, -0.09, n_check)
else:
    check_last_emitter_direction(rid, "dynamic infra-red", 0.99, 0.00, -0.13, n_check)

robot.step(time_step)
n_check += 1

# radio, static emitter
check_queue_length(rrs, "static radio", 1, n_check)
if dynamic:
    check_last_emitter_direction(rrs, "static radio", 0.94, -0.32, -0.09, n_check)
else:
    check_last_emitter_direction(rrs, "static radio", 1.00, 0.00, 0.00, n_check)

# radio, dynamic emitter
if dynamic:
    check_queue_length(rrd, "dynamic radio", 1, n_check)
else:
    check_queue_length(rrd, "dynamic radio", 0, n_check)

# infra-red, static emitter
if dynamic:
    check_queue_length(ris, "static infra-red", 0, n_check)
else:
    check_queue_length(ris, "static infra-red", 1, n_check)
    check_last_emitter_direction(ris, "static infra-red", 1.00, 0.00, 0.00, n_check)

# infra-red, dynamic emitter
check_queue_length(rid, "dynamic infra-red", 0, n_check)

ts_send_success()
