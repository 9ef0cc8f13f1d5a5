"""Port of Webots' tests/protos/controllers/copy_args_in_custom_data: a helper robot controller (no assertions) that
writes its first controller argument into its robot's customData, then steps until the simulation ends.

Run by the template robot of template_node_id.wbt and template_node_id_lua.wbt, whose PROTO passes its context.id as
controllerArgs.
"""

import sys

from controller import Robot

TIME_STEP = 32

robot = Robot()

robot.setCustomData(sys.argv[1])

while robot.step(TIME_STEP) != -1:
    pass
