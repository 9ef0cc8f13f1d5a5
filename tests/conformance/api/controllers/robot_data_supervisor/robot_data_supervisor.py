"""Port of Webots' tests/api/controllers/robot_data_supervisor: a supervisor writes "a + b" into another robot's
customData field and reads back the sum that robot's controller wrote with setCustomData."""

import random

from controller import Supervisor
from ts_assertion import ts_assert_int_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Supervisor()
ts_setup(robot)

robot.step(TIME_STEP)

robot_node = robot.getFromDef("ROBOT")
custom_data_field = robot_node.getField("customData")

a = random.randrange(100)
b = random.randrange(100)
custom_data_field.setSFString("%u + %u" % (a, b))

for _ in range(10):
    robot.step(TIME_STEP)

expected_result = a + b
answer = custom_data_field.getSFString().split()
result = int(answer[0]) if answer and answer[0].lstrip("-").isdigit() else 0

ts_assert_int_equal(result, expected_result, "Result is wrong, expected %d + %d = %d instead of %d", a, b, a + b,
                    result)

ts_send_success()
