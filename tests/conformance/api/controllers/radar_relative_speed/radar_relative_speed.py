"""Port of Webots' tests/api/controllers/radar_relative_speed: the speed of a radar target is relative to the radar,
first with the target moving, then with the radar's robot moving too."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

TARGET_VELOCITY = [0.0, 0.0, -1.5, 0.0, 0.0, 0.0]
SUPERVISOR_VELOCITY = [0.0, 0.0, -0.75, 0.0, 0.0, 0.0]

robot = Supervisor()
ts_setup(robot)

radar = robot.getDevice("radar")
radar_target = robot.getFromDef("RADAR_TARGET")
supervisor = robot.getSelf()

radar.enable(TIME_STEP)

robot.step(TIME_STEP)
target_number = radar.getNumberOfTargets()
ts_assert_int_equal(target_number, 1, "The radar should see 1 target and not %d.", target_number)

radar_target.setVelocity(TARGET_VELOCITY)

robot.step(TIME_STEP)

target = radar.getTargets()
ts_assert_double_in_delta(target[0].speed, 1.5, 0.001, "The initial speed should be 1.5")

supervisor.setVelocity(SUPERVISOR_VELOCITY)

robot.step(TIME_STEP)

new_target = radar.getTargets()
ts_assert_double_in_delta(new_target[0].speed, 0.75, 0.001, "The secondary speed should be 0.75")

ts_send_success()
