"""The window's keys: Webots' simulation shortcuts, and the key codes robots get."""

import glfw
import pytest

from wbtc.runtime.controls import Controls, webots_key
from wbtc.runtime.window import clock

CTRL, SHIFT, ALT = glfw.MOD_CONTROL, glfw.MOD_SHIFT, glfw.MOD_ALT


@pytest.mark.parametrize(("key", "mods", "code"), [
    (glfw.KEY_A, 0, 65), (glfw.KEY_A, SHIFT, 65 | 0x10000), (glfw.KEY_7, 0, 55), (glfw.KEY_SPACE, 0, 32),
    (glfw.KEY_UP, 0, 315), (glfw.KEY_DOWN, CTRL, 317 | 0x20000), (glfw.KEY_LEFT, ALT, 314 | 0x40000),
    (glfw.KEY_RIGHT, 0, 316), (glfw.KEY_PAGE_UP, 0, 366), (glfw.KEY_HOME, 0, 313), (glfw.KEY_END, 0, 312),
    (glfw.KEY_ENTER, 0, 4), (glfw.KEY_F5, 0, None), (glfw.KEY_LEFT_SHIFT, SHIFT, None),
])
def test_keys_reach_robots_as_webots_codes(key, mods, code):
    assert webots_key(key, mods) == code


def test_simulation_shortcuts():
    controls = Controls()
    assert not controls.key(glfw.KEY_0, 0, 2)  # a plain 0 is the robot's
    assert controls.key(glfw.KEY_0, CTRL, 2) and controls.paused
    assert controls.key(glfw.KEY_1, CTRL, 2) and controls.steps == 1 and controls.paused
    assert controls.key(glfw.KEY_3, CTRL, 2) and (controls.paused, controls.fast) == (False, True)
    assert controls.key(glfw.KEY_2, CTRL, 2) and (controls.paused, controls.fast) == (False, False)
    assert controls.key(glfw.KEY_T, CTRL | SHIFT, 2) and controls.reset
    follows = []
    for _ in range(3):
        controls.key(glfw.KEY_F, CTRL, 2)
        follows.append(controls.follow)
    assert follows == [0, 1, -1]  # robot 0, robot 1, then the free view again
    assert controls.key(glfw.KEY_F1, 0, 2) and controls.help
    assert controls.help_text()[0].splitlines()[0] == "Ctrl+0"


@pytest.mark.parametrize(("seconds", "text"), [(0.0, "0:00:00:000"), (2.304, "0:00:02:304"),
                                               (3725.5, "1:02:05:500")])
def test_clock_reads_as_webots(seconds, text):
    assert clock(seconds) == text
