"""Port of Webots' tests/api/controllers/coupled_motor: motors sharing a name turn together by their multipliers."""

from controller import Robot
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 16
MULTIPLIER = 2

robot = Robot()
ts_setup(robot)
reference_motor = robot.getDevice("reference motor")
reference_sensor = robot.getDevice("reference sensor")
positive = robot.getDevice("positive multiplier sensor")
negative = robot.getDevice("negative multiplier sensor")
for sensor in (reference_sensor, positive, negative):
    sensor.enable(TIME_STEP)

reference_motor.setPosition(float("inf"))
reference_motor.setVelocity(0.2)
for _ in range(100):
    robot.step(TIME_STEP)
    reference, plus, minus = reference_sensor.getValue(), positive.getValue(), negative.getValue()
    print("%f %f %f" % (reference, plus, minus))
    ts_assert_double_in_delta(plus, reference * MULTIPLIER, 1e-9,
                              "The position of the motor isn't %d times that of the reference", MULTIPLIER)
    ts_assert_double_in_delta(minus, reference * -MULTIPLIER, 1e-9,
                              "The position of the motor isn't %d times that of the reference", -MULTIPLIER)

reference_motor.setPosition(0.0)
reference_motor.setVelocity(10)
for _ in range(5000):
    robot.step(TIME_STEP)
    print("%f %f %f" % (reference_sensor.getValue(), positive.getValue(), negative.getValue()))

ts_send_success()
