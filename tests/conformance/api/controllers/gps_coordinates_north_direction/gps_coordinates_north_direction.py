"""Port of Webots' tests/api/controllers/gps_coordinates_north_direction: WGS84 values follow coordinateSystem."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

gps = robot.getDevice("gps")
gps.enable(TIME_STEP)

worldinfo_node = robot.getFromDef("WORLDINFO")
coordinate_system_field = worldinfo_node.getField("coordinateSystem")

robot.step(TIME_STEP)

position = gps.getValues()
ts_assert_double_in_delta(position[2], 0.0, 0.0001, "The altitude measured by the GPS should be 0 and not %f", position[2])
old_latitude = position[0]
old_longitude = position[1]

coordinate_system_field.setSFString("ENU")
robot.step(TIME_STEP)

position = gps.getValues()
ts_assert_double_in_delta(position[2], 0, 0.0001, "The altitude measured by the GPS should be 0 and not %f", position[2])

# After the change of coordinate system, latitude and longitude are exchanged.
ts_assert_double_in_delta(position[0], old_longitude, 0.001,
                          "The latitude and longitude have not been correctly inversed after changing the coordinate system.")
ts_assert_double_in_delta(position[1], -old_latitude, 0.001,
                          "The longitude and latitude have not been correctly inversed after changing the coordinate system.")

ts_send_success()
