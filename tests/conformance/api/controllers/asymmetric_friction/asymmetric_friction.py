"""Port of Webots' tests/api/controllers/asymmetric_friction: two boxes sliding on a tilted plane with asymmetric friction end at known positions."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

TIME_STEP = 64

EXPECTED_POS1 = (1.353466, -1.088782, -0.527743)
EXPECTED_POS2 = (-0.798742, -0.927224, 0.699450)

robot = Supervisor()
ts_setup(robot)

translation1 = robot.getFromDef("BOX1").getField("translation")
translation2 = robot.getFromDef("BOX2").getField("translation")

for _ in range(40):
    robot.step(TIME_STEP)

pos1 = translation1.getSFVec3f()
pos2 = translation2.getSFVec3f()

for c in range(3):
    ts_assert_double_in_delta(pos1[c], EXPECTED_POS1[c], 0.001, "The box1 is not at the position expected.")
    ts_assert_double_in_delta(pos2[c], EXPECTED_POS2[c], 0.001, "The box2 is not at the position expected.")

ts_send_success()
