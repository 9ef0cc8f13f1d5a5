"""Port of Webots' tests/api/controllers/gps_speed: GPS speed and speed vector, with and without Physics."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_assert_vec3_in_delta, ts_send_success, ts_setup

NAN = float("nan")


def check_speed(gps, v, vx, vy, vz, end_msg):
    speed = gps.getSpeed()
    ts_assert_double_in_delta(speed, v, 0.0001, 'The speed value measured by the GPS "%s" should be %f and not %f %s.',
                              gps.getName(), v, speed, end_msg)
    r = gps.getSpeedVector()
    ts_assert_vec3_in_delta(r[0], r[1], r[2], vx, vy, vz, 0.0001,
                            'The speed vector value measured by the GPS "%s" should be [%f, %f, %f] not [%f, %f, %f] %s.',
                            gps.getName(), vx, vy, vz, r[0], r[1], r[2], end_msg)


robot = Robot()
ts_setup(robot)
time_step = int(robot.getBasicTimeStep())

gps_with_physics = robot.getDevice("gps_with_physics")
gps_without_physics = robot.getDevice("gps_without_physics")

check_speed(gps_with_physics, NAN, NAN, NAN, NAN, "before the device is enabled")
gps_with_physics.enable(time_step)
check_speed(gps_without_physics, NAN, NAN, NAN, NAN, "before the device is enabled")
gps_without_physics.enable(time_step)

check_speed(gps_with_physics, NAN, NAN, NAN, NAN, "before a wb_robot_step is performed")
check_speed(gps_without_physics, NAN, NAN, NAN, NAN, "before a wb_robot_step is performed")
robot.step(time_step)

check_speed(gps_with_physics, 5.0, -5.0, 0.0, 0.0, "after one step (because got a Physics node)")
check_speed(gps_without_physics, NAN, NAN, NAN, NAN, "after one step (because no Physics node)")
robot.step(time_step)

check_speed(gps_with_physics, 5.0, -5.0, 0.0, 0.0, "after two steps")
check_speed(gps_without_physics, 5.0, 0.0, -5.0, 0.0, "after two steps")

ts_send_success()
