"""Port of Webots' tests/api/controllers/supervisor_restart_controller_display: restarting the controller of a
robot that draws on a Display (display_test) does not crash the simulation."""

from controller import Supervisor
from ts_assertion import ts_send_success, ts_setup

TIME_STEP = 64

robot = Supervisor()
ts_setup(robot)

mybot = robot.getFromDef("MYBOT")

robot.step(10 * TIME_STEP)

mybot.restartController()

robot.step(10 * TIME_STEP)

ts_send_success()
