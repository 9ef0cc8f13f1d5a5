"""Port of Webots' tests/api/controllers/supervisor_simulation_mode: simulationSetMode and simulationGetMode; steps
in real-time mode take longer (wall clock) than in fast mode, and pausing (also around step(0)) does not advance
the simulation time."""

import time

from controller import Supervisor
from ts_assertion import (
    ts_assert_boolean_equal,
    ts_assert_double_equal,
    ts_assert_double_in_delta,
    ts_send_success,
    ts_setup,
)

robot = Supervisor()
ts_setup(robot)


def step(time_step: int) -> None:
    if robot.step(time_step) == -1:
        ts_assert_boolean_equal(0, "Controller stopped before having being able to conclude.")


_start_time = [0, 0]


def _timeofday() -> tuple[int, int]:
    """(seconds, microseconds), as gettimeofday gives them."""
    now = time.time_ns() // 1000
    return now // 1000000, now % 1000000


def start_chrono() -> None:
    _start_time[:] = _timeofday()


def stop_chrono() -> int:
    """Milliseconds since start_chrono, computed as the C test does (microseconds truncated)."""
    end_sec, end_usec = _timeofday()
    return 1000 * (end_sec - _start_time[0]) + int((end_usec - _start_time[1]) / 1000)


initial_mode = robot.simulationGetMode()
print("Initial mode=%d" % initial_mode)

n_steps = 100
time_step = int(robot.getBasicTimeStep())

robot.simulationSetMode(Supervisor.SIMULATION_MODE_FAST)

start_chrono()
for _ in range(n_steps):
    step(time_step)
time_counter = stop_chrono()

mean_step_time_in_fast_mode = time_counter / n_steps
print("Mean step time in fast mode = %g" % mean_step_time_in_fast_mode)

ts_assert_double_in_delta(robot.getTime(), 0.001 * time_step * n_steps, 0.001,
                          "Unexpected simulation time at the end of the fast mode test (found = %g).", robot.getTime())

robot.simulationSetMode(Supervisor.SIMULATION_MODE_REAL_TIME)

start_chrono()
for _ in range(n_steps):
    step(time_step)
time_counter = stop_chrono()

mean_step_time_in_real_time_mode = time_counter / n_steps
print("Mean step time in real-time mode = %g" % mean_step_time_in_real_time_mode)

ts_assert_double_in_delta(robot.getTime(), 0.001 * time_step * n_steps * 2, 0.001,
                          "Unexpected simulation time at the end of the real-time mode test (found = %g).",
                          robot.getTime())

ts_assert_boolean_equal(mean_step_time_in_fast_mode < mean_step_time_in_real_time_mode,
                        "The mean time to perform steps in real-time mode (%g ms) is taking less time than in fast mode "
                        "(%g ms).", mean_step_time_in_real_time_mode, mean_step_time_in_fast_mode)

time_before_pause = robot.getTime()
start_chrono()
robot.simulationSetMode(Supervisor.SIMULATION_MODE_PAUSE)
time.sleep(1)
robot.simulationSetMode(Supervisor.SIMULATION_MODE_FAST)
time_counter = stop_chrono()
time_after_pause = robot.getTime()

ts_assert_double_equal(time_before_pause, time_after_pause, "A: The simulation time before pausing the simulator (%g s) "
                       "and when resuming the simulator (%g s) is differing.", time_before_pause, time_after_pause)
ts_assert_boolean_equal(time_counter >= 1000, "The time spent in the sleep is smaller than one second (%d ms).",
                        time_counter)

time_before_pause = robot.getTime()
robot.simulationSetMode(Supervisor.SIMULATION_MODE_PAUSE)
step(0)
robot.simulationSetMode(Supervisor.SIMULATION_MODE_FAST)
time_after_pause = robot.getTime()

ts_assert_double_equal(time_before_pause, time_after_pause, "B: The simulation time before pausing the simulator (%g s) "
                       "and when resuming the simulator (%g s) is differing.", time_before_pause, time_after_pause)

print("Restore mode to %d" % initial_mode)
robot.simulationSetMode(initial_mode)

ts_send_success()
