"""Port of Webots' tests/api/controllers/gps_coordinates: a WGS84 GPS near New York, and the D/M/S conversion."""

from controller import GPS, Robot
from ts_assertion import (
    ts_assert_double_in_delta,
    ts_assert_double_is_bigger,
    ts_assert_int_equal,
    ts_assert_string_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
NEW_YORK_LATITUDE, NEW_YORK_ALTITUDE, NEW_YORK_LONGITUDE = 40.67, 10, -73.94
EXPECTED_STRING = "-73° -56′ -23″"

robot = Robot()
ts_setup(robot)
gps = robot.getDevice("gps")
gps.enable(TIME_STEP)
coordinate_system = gps.getCoordinateSystem()
ts_assert_int_equal(coordinate_system, GPS.WGS84, "Wrong coordinate system returned")
robot.step(TIME_STEP)

position = gps.getValues()
ts_assert_double_in_delta(position[0], NEW_YORK_LATITUDE, 0.1, "The latitude measured by the GPS should be %f and not %f",
                          NEW_YORK_LATITUDE, position[0])
ts_assert_double_in_delta(position[2], NEW_YORK_ALTITUDE, 0.1, "The altitude measured by the GPS should be %f and not %f",
                          NEW_YORK_ALTITUDE, position[1])
ts_assert_double_in_delta(position[1], NEW_YORK_LONGITUDE, 0.1, "The longitude measured by the GPS should be %f and not "
                          "%f", NEW_YORK_LONGITUDE, position[2])
for _ in range(20):
    robot.step(TIME_STEP)

speed = gps.getSpeed()
ts_assert_double_is_bigger(speed, 0.005, "The speed returned by the GPS should be bigger than 0.005m/s (%f returned)", speed)
converted = GPS.convertToDegreesMinutesSeconds(NEW_YORK_LONGITUDE)
ts_assert_string_equal(converted, EXPECTED_STRING, "The coordinate '%lf' should be equal to '%s' in the convert "
                       "degree/minutes/seconds and not '%s'", NEW_YORK_LONGITUDE, EXPECTED_STRING, converted)

ts_send_success()
