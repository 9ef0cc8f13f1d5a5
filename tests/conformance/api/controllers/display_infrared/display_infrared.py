"""Port of Webots' tests/api/controllers/display_infrared: infra-red sensors read what a Display draws.

A 20 x 20 grid of infra-red DistanceSensors faces a Display's screen; the display is filled black and two
white ovals are drawn. Infra-red readings depend on the colour they hit, so half of each reading must match
Webots' expected_data.txt (white ~0.5, black 1.0) within 0.01.
"""

from pathlib import Path

from controller import Robot
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_in_delta,
    ts_assert_int_equal,
    ts_send_success,
    ts_setup,
)

TIME_STEP = 32
BLACK = 0x000000
WHITE = 0xFFFFFF
XSIZE = 20
YSIZE = 20

robot = Robot()
ts_setup(robot)
display = robot.getDevice("display")
ts_assert_boolean_equal(display is not None, "Unable to find the display device")

ds = [None] * (XSIZE * YSIZE)
for i in range(XSIZE):
    for j in range(YSIZE):
        index = j * XSIZE + i
        ds[index] = robot.getDevice("ds%d-%d" % (i, j))
        ts_assert_boolean_equal(ds[index] is not None, "Unable to find the distance sensor [%d, %d] device", i, j)
        ds[index].enable(TIME_STEP)

display_width = display.getWidth()
ts_assert_int_equal(display_width, XSIZE, "Display has a wrong width")
display_height = display.getHeight()
ts_assert_int_equal(display_width, XSIZE, "Display has a wrong height")  # sic: the C test checks the width twice

display.setColor(BLACK)
display.fillRectangle(0, 0, display_width, display_height)
display.setColor(WHITE)
display.fillOval(5, 10, 4, 8)
display.fillOval(15, 10, 4, 8)

robot.step(TIME_STEP)

expected_values = Path("expected_data.txt").read_text().split()
ts_assert_int_equal(len(expected_values), XSIZE * YSIZE, "fscanf failed")
for j in range(YSIZE):
    for i in range(XSIZE):
        index = j * XSIZE + i
        expected = float(expected_values[index])
        value = 0.5 * ds[index].getValue()
        ts_assert_double_in_delta(value, expected, 0.01, "Measurement [%d, %d] failed. Expected=%f Received=%f",
                                  i, j, expected, value)

ts_send_success()
