"""Port of Webots' tests/api/controllers/supervisor_start_stop_movie: movieIsReady and movieFailed before, during
and after a 20-step recording, and movie.mp4 written within 5 s of wall-clock time after movieStopRecording."""

import os
import sys
import time

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_boolean_not_equal,
    ts_send_error_and_exit,
    ts_send_success,
    ts_setup,
)

FILE_NAME = "movie.mp4"
TIME_STEP = 32


def file_exists() -> bool:
    if os.path.exists(FILE_NAME):
        return True
    ts_send_error_and_exit("wb_supervisor_start/stop_movie() failed to create the " + FILE_NAME + " file in 5 seconds.")
    return False


robot = Supervisor()
ts_setup(robot)

if os.path.exists(FILE_NAME):
    os.remove(FILE_NAME)

ts_assert_boolean_equal(robot.movieIsReady(), "Movie should be ready before starting recording a video.")
ts_assert_boolean_not_equal(robot.movieFailed(), "Movie shouldn't be failed before starting recording a video.")

robot.movieStartRecording(FILE_NAME, 640, 480, 0, 50, 1, False)

ts_assert_boolean_not_equal(robot.movieIsReady(), "Movie shouldn't be ready just after starting recording a video.")

for _ in range(20):
    robot.step(TIME_STEP)

robot.movieStopRecording()

ts_assert_boolean_not_equal(robot.movieIsReady(), "Movie shouldn't be ready just after stopping recording a video.")

for _ in range(50):
    time.sleep(0.1)
    if robot.movieIsReady():
        ts_assert_boolean_not_equal(robot.movieFailed(), "Error while recording the movie file.")
        if file_exists():
            ts_send_success()
        sys.exit(1)

if file_exists():
    ts_send_error_and_exit("wb_supervisor_movie_is_ready doesn't return TRUE after 5 seconds from stop command.")
sys.exit(1)
