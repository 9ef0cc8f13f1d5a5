"""Port of Webots' tests/protos/controllers/template_static: two instances of a PROTO tagged `static` whose template
draws a random box size get the same size, two seeded differently of a non-static one do not, and a static one
differs from a non-static one, as seen by four distance sensors.

As the C original's ts_setup(argv[0]), the test name is the controller's.
"""

from controller import Robot
from ts_assertion import ts_assert_double_equal, ts_assert_double_not_equal, ts_send_success, ts_setup

TIME_STEP = 32

robot = Robot()
ts_setup(robot)

# get and enable the acc
ds_static1 = robot.getDevice("static 1")
ds_static2 = robot.getDevice("static 2")
ds_non_static1 = robot.getDevice("non static 1")
ds_non_static2 = robot.getDevice("non static 2")

ds_static1.enable(TIME_STEP)
ds_static2.enable(TIME_STEP)
ds_non_static1.enable(TIME_STEP)
ds_non_static2.enable(TIME_STEP)

robot.step(TIME_STEP)

# check that both 'static' PROTO nodes are equivalent
ts_assert_double_equal(ds_static1.getValue(), ds_static2.getValue(),
                       "Static procedural PROTO nodes should have the same size (%lf != %lf)",
                       ds_static1.getValue(), ds_static2.getValue())

# check that both 'non-static' PROTO nodes are not equivalent
ts_assert_double_not_equal(ds_non_static1.getValue(), ds_non_static2.getValue(),
                           "Non-static procedural PROTO nodes should have different sizes (%lf = %lf)",
                           ds_non_static1.getValue(), ds_non_static2.getValue())

# Make sure static and non-static PROTO nodes are not equivalent
ts_assert_double_not_equal(ds_static1.getValue(), ds_non_static2.getValue(),
                           "Non-static and static procedural PROTO nodes should have different sizes (%lf = %lf)",
                           ds_static1.getValue(), ds_non_static2.getValue())

ts_send_success()
