"""Port of Webots' tests/api/controllers/inertial_unit: roll, pitch and yaw of a robot turned by its supervisor.

The stored upstream controller first checks a 2-row lookupTable that the stored world (R2021c) does not write; this
port follows the version of the controller that matches that world, as kept in omnilink-tech/omnisim (a Webots fork,
tests/api/controllers/inertial_unit/inertial_unit.c): it checks the noise the world writes (0.000005) and reads the
angles within 0.001.
"""

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

noise = inertial_unit.getNoise()
ts_assert_double_equal(noise, 0.000005, "The returned noise is wrong (%lf instead of 0.000005)", noise)

for i, (problem, solution) in enumerate(zip(PROBLEMS, SOLUTIONS, strict=True)):
    rotation.setSFRotation(problem)
    robot.step(TIME_STEP)
    rpy = inertial_unit.getRollPitchYaw()
    ts_assert_doubles_in_delta(3, rpy, solution, 0.001, "Getting roll-pitch-yaw failed after %d steps (received = "
                               "{%f, %f, %f}, expected = {%f, %f, %f}", i, *rpy, *solution)

ts_send_success()
