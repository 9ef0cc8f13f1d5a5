"""What a camera sees of a pen's ink: the helpers every one of Webots' pen tests defines for itself.

Webots' `tests/api/controllers/pen_*.c` each carry the same `isGray`, `computeNumColorPixels` and
`getPixelColor` over their global camera; wbtc's ports share them here, with the camera and the
image size passed in, under the C names so that a port still reads line for line.
"""


def isGray(color):
    """Whether an (r, g, b) colour is a shade of grey (an unpainted pixel of the white board)."""
    return color[0] == color[1] and color[1] == color[2]


def getPixelColor(camera, width, x, y):
    """The (r, g, b) of pixel (x, y) of the camera's last image."""
    image = camera.getImage()
    return (camera.imageGetRed(image, width, x, y), camera.imageGetGreen(image, width, x, y),
            camera.imageGetBlue(image, width, x, y))


def computeNumColorPixels(camera, width, height):
    """How many pixels of the camera's last image are not grey (inked)."""
    numColorPixels = 0
    for y in range(height):
        for x in range(width):
            if not isGray(getPixelColor(camera, width, x, y)):
                numColorPixels += 1
    return numColorPixels
