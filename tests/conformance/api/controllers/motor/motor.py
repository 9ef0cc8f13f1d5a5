"""Port of Webots' tests/api/controllers/motor: a RotationalMotor's getters, PID position control and torque feedback."""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_double_in_delta, ts_send_success, ts_setup

NAN = float("nan")
ACCELERATION = 4.8
CONTROL_P, CONTROL_I, CONTROL_D = 15, 5, 1
TORQUE = 50.0
VELOCITY = 18.0
NUMBER_OF_STEPS = 20
TIME_STEP = 32  # as in the world file
MAX_POS, MIN_POS = 1.51, -1.63
MAX_ACCELERATION, MAX_VELOCITY, MAX_TORQUE = 5.0, 20.0, 100.0
REFERENCE_POSITION, REFERENCE_TORQUE = 1.18212, 0.0268543  # Webots' values after the PID run

robot = Robot()
ts_setup(robot)
motor = robot.getDevice("rotational motor")
position_sensor = motor.getPositionSensor()
robot.step(TIME_STEP)

position = position_sensor.getValue()
ts_assert_double_equal(position, NAN, "The position value measured by the position sensor should be NaN and not %g before "
                       "the device is enabled", position)
torque_feedback = motor.getTorqueFeedback()
ts_assert_double_equal(torque_feedback, NAN, "The torque feedback value measured by the motor should be NaN and not %g "
                       "before the device is enabled", torque_feedback)
period = motor.getTorqueFeedbackSamplingPeriod()
ts_assert_double_equal(period, 0, "The torque feedback sampling period value measured by the motor should be 0 and not %g "
                       "before the device is enabled", period)
max_position = motor.getMaxPosition()
ts_assert_double_equal(max_position, MAX_POS, "The max position value of the motor should be %g and not %g", MAX_POS,
                       max_position)
min_position = motor.getMinPosition()
ts_assert_double_equal(min_position, MIN_POS, "The min position value of the motor should be %g and not %g", MIN_POS,
                       min_position)
velocity, max_velocity = motor.getVelocity(), motor.getMaxVelocity()
ts_assert_double_equal(max_velocity, MAX_VELOCITY, "The max velocity value of the motor should be %g and not %g",
                       MAX_VELOCITY, max_velocity)
ts_assert_double_equal(velocity, max_velocity, "Velocity %g and max velocity %g values have to be equal", velocity,
                       max_velocity)
acceleration = motor.getAcceleration()
ts_assert_double_equal(acceleration, MAX_ACCELERATION, "The acceleration value of the motor should be %g and not %g",
                       acceleration, MAX_ACCELERATION)
torque, max_torque = motor.getAvailableTorque(), motor.getMaxTorque()
ts_assert_double_equal(max_torque, MAX_TORQUE, "The max torque value of the motor should be %g and not %g", MAX_TORQUE,
                       max_torque)
ts_assert_double_equal(torque, max_torque, "Torque %g and max torque %g values have to be equal", torque, max_torque)

position_sensor.enable(TIME_STEP)
motor.enableTorqueFeedback(TIME_STEP)
motor.setControlPID(CONTROL_P, CONTROL_I, CONTROL_D)
motor.setAvailableTorque(TORQUE)
motor.setPosition(100)
robot.step(TIME_STEP)

target = motor.getTargetPosition()
ts_assert_double_equal(target, max_position, "The target position value measured by the motor should be %g and not %g",
                       max_position, target)
for _ in range(NUMBER_OF_STEPS):
    robot.step(TIME_STEP)

position = position_sensor.getValue()
ts_assert_double_in_delta(position, REFERENCE_POSITION, 0.001, "The position value measured by the position sensor should "
                          "be %g and not %g", REFERENCE_POSITION, position)
torque = motor.getTorqueFeedback()
ts_assert_double_in_delta(torque, REFERENCE_TORQUE, 0.001, "The torque feedback value measured by the motor should be %g "
                          "and not %g", REFERENCE_TORQUE, torque)
velocity, max_velocity = motor.getVelocity(), motor.getMaxVelocity()
ts_assert_double_equal(max_velocity, MAX_VELOCITY, "The max velocity value of the motor should be %g and not %g after "
                       "parameters changed", MAX_VELOCITY, max_velocity)
ts_assert_double_equal(velocity, MAX_VELOCITY, "Velocity should be %g and not %g after parameters changed", MAX_VELOCITY,
                       velocity)
torque, max_torque = motor.getAvailableTorque(), motor.getMaxTorque()
ts_assert_double_equal(max_torque, MAX_TORQUE, "The max torque value of the motor should be %g and not %g after torque "
                       "changed", MAX_TORQUE, max_torque)
ts_assert_double_equal(torque, TORQUE, "Torque should be %g and not %g after torque changed", TORQUE, torque)

motor.setVelocity(VELOCITY)
motor.setAcceleration(ACCELERATION)
robot.step(TIME_STEP)
acceleration = motor.getAcceleration()
ts_assert_double_equal(acceleration, ACCELERATION, "Acceleration should be %g and not %g after acceleration changed",
                       ACCELERATION, acceleration)
velocity, max_velocity = motor.getVelocity(), motor.getMaxVelocity()
ts_assert_double_equal(max_velocity, MAX_VELOCITY, "The max velocity value of the motor should be %g and not %g after "
                       "velocity changed", MAX_VELOCITY, max_velocity)
ts_assert_double_equal(velocity, VELOCITY, "Velocity should be %g and not %g after velocity changed", VELOCITY, velocity)

ts_send_success()
