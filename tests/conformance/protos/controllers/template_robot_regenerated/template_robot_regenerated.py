"""Port of Webots' tests/protos/controllers/template_robot_regenerated: a supervisor changes five times, every ten
steps, the template field `proceduralField` of a Robot PROTO, which Webots regenerates (and whose controller it
restarts) each time; the simulation has to go on.

Run by template_robot_regenerated.wbt (JavaScript template) and its _lua variant (Lua template). As the C original's
ts_setup(argv[0]), the test name is the controller's.
"""

from controller import Supervisor
from ts_assertion import ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)  # give the controller args

robot.step(TIME_STEP)

node = robot.getFromDef("ROBOT")
field = node.getField("proceduralField")

i = 0
while robot.step(10 * TIME_STEP) != -1 and i < 5:
    buffer = "counter: %d" % i
    field.setSFString(buffer)
    i += 1

ts_send_success()
