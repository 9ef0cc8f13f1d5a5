"""Port of Webots' tests/api/controllers/battery: battery drain by a motor and the CPU, and the motor stopping.

The stopped motor's position is expected at 0.5739, as the check's own message says and as the upstream version at
8364fc97 (and omnilink-tech/omnisim) writes it; the version at 19fba6ad wrote 3572458.46.
"""

import math

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

robot = Robot()
ts_setup(robot)

motor = robot.getDevice("rotational motor")
position_sensor = robot.getDevice("position sensor")
TIME_STEP = int(robot.getBasicTimeStep())

position_sensor.enable(TIME_STEP)
robot.batterySensorEnable(TIME_STEP)
motor.setPosition(2 * math.pi)
robot.step(TIME_STEP)
battery_level = robot.batterySensorGetValue()

theorical_battery_level = 504
ts_assert_double_in_delta(battery_level, theorical_battery_level, 1,
                          "The battery level measured by the battery sensor should be %g and not %g",
                          theorical_battery_level, battery_level)

for _ in range(10):
    robot.step(TIME_STEP)

# The robot runs out of battery in the middle of the loop above: the motor stops where it was.
position = position_sensor.getValue()
ts_assert_double_in_delta(position, 0.5739, 0.001,
                          "The position value measured by the position sensor should be 0.5739 and not %g", position)

battery_level = robot.batterySensorGetValue()
ts_assert_double_in_delta(battery_level, 0, 0.001, "The battery level measured by the battery sensor should be 0 and not %g",
                          battery_level)

ts_send_success()
