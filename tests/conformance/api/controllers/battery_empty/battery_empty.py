"""Port of Webots' tests/api/controllers/battery_empty: an empty battery field reads -1."""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())
robot.batterySensorEnable(time_step)

robot.step(time_step)
ts_assert_double_equal(robot.batterySensorGetValue(), -1.0,
                       "When the 'battery' field is empty 'wb_robot_battery_sensor_get_value' should return '-1.0'")

ts_send_success()
