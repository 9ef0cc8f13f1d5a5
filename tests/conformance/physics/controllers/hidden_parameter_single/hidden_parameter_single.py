"""Port of Webots' tests/physics/controllers/hidden_parameter_single: hidden translation, rotation and linear
velocity of a PROTO robot, and hidden joint positions of four PROTO robots, are applied when the world loads."""

import math

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_assert_doubles_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32

expected_init_pos = [0.1, 0.1, 0.23]
angle = 0.47
cos_angle = math.cos(angle)
sin_angle = math.sin(angle)
expected_matrix = [1.0, 0.0, 0.0, 0.0, cos_angle, -sin_angle, 0.0, sin_angle, cos_angle]

supervisor = Supervisor()
ts_setup(supervisor)

robot = supervisor.getFromDef("ROBOT")

ts_assert_doubles_equal(3, robot.getPosition(), expected_init_pos, "The hidden translation has not been set correctly")

ts_assert_doubles_equal(9, robot.getOrientation(), expected_matrix, "The hidden rotation has not been set correctly")

supervisor.step(TIME_STEP)

position = robot.getPosition()
ts_assert_boolean_equal((expected_init_pos[1] + 0.015) < position[1],
                        "The hidden linear velocity has not been set correctly")

receiver = supervisor.getDevice("receiver")
receiver.enable(TIME_STEP)

delta = 1e-10
received_message = False

while supervisor.step(TIME_STEP) != -1 and supervisor.getTime() < 5.0:
    if receiver.getQueueLength() > 0:
        fields = receiver.getBytes().split(b"\0", 1)[0].decode().split()
        position, position2, position3 = (float(value) for value in fields[:3])
        robot_name = fields[3] if len(fields) > 3 else ""
        received_message = True

        if robot_name == "HingeJoint":
            ts_assert_double_in_delta(position, 0.111, delta, "HingeJoint position is %.4f instead of %.4f", position,
                                      0.111)
        elif robot_name == "SliderJoint":
            ts_assert_double_in_delta(position, 0.222, delta, "SliderJoint position is %.4f instead of %.4f", position,
                                      0.222)
        elif robot_name == "Hinge2Joint":
            ts_assert_double_in_delta(position, 0.333, delta, "Hinge2Joint position is %.4f instead of %.4f", position,
                                      0.333)
            ts_assert_double_in_delta(position2, 0.444, delta, "Hinge2Joint position2 is %.4f instead of %.4f",
                                      position2, 0.444)
        elif robot_name == "BallJoint":
            ts_assert_double_in_delta(position, 0.555, delta, "BallJoint position is %.4f instad of %.4f", position,
                                      0.555)
            ts_assert_double_in_delta(position2, 0.666, delta, "BallJoint position2 is %.4f instead of %.4f", position2,
                                      0.666)
            ts_assert_double_in_delta(position3, 0.777, delta, "BallJoint position3 is %.4f instead of %.4f", position3,
                                      0.777)
        else:
            ts_assert_boolean_equal(0, "Message unknown.")

        receiver.nextPacket()

ts_assert_boolean_equal(received_message, "Should have received at least one message, but didn't.")

ts_send_success()
