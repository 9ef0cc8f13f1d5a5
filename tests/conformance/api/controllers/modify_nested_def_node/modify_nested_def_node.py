"""Port of Webots' tests/api/controllers/modify_nested_def_node: editing a DEF node changes every USE of it."""

from controller import Supervisor
from ts_assertion import ts_assert_double_in_delta, ts_send_success, ts_setup

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

ds_def1 = robot.getDevice("ds1")  # generic
ds_use1 = robot.getDevice("ds2")  # generic
ds_def2 = robot.getDevice("ds3")  # generic
ds_use2 = robot.getDevice("ds4")  # infra-red (no bounding object)
ds_use3 = robot.getDevice("ds5")  # infra-red (no bounding object)
for sensor in (ds_def1, ds_use1, ds_def2, ds_use2, ds_use3):
    sensor.enable(time_step)

robot.step(time_step)

# Initial sizes: nothing detected, every value 1000. (The C original reads ds4 for "use1" here too.)
def1 = ds_def1.getValue()
use1 = ds_use2.getValue()
def2 = ds_def2.getValue()
use2 = ds_use2.getValue()
use3 = ds_use3.getValue()

ts_assert_double_in_delta(def1, 1000.0, 1.0, "The initial size of box B1 is wrong.")
ts_assert_double_in_delta(use1, 1000.0, 1.0, "The initial size of USE node containing box B1 is wrong.")
ts_assert_double_in_delta(def2, 1000.0, 1.0, "The initial size of box B2 is wrong.")
ts_assert_double_in_delta(use2, 1000.0, 1.0, "The initial size of USE node containing box B2 is wrong.")
ts_assert_double_in_delta(use3, 1000.0, 1.0, "The initial translation of USE node in USE_CASE_4 is wrong.")

new_size = [0.3, 0.1, 0.1]
robot.getFromDef("B1").getField("size").setSFVec3f(new_size)
robot.getFromDef("B2").getField("size").setSFVec3f(new_size)

robot.step(time_step)

def1 = ds_def1.getValue()
use1 = ds_use1.getValue()
def2 = ds_def2.getValue()
use2 = ds_use2.getValue()

ts_assert_double_in_delta(def1, 500.0, 1.0, "The size of box B1 is wrong after modifying it.")
ts_assert_double_in_delta(use1, 500.0, 1.0, "The size of USE node containing box B1 after modifying it.")
ts_assert_double_in_delta(def2, 500.0, 1.0, "The size of box B2 is wrong after modifying it.")
ts_assert_double_in_delta(use2, 526.0, 10.0, "The size of of USE node containing box B2 is wrong after modifying it.")

# Moving T2 moves the nested USE nodes of USE_CASE_4.
robot.getFromDef("T2").getField("translation").setSFVec3f([0.4, -0.2, 0])

robot.step(time_step)

use3 = ds_use3.getValue()
ts_assert_double_in_delta(use3, 504.0, 1.0, "The translation of USE node in USE_CASE_4 is wrong after modifying it.")

ts_send_success()
