"""Port of Webots' tests/api/controllers/pen: two pens ink a white board, two cameras read the mean colour.

pen0 writes red at density 0.1 stroke after stroke (the board fades to red), pen1 writes green at density 1, then
purple over it; a pen whose write is off leaves the board as it is. The means are C's integer divisions.
"""

from controller import Robot
from ts_assertion import ts_assert_color_in_delta, ts_send_success, ts_setup

TIME_STEP = 32
width = 64
height = 64
size = 4096

cam = [None, None]


def computeImageMeanColor(index):
    r = g = b = 0
    image = cam[index].getImage()
    for y in range(height):
        for x in range(width):
            r += cam[index].imageGetRed(image, width, x, y)
            g += cam[index].imageGetGreen(image, width, x, y)
            b += cam[index].imageGetBlue(image, width, x, y)
    return r // size, g // size, b // size


robot = Robot()
ts_setup(robot)

pen0 = robot.getDevice("pen0")
pen1 = robot.getDevice("pen1")
pen0.write(False)
pen1.write(False)

cam[0] = robot.getDevice("camera0")
cam[1] = robot.getDevice("camera1")
cam[0].enable(TIME_STEP)
cam[1].enable(TIME_STEP)

# FIRST STEP - set ink color
robot.step(TIME_STEP)

pen0.setInkColor(0xFF0000, 0.1)
pen1.setInkColor(0x00FF00, 1.0)

# check camera 0
color = computeImageMeanColor(0)
ts_assert_color_in_delta(*color, 207, 207, 207, 2,
                         "The value measured by the camera \"cam0\" should be (r=207,g=207,b=207) and not "
                         "(r=%d,g=%d,b=%d) before the pen \"pen0\" prints", *color)
# check camera 1
color = computeImageMeanColor(1)
ts_assert_color_in_delta(*color, 207, 207, 207, 2,
                         "The value measured by the camera \"cam1\" should be (r=207,g=207,b=207) and not "
                         "(r=%d,g=%d,b=%d) before the pen \"pen1\" prints", *color)

pen0.write(True)

# SECOND STEP - write with pen 0
robot.step(TIME_STEP)

# check camera 0
color = computeImageMeanColor(0)
ts_assert_color_in_delta(*color, 207, 201, 201, 2,
                         "Pen \"pen0\" should print with color (r=207,g=201,b=201) and not (r=%d,g=%d,b=%d)", *color)
# check camera 1
color = computeImageMeanColor(1)
ts_assert_color_in_delta(*color, 207, 207, 207, 2,
                         "The value measured by the camera \"cam1\" should be (r=207,g=207,b=207) and not "
                         "(r=%d,g=%d,b=%d) before the pen \"pen1\" prints", *color)

pen1.write(True)

# THIRD STEP - write with both pens
robot.step(TIME_STEP)

# check camera 0
color = computeImageMeanColor(0)
ts_assert_color_in_delta(*color, 207, 195, 195, 2,
                         "Pen \"pen0\" should print on the existing color obtaing color (r=207,g=195,b=195) and not "
                         "(r=%d,g=%d,b=%d)d", *color)

# check camera 1
color = computeImageMeanColor(1)
ts_assert_color_in_delta(*color, 0, 207, 0, 2,
                         "Pen \"pen1\" should print with color (r=0,g=207,b=0) and not (r=%d,g=%d,b=%d)", *color)

pen1.setInkColor(0xCC33FF, 1.0)

pen1.write(False)

# FORTH STEP - change ink color of pen 1 but not write
robot.step(TIME_STEP)

# check camera 0
color = computeImageMeanColor(0)
ts_assert_color_in_delta(*color, 207, 189, 189, 2,
                         "Pen \"pen0\" should print on the existing color obtaing color (r=207,g=189,b=189) and not "
                         "(r=%d,g=%d,b=%d)", *color)
# check camera 1
color = computeImageMeanColor(1)
ts_assert_color_in_delta(*color, 0, 207, 0, 2,
                         "Pen \"pen1\" should not overwrite color (r=0,g=207,b=0) with (r=%d,g=%d,b=%d) if WRITE=FALSE",
                         *color)

# pen0.write(True)
pen1.write(True)

# FIVE STEP - write with pen 1
robot.step(TIME_STEP)

# check camera 0
color = computeImageMeanColor(0)
ts_assert_color_in_delta(*color, 207, 178, 178, 2,
                         "Pen \"pen0\" should print on the existing color obtaing color (r=207,g=178,b=178) and not "
                         "(r=%d,g=%d,b=%d)", *color)
# check camera 1
color = computeImageMeanColor(1)
ts_assert_color_in_delta(*color, 154, 178, 167, 2,
                         "Pen \"pen1\" should overwrite previous color with color (r=154,g=178,b=167) and not "
                         "(r=%d,g=%d,b=%d) if WRITE=FALSE", *color)

# FIFTH STEP - check density
for _i in range(1, 34):
    robot.step(TIME_STEP)

# check camera 0
color = computeImageMeanColor(0)
ts_assert_color_in_delta(*color, 207, 0, 0, 5,
                         "Pen \"pen0\" should print on the existing color obtaining color (r=207,g=0,b=0) and not "
                         "(r=%d,g=%d,b=%d)", *color)

ts_send_success()
