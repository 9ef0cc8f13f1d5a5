"""Port of Webots' tests/api/controllers/inertial_unit: roll, pitch and yaw of a robot turned by its supervisor."""

from controller import Supervisor
from ts_assertion import ts_assert_double_equal, ts_assert_doubles_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
PROBLEMS = [[0, 1, 0, 0], [0, 1, 0, -1.5708], [0, 1, 0, 1.5708], [1, 0, 0, 1.5708], [1, 0, 0, -1.5708],
            [0, 0, 1, 0.7854], [0, 0, 1, -0.7854]]
SOLUTIONS = [[0, 0, 0], [0, 0, -1.5708], [0, 0, 1.5708], [1.5708, 0, 0], [-1.5708, 0, 0], [0, 0.7854, 0],
             [0, -0.7854, 0]]

robot = Supervisor()
ts_setup(robot)
robot.step(TIME_STEP)
rotation = robot.getSelf().getField("rotation")
inertial_unit = robot.getDevice("inertial unit")
inertial_unit.enable(TIME_STEP)

lookup_table = inertial_unit.getLookupTable()
size = len(lookup_table) // 3
ts_assert_double_equal(size, 2, "Lookup table size returned is wrong (%d instead of 2)", size)
ts_assert_double_equal(lookup_table[3], 1000, "Lookup table (index 3) returned is wrong (%lf instead of 1000)",
                       lookup_table[3])
ts_assert_double_equal(lookup_table[5], 0, "Lookup table (index 5) returned is wrong (%lf instead of 0)", lookup_table[5])

for i, (problem, solution) in enumerate(zip(PROBLEMS, SOLUTIONS, strict=True)):
    rotation.setSFRotation(problem)
    robot.step(TIME_STEP)
    rpy = inertial_unit.getRollPitchYaw()
    ts_assert_doubles_in_delta(3, rpy, solution, 0.0001, "Getting roll-pitch-yaw failed after %d steps (received = "
                               "{%f, %f, %f}, expected = {%f, %f, %f}", i, *rpy, *solution)

ts_send_success()
