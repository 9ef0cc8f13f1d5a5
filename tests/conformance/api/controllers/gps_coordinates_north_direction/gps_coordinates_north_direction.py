"""Port of Webots' tests/api/controllers/gps_coordinates_north_direction: WGS84 values of a GPS 5 km north and 2 km
east of gpsReference 0 0 0 in an NUE world.

The stored upstream controller then switches the world to ENU and expects latitude and longitude to swap, which no
Webots release since R2020b gives; this port follows the version of the controller that matches the stored world,
as kept in omnilink-tech/omnisim (a Webots fork, tests/api/controllers/gps_coordinates_north_direction/
gps_coordinates_north_direction.c): Webots' UTM projection of the position, to 1e-7 degree.
"""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

gps = robot.getDevice("gps")
gps.enable(TIME_STEP)

robot.step(TIME_STEP)

expected_position = [0.0451744, 0.0179479, 0]
position = gps.getValues()
for i in range(3):
    ts_assert_double_in_delta(position[i], expected_position[i], 0.0000001,
                              "The %c value measured by the GPS should be %g and not %g", "XYZ"[i],
                              expected_position[i], position[i])

ts_send_success()
