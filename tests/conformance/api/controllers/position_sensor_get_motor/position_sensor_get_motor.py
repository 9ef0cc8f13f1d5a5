"""Port of Webots' tests/api/controllers/position_sensor_get_motor: each axis's sensor knows its own motor and brake."""

from controller import Robot
from ts_assertion import ts_assert_pointer_null, ts_assert_string_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)
robot.step(TIME_STEP)


def test_get_motor(sensor_name: str, expected_motor_name: str) -> None:
    sensor = robot.getDevice(sensor_name)
    actual = sensor.getName()
    ts_assert_string_equal(actual, sensor_name, 'wb_device_get_name(wb_robot_get_device("%s")) returned "%s"',
                           sensor_name, actual)
    motor = sensor.getMotor()
    motor_name = motor.getName() if motor is not None else None
    ts_assert_string_equal(motor_name, expected_motor_name, 'wb_device_get_name(wb_position_sensor_get_motor('
                           'wb_robot_get_device("%s"))) returned "%s" instead of "%s"', sensor_name, motor_name,
                           expected_motor_name)


test_get_motor("position sensor1", "rotational motor1")
test_get_motor("position sensor2", "rotational motor2")
test_get_motor("position sensor3", "rotational motor3")
# position sensor3 has no brake: it must not get the first axis's brake.
brake = robot.getDevice("position sensor3").getBrake()
ts_assert_pointer_null(brake, 'wb_position_sensor_get_brake(wb_robot_get_device("position sensor3")) != NULL')

ts_send_success()
