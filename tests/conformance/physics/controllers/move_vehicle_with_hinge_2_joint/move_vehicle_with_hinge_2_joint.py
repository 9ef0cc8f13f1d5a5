"""Port of Webots' tests/physics/controllers/move_vehicle_with_hinge_2_joint: after a supervisor moves a driving
vehicle whose steered front wheel hangs on a Hinge2Joint (and then moves the CAR robot too), a distance sensor beside
the front wheel never sees it for 100 steps, so the joint's axes and anchor followed the move."""

from controller import Supervisor
from ts_assertion import ts_assert_double_is_bigger, ts_assert_int_equal, ts_send_success, ts_setup


def move_vehicle(def_name):
    robot_node = robot.getFromDef(def_name)
    translation_field = robot_node.getField("translation")
    current_position = translation_field.getSFVec3f()
    position = [current_position[0] - 2, current_position[1], current_position[2]]
    translation_field.setSFVec3f(position)


robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

motors = [robot.getDevice("front motor"), robot.getDevice("rear right motor"), robot.getDevice("rear left motor")]
for motor in motors:
    motor.setVelocity(4.0)
    motor.setPosition(1000000)

steer_motor = robot.getDevice("steer motor")
steer_motor.setPosition(0.234)

robot.step(5 * time_step)

move_vehicle("VEHICLE")

sensor = robot.getDevice("front wheel sensor")
sensor.enable(time_step)

robot.step(20 * time_step)

move_vehicle("CAR")  # move_car checks the car after this move

steps = 100
while steps > 0 and robot.step(time_step) != -1:
    ts_assert_double_is_bigger(sensor.getValue(), 999.0, "Front wheel joint axis or anchor is wrong.")
    steps -= 1

ts_assert_int_equal(steps, 0, "Simulation terminated before completing all the tests.")

ts_send_success()
