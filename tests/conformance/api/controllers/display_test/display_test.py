"""Port of Webots' tests/api/controllers/display_test (no assertions): a robot spinning on the spot that pastes a
random emoticon on its Display every 30 steps, for supervisor_restart_controller_display to restart.

Its image, projects/samples/devices/controllers/display/emoticons.png in Webots' repository, is binary and not kept
here: the path is kept as in the C original and points at no file, so the pastes draw nothing.

The name ends in `_test.py`, so pytest collects this file: the controller runs only as a script (as wbtc starts
it), and importing it does nothing.
"""

import random

SPEED = 40
TIME_STEP = 64

EMOTICON_WIDTH = 14
EMOTICON_HEIGHT = 14
EMOTICONS_NUMBER_X = 5
EMOTICONS_NUMBER_Y = 11


def main() -> None:
    """The C original's main()."""
    from controller import Robot

    robot = Robot()

    counter = 0
    emoticon_display = robot.getDevice("emoticon_display")
    emoticons_image = emoticon_display.imageLoad(
        "../../../../projects/samples/devices/controllers/display/emoticons.png")

    left_motor = robot.getDevice("left wheel motor")
    right_motor = robot.getDevice("right wheel motor")
    left_motor.setPosition(float("inf"))
    right_motor.setPosition(float("inf"))
    left_motor.setVelocity(SPEED)
    right_motor.setVelocity(-SPEED)

    while robot.step(TIME_STEP) != -1:
        counter += 1

        if counter % 30 == 1:
            x = -EMOTICON_WIDTH * random.randrange(EMOTICONS_NUMBER_X)
            y = -EMOTICON_HEIGHT * random.randrange(EMOTICONS_NUMBER_Y)
            emoticon_display.imagePaste(emoticons_image, x, y, True)

    emoticon_display.imageDelete(emoticons_image)


if __name__ == "__main__":
    main()
