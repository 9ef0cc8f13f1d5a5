"""The viewer window's keys: Webots' simulation shortcuts, and the rest as Webots key codes.

| Keys | Action (Webots' Simulation menu) |
| --- | --- |
| Ctrl+0 | pause / run |
| Ctrl+1 | one basic time step (and stay paused) |
| Ctrl+2 | run in real time |
| Ctrl+3 | run fast (no pacing) |
| Ctrl+Shift+T, Ctrl+Shift+R | reset (Webots' Reset button): time 0, poses back, every controller anew |
| Ctrl+F | follow: the free view, then each robot in turn |
| F1 | show / hide the panel of keys |

Every other key reaches the robots' Keyboard devices: letters as upper-case ASCII, arrows and
page keys as Webots' codes, with Shift, Ctrl and Alt as Webots' modifier bits.
"""

from __future__ import annotations

from dataclasses import dataclass

import glfw

#: GLFW's codes of keys that are not plain ASCII, to Webots' (include/controller/c/webots/keyboard.h).
SPECIAL = {glfw.KEY_RIGHT: 316, glfw.KEY_LEFT: 314, glfw.KEY_DOWN: 317, glfw.KEY_UP: 315, glfw.KEY_PAGE_UP: 366,
           glfw.KEY_PAGE_DOWN: 367, glfw.KEY_HOME: 313, glfw.KEY_END: 312, glfw.KEY_ENTER: 4, glfw.KEY_ESCAPE: 27,
           glfw.KEY_TAB: 9, glfw.KEY_BACKSPACE: 8, glfw.KEY_DELETE: 127}
#: GLFW's modifier bits to Webots' (WB_KEYBOARD_SHIFT, _CONTROL, _ALT).
MODIFIERS = {glfw.MOD_SHIFT: 0x10000, glfw.MOD_CONTROL: 0x20000, glfw.MOD_ALT: 0x40000}

HELP = [("Ctrl+0", "pause / run"), ("Ctrl+1", "one step"), ("Ctrl+2", "real time"), ("Ctrl+3", "fast"),
        ("Ctrl+Shift+T", "reset"), ("Ctrl+F", "follow next robot"), ("F1", "hide this panel"),
        ("mouse", "left: turn, right: move, wheel: zoom")]


def webots_key(key: int, mods: int) -> int | None:
    """A GLFW key press as Webots' Keyboard reports it (None for keys it does not report)."""
    if key in SPECIAL:
        code = SPECIAL[key]
    elif 32 <= key <= 96:  # GLFW's printable keys are their ASCII codes, letters in upper case (as Webots')
        code = key
    else:
        return None
    for bit, webots in MODIFIERS.items():
        if mods & bit:
            code |= webots
    return code


@dataclass
class Controls:
    """What the window's keys have asked for; the window reads and clears it."""

    paused: bool = False
    fast: bool = False
    steps: int = 0  # single steps asked for while paused
    reset: bool = False
    follow: int = -1  # -1: the free view; i: following robot i
    help: bool = False

    def key(self, key: int, mods: int, robots: int) -> bool:
        """Apply a simulation shortcut; False when the key is not one (it goes to the robots)."""
        ctrl, shift = bool(mods & glfw.MOD_CONTROL), bool(mods & glfw.MOD_SHIFT)
        if key == glfw.KEY_F1 and not mods:
            self.help = not self.help
        elif ctrl and shift and key in (glfw.KEY_T, glfw.KEY_R):
            self.reset = True
        elif ctrl and not shift and key == glfw.KEY_0:
            self.paused = not self.paused
        elif ctrl and not shift and key == glfw.KEY_1:
            self.paused, self.steps = True, self.steps + 1
        elif ctrl and not shift and key in (glfw.KEY_2, glfw.KEY_3):
            self.paused, self.fast = False, key == glfw.KEY_3
        elif ctrl and not shift and key == glfw.KEY_F:
            self.follow = self.follow + 1 if self.follow + 1 < robots else -1
        else:
            return False
        return True

    def help_text(self) -> tuple[str, str]:
        """The panel of keys: (keys, actions)."""
        return "\n".join(k for k, _ in HELP), "\n".join(a for _, a in HELP)
