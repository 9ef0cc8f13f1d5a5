"""Port of Webots' tests/api/controllers/radar_occlusion: a radar with occlusion does not see targets hidden behind
a front target, one without occlusion does, until the front target is removed."""

from controller import Supervisor
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

radar_with_occlusion = robot.getDevice("radar_with_occlusion")
radar_without_occlusion = robot.getDevice("radar_without_occlusion")

radar_with_occlusion.enable(TIME_STEP)
radar_without_occlusion.enable(TIME_STEP)

robot.step(TIME_STEP)

ts_assert_int_equal(radar_with_occlusion.getNumberOfTargets(), 1,
                    "The radar with occlusion should see only 1 target because the other ones are occluded.")
ts_assert_int_equal(radar_without_occlusion.getNumberOfTargets(), 3, "The radar without occlusion should see 3 targets.")

front_target = robot.getFromDef("FRONT_TARGET")
front_target.remove()

robot.step(TIME_STEP)

ts_assert_int_equal(radar_with_occlusion.getNumberOfTargets(), 2, "The radar with occlusion should see only 2 targets.")
ts_assert_int_equal(radar_without_occlusion.getNumberOfTargets(), 2, "The radar without occlusion should see 2 targets.")

ts_send_success()
