"""Port of Webots' tests/api/controllers/supervisor_export_image: exportImage writes a PNG and a JPEG file of the 3D
view (they must exist within eleven steps after the call)."""

import os

from controller import Supervisor
from ts_assertion import ts_assert_boolean_equal, ts_assert_boolean_not_equal, ts_send_success, ts_setup

FILE_NAME_PNG = "image.png"
FILE_NAME_JPG = "image.jpg"

robot = Supervisor()
ts_setup(robot)

time_step = int(robot.getBasicTimeStep())

for name in (FILE_NAME_PNG, FILE_NAME_JPG):
    if os.path.exists(name):
        os.remove(name)

ts_assert_boolean_not_equal(os.path.exists(FILE_NAME_PNG), "Impossible to remove the PNG file")
ts_assert_boolean_not_equal(os.path.exists(FILE_NAME_JPG), "Impossible to remove the JPG file")

robot.step(time_step)

robot.exportImage(FILE_NAME_PNG, 100)
robot.exportImage(FILE_NAME_JPG, 100)

robot.step(time_step)

for _ in range(10):
    if os.path.exists(FILE_NAME_PNG) and os.path.exists(FILE_NAME_JPG):
        break
    robot.step(time_step)

ts_assert_boolean_equal(os.path.exists(FILE_NAME_PNG),
                        "wb_supervisor_export_image() failed to create the " + FILE_NAME_PNG + " file.")
ts_assert_boolean_equal(os.path.exists(FILE_NAME_JPG),
                        "wb_supervisor_export_image() failed to create the " + FILE_NAME_JPG + " file.")

ts_send_success()
