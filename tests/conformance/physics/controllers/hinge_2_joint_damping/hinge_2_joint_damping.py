"""Port of Webots' tests/physics/controllers/hinge_2_joint_damping: a two-wheeled robot spins in place while a
supervisor raises the wheels' second-axis damping constant (0, 20, 50); the gyro's yaw rate must follow."""

import math

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 64

expected_angle_rate = [0.696, 0.348, 0.139]

robot = Robot()
ts_setup(robot)

wheels = [robot.getDevice("wheel1"), robot.getDevice("wheel2")]
wheels[0].setPosition(math.inf)
wheels[1].setPosition(math.inf)

wheels[0].setVelocity(-1.0)
wheels[1].setVelocity(1.0)

gyro = robot.getDevice("gyro")
gyro.enable(TIME_STEP)

n_step = 0
while robot.step(TIME_STEP) != -1:
    angle_rate = gyro.getValues()[1]
    index = n_step // 10

    ts_assert_double_in_delta(angle_rate, expected_angle_rate[index], 0.01,
                              "Unexpected angle rate (expected = %lf, measured = %lf)", expected_angle_rate[index],
                              angle_rate)
    print("angle_rate: %f excpected: %f" % (angle_rate, expected_angle_rate[index]))
    n_step += 1
    if n_step == 30:
        break

ts_send_success()
