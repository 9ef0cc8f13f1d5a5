"""Port of Webots' tests/physics/controllers/elevation_grid_rotation: eight boxes resting on a rotated ElevationGrid
keep their heights (within 1 cm) over 100 steps of 64 ms."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 64
NODE_NUMBER = 8

robot = Supervisor()
ts_setup(robot)

nodes = []
heights = []
for i in range(NODE_NUMBER):
    node = robot.getFromDef("SOLID%d" % i)
    nodes.append(node)
    heights.append(node.getPosition()[1])

robot.step(100 * TIME_STEP)

for i in range(NODE_NUMBER):
    ts_assert_double_in_delta(nodes[i].getPosition()[1], heights[i], 0.01,
                              "Height of Solid '%d' is not correct (%lf != %lf).", i, nodes[i].getPosition()[1],
                              heights[i])

ts_send_success()
